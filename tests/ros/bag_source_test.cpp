// The rosbag reader against the recorded bags of ../shared/data/rosbags (SOURCES.txt), the TUM
// bag against the same frames as a TUM folder, bags written here from the simulator, and bags
// with defects.
#include "core/ros/bag_source.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>

#include "core/io/dataset.h"
#include "core/io/tum_rgbd_source.h"
#include "core/ros/bag_file.h"
#include "core/ros/bag_writer.h"
#include "core/sensors/driver_registry.h"
#include "tests/ros/bag_test_writer.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using testing::TempDir;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::vector<Frame> ReadAll(Source& source) {
  std::vector<Frame> frames;
  while (source.Grab().ok()) {
    StatusOr<Frame> frame = source.Retrieve();
    EXPECT_TRUE(frame.ok()) << frame.status().ToString();
    if (!frame.ok()) break;
    frames.push_back(std::move(*frame));
  }
  return frames;
}

// Largest absolute difference of two float images, NaN where both are NaN; -1 when a pixel is
// NaN in only one of them.
double MaxDepthDifference(const cv::Mat& a, const cv::Mat& b) {
  double worst = 0;
  for (int r = 0; r < a.rows; ++r) {
    for (int c = 0; c < a.cols; ++c) {
      const float x = a.at<float>(r, c), y = b.at<float>(r, c);
      if (std::isnan(x) != std::isnan(y)) return -1;
      if (!std::isnan(x)) worst = std::max(worst, double(std::abs(x - y)));
    }
  }
  return worst;
}

// Topic -> (type, messages) of each recorded bag, as ../shared/data/rosbags/SOURCES.txt lists.
struct RecordedBag {
  std::string file;
  std::map<std::string, std::pair<std::string, int64_t>> topics;
  SourceKind kind;
  int64_t frames;
};

std::vector<RecordedBag> RecordedBags() {
  return {
      {"tum_fr1_desk.bag",
       {{"/camera/rgb/image_color", {"sensor_msgs/Image", 9}},
        {"/camera/depth/image", {"sensor_msgs/Image", 9}},
        {"/camera/rgb/camera_info", {"sensor_msgs/CameraInfo", 9}},
        {"/camera/depth/camera_info", {"sensor_msgs/CameraInfo", 9}},
        {"/tf", {"tf2_msgs/TFMessage", 9}}},
       SourceKind::kRgbd,
       9},
      {"embag_test.bag",
       {{"/base_pose_ground_truth", {"nav_msgs/Odometry", 5}},
        {"/base_scan", {"sensor_msgs/LaserScan", 5}},
        {"/luminar_pointcloud", {"sensor_msgs/PointCloud2", 5}}},
       SourceKind::kCloud,
       5},
      {"aruco_images.bag",
       {{"/raspicam_node/image/compressed", {"sensor_msgs/CompressedImage", 1}},
        {"/raspicam_node/camera_info", {"sensor_msgs/CameraInfo", 15}}},
       SourceKind::kMono,
       1},
      {"aruco_marker.bag",
       {{"/raspicam_node/image/compressed", {"sensor_msgs/CompressedImage", 1}},
        {"/raspicam_node/camera_info", {"sensor_msgs/CameraInfo", 1}}},
       SourceKind::kMono,
       1},
      {"fiducial_board_611.bag",
       {{"raspicam_node/camera/image/compressed", {"sensor_msgs/CompressedImage", 1}},
        {"/raspicam_node/camera/camera_info", {"sensor_msgs/CameraInfo", 32}}},
       SourceKind::kMono,
       1},
  };
}

TEST(BagSource, EveryRecordedBagOpensWithTheTopicCountsOfItsSources) {
  SIGHTLINE_REQUIRE_DATA(folder, "rosbags");
  for (const RecordedBag& expected : RecordedBags()) {
    SCOPED_TRACE(expected.file);
    const std::string path = folder + "/" + expected.file;
    StatusOr<BagSummary> summary = ReadBagSummary(path);
    ASSERT_TRUE(summary.ok()) << summary.status().ToString();
    ASSERT_EQ(summary->topics.size(), expected.topics.size());
    for (const BagTopic& topic : summary->topics) {
      auto it = expected.topics.find(topic.name);
      ASSERT_NE(it, expected.topics.end()) << topic.name;
      EXPECT_EQ(topic.type, it->second.first) << topic.name;
      EXPECT_EQ(topic.messages, it->second.second) << topic.name;
    }
    StatusOr<std::unique_ptr<Source>> source = OpenSource(path);
    ASSERT_TRUE(source.ok()) << source.status().ToString();
    EXPECT_EQ((*source)->info().format, "ROS bag");
    EXPECT_EQ((*source)->info().kind, expected.kind);
    EXPECT_EQ((*source)->info().frame_count, expected.frames);
    EXPECT_EQ(ReadAll(**source).size(), size_t(expected.frames));
  }
}

TEST(BagSource, EmbagsLz4ChunksGivePointCloudsAndGroundTruthOdometry) {
  SIGHTLINE_REQUIRE_DATA(path, "rosbags/embag_test.bag");
  BagSource source(path);
  ASSERT_TRUE(source.Open().ok());
  EXPECT_EQ(source.summary().layout.CompressionText(), "lz4");
  EXPECT_EQ(source.summary().layout.chunks, 6);
  ASSERT_NE(source.odometry(), nullptr);
  EXPECT_EQ(source.odometry()->size(), 5u);
  ASSERT_NE(source.ground_truth(), nullptr);
  EXPECT_EQ(source.ground_truth()->size(), 5u);
  EXPECT_NEAR(source.summary().end_s - source.summary().start_s, 7.59, 0.01);
  for (const Frame& frame : ReadAll(source)) {
    const auto* cloud = std::get_if<CloudFrame>(&frame);
    ASSERT_NE(cloud, nullptr);
    size_t finite = 0;
    for (const Eigen::Vector3f& p : cloud->cloud->points) finite += p.allFinite() ? 1 : 0;
    EXPECT_GT(finite, 1000u);
    EXPECT_GT(cloud->stamp.sensor_time_s, 1.5e9);  // Header stamps of 2020.
  }
}

TEST(BagSource, TumBagGivesTheFramesCameraAndTruthOfTheTumFolder) {
  SIGHTLINE_REQUIRE_DATA(bag_path, "rosbags/tum_fr1_desk.bag");
  SIGHTLINE_REQUIRE_DATA(folder, "tum_fr1_desk");
  BagSource bag(bag_path);
  ASSERT_TRUE(bag.Open().ok());
  TumRgbdSource tum(folder);
  ASSERT_TRUE(tum.Open().ok());
  const PinholeCamera& a = *bag.info().camera;
  const PinholeCamera& b = *tum.info().camera;
  EXPECT_DOUBLE_EQ(a.fx, b.fx);
  EXPECT_DOUBLE_EQ(a.fy, b.fy);
  EXPECT_DOUBLE_EQ(a.cx, b.cx);
  EXPECT_DOUBLE_EQ(a.cy, b.cy);
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(a.distortion[i], b.distortion[i]) << i;
  const std::vector<Frame> from_bag = ReadAll(bag), from_folder = ReadAll(tum);
  ASSERT_EQ(from_bag.size(), 9u);
  ASSERT_EQ(from_folder.size(), 9u);
  ASSERT_NE(bag.ground_truth(), nullptr);
  const Trajectory& truth = *tum.ground_truth();
  for (size_t i = 0; i < 9; ++i) {
    const auto& x = std::get<RgbdFrame>(from_bag[i]);
    const auto& y = std::get<RgbdFrame>(from_folder[i]);
    EXPECT_NEAR(x.stamp.sensor_time_s, y.stamp.sensor_time_s, 1e-6) << i;
    EXPECT_EQ(cv::norm(x.color, y.color, cv::NORM_INF), 0) << i;
    EXPECT_GE(MaxDepthDifference(x.depth_m, y.depth_m), 0) << "NaN pattern differs, frame " << i;
    EXPECT_LT(MaxDepthDifference(x.depth_m, y.depth_m), 1e-6) << i;
    // The bag's /tf pose, stamped with the colour image's time, is the folder's mocap sample
    // at or after that time (how its writer picked it; the folder's nearest sample is up to
    // 10 ms earlier).
    auto mine = bag.ground_truth()->Nearest(x.stamp.sensor_time_s, 1e-6);
    ASSERT_TRUE(mine) << i;
    const auto after =
        std::lower_bound(truth.poses().begin(), truth.poses().end(), y.stamp.sensor_time_s,
                         [](const TimedPose& pose, double t) { return pose.time_s < t; });
    ASSERT_NE(after, truth.poses().end()) << i;
    const Eigen::Isometry3d& p = bag.ground_truth()->poses()[*mine].world_from_sensor;
    const Eigen::Isometry3d& q = after->world_from_sensor;
    EXPECT_LT((p.translation() - q.translation()).norm(), 1e-4) << i;
    EXPECT_LT(Eigen::AngleAxisd(p.rotation().transpose() * q.rotation()).angle(), 1e-3) << i;
  }
}

TEST(BagSource, SeekingGivesTheFrameReadInOrder) {
  SIGHTLINE_REQUIRE_DATA(path, "rosbags/tum_fr1_desk.bag");
  BagSource source(path);
  ASSERT_TRUE(source.Open().ok());
  EXPECT_TRUE(source.info().seekable);
  const std::vector<Frame> all = ReadAll(source);
  for (int64_t index : {6, 2, 8, 0}) {
    ASSERT_TRUE(source.Seek(index).ok());
    ASSERT_TRUE(source.Grab().ok());
    StatusOr<Frame> frame = source.Retrieve();
    ASSERT_TRUE(frame.ok());
    const auto& x = std::get<RgbdFrame>(*frame);
    const auto& y = std::get<RgbdFrame>(all[size_t(index)]);
    EXPECT_EQ(x.stamp.sequence_id, index);
    EXPECT_EQ(cv::norm(x.color, y.color, cv::NORM_INF), 0);
  }
}

TEST(BagSource, OptionsChooseAnotherKindAndNameWhatIsMissing) {
  SIGHTLINE_REQUIRE_DATA(path, "rosbags/tum_fr1_desk.bag");
  OptionSet options;
  ASSERT_TRUE(DeclareSensorOptions(&options).ok());
  ASSERT_TRUE(options.ApplyOverride("io.rosbag.kind=mono").ok());
  StatusOr<std::unique_ptr<Source>> mono = OpenSource(path, options);
  ASSERT_TRUE(mono.ok()) << mono.status().ToString();
  EXPECT_EQ((*mono)->info().kind, SourceKind::kMono);
  EXPECT_EQ((*mono)->info().frame_count, 9);

  ASSERT_TRUE(options.ApplyOverride("io.rosbag.kind=auto").ok());
  ASSERT_TRUE(options.ApplyOverride("io.rosbag.image_topic=/camera/nothing").ok());
  StatusOr<std::unique_ptr<Source>> missing = OpenSource(path, options);
  ASSERT_FALSE(missing.ok());
  EXPECT_TRUE(Contains(missing.status().message(), "/camera/nothing"));
  EXPECT_TRUE(Contains(missing.status().message(), "/camera/rgb/image_color"));

  options.Reset("io.rosbag.image_topic");
  ASSERT_TRUE(options.ApplyOverride("io.rosbag.tf_parent_frame=world").ok());
  ASSERT_TRUE(options.ApplyOverride("io.rosbag.tf_child_frame=base").ok());
  StatusOr<std::unique_ptr<Source>> no_tf = OpenSource(path, options);
  ASSERT_FALSE(no_tf.ok());
  EXPECT_TRUE(Contains(no_tf.status().message(), "world -> base"));
  EXPECT_TRUE(Contains(no_tf.status().message(), "world -> kinect"));
}

// Bags written from the simulator come back frame for frame.
class SimBagRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(SimBagRoundTrip, RgbdFramesCameraTruthAndOdometryComeBackExactly) {
  const std::string path = TempDir("sim_bag_" + GetParam()) + "/sim.bag";
  testing::SimBagOptions write;
  write.compression = GetParam();
  write.stereo = false;
  StatusOr<testing::SimBag> written = testing::WriteSimBag(path, write);
  ASSERT_TRUE(written.ok()) << written.status().ToString();
  BagSource source(path);
  ASSERT_TRUE(source.Open().ok());
  EXPECT_EQ(source.summary().layout.CompressionText(), GetParam());
  EXPECT_EQ(source.info().kind, SourceKind::kRgbd);
  EXPECT_EQ(source.info().camera->fx, written->rgbd_camera.fx);
  EXPECT_EQ(source.info().camera->cx, written->rgbd_camera.cx);
  const std::vector<Frame> frames = ReadAll(source);
  ASSERT_EQ(frames.size(), size_t(write.frames));
  for (size_t i = 0; i < frames.size(); ++i) {
    const auto& f = std::get<RgbdFrame>(frames[i]);
    EXPECT_NEAR(f.stamp.sensor_time_s, written->times_s[i], 1e-6);
    EXPECT_EQ(cv::norm(f.color, written->color[i], cv::NORM_INF), 0) << i;
    EXPECT_EQ(MaxDepthDifference(f.depth_m, written->depth_m[i]), 0) << i;
  }
  ASSERT_NE(source.ground_truth(), nullptr);
  ASSERT_EQ(source.ground_truth()->size(), written->camera_truth.size());
  for (size_t i = 0; i < written->camera_truth.size(); ++i) {
    const Eigen::Isometry3d& p = source.ground_truth()->poses()[i].world_from_sensor;
    const Eigen::Isometry3d& q = written->camera_truth.poses()[i].world_from_sensor;
    EXPECT_LT((p.matrix() - q.matrix()).norm(), 1e-9) << i;
  }
  ASSERT_NE(source.odometry(), nullptr);
  ASSERT_EQ(source.odometry()->size(), written->odometry.size());
  EXPECT_GT(source.odometry()->size(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Compressions, SimBagRoundTrip, ::testing::Values("none", "bz2", "lz4"));

TEST(BagSource, SixteenBitDepthComesBackInMillimetres) {
  const std::string path = TempDir("sim_bag_16u") + "/sim.bag";
  testing::SimBagOptions write;
  write.depth_16u = true;
  write.stereo = false;
  write.frames = 3;
  StatusOr<testing::SimBag> written = testing::WriteSimBag(path, write);
  ASSERT_TRUE(written.ok()) << written.status().ToString();
  BagSource source(path);
  ASSERT_TRUE(source.Open().ok());
  const std::vector<Frame> frames = ReadAll(source);
  ASSERT_EQ(frames.size(), 3u);
  for (size_t i = 0; i < frames.size(); ++i) {
    const double worst =
        MaxDepthDifference(std::get<RgbdFrame>(frames[i]).depth_m, written->depth_m[i]);
    EXPECT_GE(worst, 0) << i;
    EXPECT_LE(worst, 0.0005 + 1e-6) << i;  // Rounded to whole millimetres.
  }
}

TEST(BagSource, StereoPairsAndTheBaselineFromTheRightProjection) {
  const std::string path = TempDir("sim_bag_stereo") + "/sim.bag";
  testing::SimBagOptions write;
  write.frames = 3;
  StatusOr<testing::SimBag> written = testing::WriteSimBag(path, write);
  ASSERT_TRUE(written.ok()) << written.status().ToString();
  RosBagOptions options;
  options.kind = "stereo";
  BagSource source(path, options);
  ASSERT_TRUE(source.Open().ok());
  EXPECT_EQ(source.choice().image, "/stereo/left/image_raw");
  EXPECT_EQ(source.choice().right_image, "/stereo/right/image_raw");
  ASSERT_TRUE(source.info().stereo.has_value());
  EXPECT_NEAR(source.info().stereo->BaselineM(), written->stereo_rig.BaselineM(), 1e-9);
  const std::vector<Frame> frames = ReadAll(source);
  ASSERT_EQ(frames.size(), 3u);
  for (size_t i = 0; i < frames.size(); ++i) {
    const auto& f = std::get<StereoFrame>(frames[i]);
    EXPECT_EQ(cv::norm(f.left, written->left[i], cv::NORM_INF), 0) << i;
    EXPECT_EQ(cv::norm(f.right, written->right[i], cv::NORM_INF), 0) << i;
  }
  // Automatic choice: three colour topics, but only /camera/rgb/image_color sits beside the
  // depth topic, so the bag reads as RGB-D.
  BagSource automatic(path);
  ASSERT_TRUE(automatic.Open().ok());
  EXPECT_EQ(automatic.info().kind, SourceKind::kRgbd);
  EXPECT_EQ(automatic.choice().image, "/camera/rgb/image_color");
}

TEST(BagSource, ATruncatedBagSaysSo) {
  SIGHTLINE_REQUIRE_DATA(original, "rosbags/tum_fr1_desk.bag");
  const std::string bytes = testing::ReadAll(original);
  ASSERT_GT(bytes.size(), 1000u);
  for (size_t keep : {bytes.size() / 2, size_t(4200), size_t(20)}) {
    const std::string path = TempDir("truncated_" + std::to_string(keep)) + "/cut.bag";
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(keep));
    StatusOr<std::unique_ptr<Source>> source = OpenSource(path);
    ASSERT_FALSE(source.ok()) << keep;
    EXPECT_TRUE(Contains(source.status().message(), path)) << source.status().ToString();
    EXPECT_TRUE(Contains(source.status().message(), "truncated")) << source.status().ToString();
  }
}

// A record header of kMaxBagRecordHeaderBytes + 1 is refused by its length before anything is
// read or allocated for it; one at the cap is read as far as the file goes (here: truncated).
TEST(BagSource, ARecordHeaderBeyondTheCapIsRefusedByItsLength) {
  for (const uint32_t len : {kMaxBagRecordHeaderBytes + 1, kMaxBagRecordHeaderBytes}) {
    const std::string path = TempDir("header_cap_" + std::to_string(len)) + "/cap.bag";
    std::string bytes = "#ROSBAG V2.0\n";
    for (int i = 0; i < 4; ++i) bytes += static_cast<char>((len >> (8 * i)) & 0xff);
    bytes += std::string(64, 'x');
    std::ofstream(path, std::ios::binary) << bytes;
    const StatusOr<BagFileLayout> layout = ReadBagFileLayout(path);
    ASSERT_FALSE(layout.ok()) << len;
    if (len > kMaxBagRecordHeaderBytes) {
      EXPECT_TRUE(Contains(layout.status().message(),
                           path + ": the record at byte 13 has a header of 1048577 bytes"))
          << layout.status().ToString();
    } else {
      EXPECT_TRUE(Contains(layout.status().message(), path + " is truncated"))
          << layout.status().ToString();
    }
  }
}

TEST(BagSource, AFileOfZerosIsNotABag) {
  const std::string path = TempDir("zeros") + "/zeros.bag";
  std::ofstream(path, std::ios::binary) << std::string(4096, '\0');
  StatusOr<std::unique_ptr<Source>> source = OpenSource(path);
  ASSERT_FALSE(source.ok());
  EXPECT_EQ(source.status().code(), StatusCode::kParseError);
  EXPECT_TRUE(Contains(source.status().message(), path + " is not a ROS bag"));
  StatusOr<std::unique_ptr<Source>> missing = OpenSource(TempDir("none") + "/none.bag");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().code(), StatusCode::kNotFound);
}

TEST(BagSource, AnUnknownEncodingNamesTheBagTopicAndMessage) {
  const std::string path = TempDir("encoding") + "/enc.bag";
  ASSERT_TRUE(testing::WriteDefectiveBag(path, "encoding").ok());
  BagSource source(path);
  ASSERT_TRUE(source.Open().ok());
  ASSERT_TRUE(source.Seek(2).ok());
  ASSERT_TRUE(source.Grab().ok());
  StatusOr<Frame> frame = source.Retrieve();
  ASSERT_FALSE(frame.ok());
  EXPECT_TRUE(Contains(frame.status().message(),
                       path + ": /cam/image_raw message 2: unsupported encoding 'yuv422'"))
      << frame.status().ToString();
}

TEST(BagSource, CameraInfoOfZerosOrMissingNamesTheTopicAndTheOption) {
  const std::string zeros = TempDir("zero_info") + "/zero.bag";
  ASSERT_TRUE(testing::WriteDefectiveBag(zeros, "zero_info").ok());
  BagSource zero_source(zeros);
  const Status zero = zero_source.Open();
  ASSERT_FALSE(zero.ok());
  EXPECT_TRUE(Contains(zero.message(), zeros + ": /cam/camera_info message 0: CameraInfo"))
      << zero.ToString();

  const std::string none = TempDir("no_info") + "/none.bag";
  ASSERT_TRUE(testing::WriteDefectiveBag(none, "no_info").ok());
  BagSource none_source(none);
  const Status missing = none_source.Open();
  ASSERT_FALSE(missing.ok());
  EXPECT_TRUE(Contains(missing.message(), "looked for /cam/camera_info")) << missing.ToString();
  EXPECT_TRUE(Contains(missing.message(), "/other/info_a, /other/info_b")) << missing.ToString();
  EXPECT_TRUE(Contains(missing.message(), "io.rosbag.camera_info_topic")) << missing.ToString();

  RosBagOptions chosen;
  chosen.camera_info_topic = "/other/info_b";
  BagSource with_option(none, chosen);
  EXPECT_TRUE(with_option.Open().ok());
}

// A CameraInfo of a few hundred bytes whose D claims 0xfffffff0 doubles: refused by its length
// before anything is allocated for it (decoding it would ask for 34 GB), naming the field.
TEST(BagSource, AnArrayLongerThanItsMessageIsRefusedNamingTheField) {
  const std::string path = TempDir("lying_info") + "/lying.bag";
  ASSERT_TRUE(testing::WriteDefectiveBag(path, "lying_info").ok());
  BagSource source(path);
  const Status opened = source.Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_TRUE(Contains(opened.message(), path)) << opened.ToString();
  EXPECT_TRUE(Contains(opened.message(),
                       "/cam/camera_info: sensor_msgs/CameraInfo: field D "
                       "declares 4294967280 float64 values"))
      << opened.ToString();
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  EXPECT_LT(usage.ru_maxrss, 1024L * 1024) << "peak RSS in KiB";
}

// Adds `delta` to the little-endian uint64 after the first "name=" in the file (a header field).
void ShiftU64Field(const std::string& path, const std::string& name, int64_t delta) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const size_t at = bytes.find(name + "=");
  ASSERT_NE(at, std::string::npos) << name;
  uint64_t value = 0;
  std::memcpy(&value, bytes.data() + at + name.size() + 1, 8);
  value += delta;
  std::memcpy(bytes.data() + at + name.size() + 1, &value, 8);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// rosbag seeks to the bag header's index_pos and to each chunk summary's chunk_pos without
// checking them; a position inside a record made it read a length from the middle of one (a
// 1.1 GB allocation, found by fuzz_rosbag). Both are refused before rosbag opens the file.
TEST(BagSource, PositionsThatAreNotRecordStartsAreRefused) {
  const std::string index = TempDir("index_mid_record") + "/index.bag";
  ASSERT_TRUE(testing::WriteDefectiveBag(index, "zero_info").ok());
  ShiftU64Field(index, "index_pos", 3);
  const Status opened = BagSource(index).Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_TRUE(Contains(opened.message(), index + ": the bag header puts the index at byte"))
      << opened.ToString();
  EXPECT_TRUE(Contains(opened.message(), "where no record starts")) << opened.ToString();

  const std::string chunk = TempDir("chunk_mid_record") + "/chunk.bag";
  ASSERT_TRUE(testing::WriteDefectiveBag(chunk, "zero_info").ok());
  ShiftU64Field(chunk, "chunk_pos", 5);
  const Status chunk_opened = BagSource(chunk).Open();
  ASSERT_FALSE(chunk_opened.ok());
  EXPECT_TRUE(Contains(chunk_opened.message(), chunk + ": the index names a chunk at byte"))
      << chunk_opened.ToString();
}

// A header field whose length runs past its record's header: rosbag's header parser copied past
// the header (a heap overflow found by a 10-minute fuzz_rosbag run); refused, naming the byte.
TEST(BagSource, AHeaderFieldLongerThanItsHeaderIsRefused) {
  const std::string path = TempDir("field_overrun") + "/field.bag";
  ASSERT_TRUE(testing::WriteDefectiveBag(path, "zero_info").ok());
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const size_t field = bytes.find("compression=");  // The first chunk's header.
  ASSERT_NE(field, std::string::npos);
  ASSERT_GE(field, 4u);
  bytes[field - 4] = static_cast<char>(static_cast<uint8_t>(bytes[field - 4]) + 200);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  const Status opened = BagSource(path).Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_TRUE(Contains(opened.message(), "has a header whose fields do not fit in its"))
      << opened.ToString();
}

// Rewrites a bag's bytes with `edit` and returns the path.
std::string EditedBag(const std::string& name, const std::function<void(std::string*)>& edit) {
  const std::string path = TempDir(name) + "/edited.bag";
  EXPECT_TRUE(testing::WriteDefectiveBag(path, "zero_info").ok());
  std::string bytes = testing::ReadAll(path);
  edit(&bytes);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  return path;
}

void AddToU32At(std::string* bytes, size_t at, uint32_t add) {
  uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<uint8_t>((*bytes)[at + i]);
  value += add;
  for (int i = 0; i < 4; ++i) (*bytes)[at + i] = static_cast<char>((value >> (8 * i)) & 0xff);
}

// A connection's header (its record's data: topic, type, md5sum, definition) with a field that
// runs past it, in the index after the chunks and inside a chunk: rosbag's header parser read
// past its buffer (a heap overflow found by fuzz_rosbag). Both are refused, naming the record.
TEST(BagSource, AConnectionHeaderFieldLongerThanItsRecordIsRefused) {
  const std::string index = EditedBag("connection_index", [](std::string* bytes) {
    const size_t field = bytes->rfind("md5sum=");  // The last connection record: the index's.
    ASSERT_NE(field, std::string::npos);
    AddToU32At(bytes, field - 4, 5000);
  });
  Status opened = BagSource(index).Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_TRUE(Contains(opened.message(), index + ": the record at byte")) << opened.ToString();
  EXPECT_TRUE(Contains(opened.message(), "is a connection whose header does not fit"))
      << opened.ToString();

  const std::string chunk = EditedBag("connection_chunk", [](std::string* bytes) {
    const size_t field = bytes->find("md5sum=");  // The first: inside the (uncompressed) chunk.
    ASSERT_NE(field, std::string::npos);
    AddToU32At(bytes, field - 4, 5000);
  });
  opened = BagSource(chunk).Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_TRUE(Contains(opened.message(), "a connection header whose fields do not fit"))
      << opened.ToString();
}

// The records inside a chunk must tile it, and an index must point at a message in it.
TEST(BagSource, AChunksRecordsAndItsIndexMustAgree) {
  const std::string header = EditedBag("chunk_record_header", [](std::string* bytes) {
    const size_t field = bytes->find("op=\x02");  // The first message data record's header.
    ASSERT_NE(field, std::string::npos);
    AddToU32At(bytes, field - 4, 3);  // Its op field now swallows the next field's length.
  });
  Status opened = BagSource(header).Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_TRUE(Contains(opened.message(), "a record header whose fields do not fit"))
      << opened.ToString();

  // Every index entry's offset moved by one byte: into the middle of its message record.
  const std::string offset = EditedBag("index_offset", [](std::string* bytes) {
    size_t pos = 13;
    int edited = 0;
    while (pos + 8 <= bytes->size()) {
      uint32_t header_len = 0, data_len = 0;
      for (int i = 3; i >= 0; --i) header_len = (header_len << 8) | uint8_t((*bytes)[pos + i]);
      const size_t data_at = pos + 8 + header_len;
      for (int i = 3; i >= 0; --i) data_len = (data_len << 8) | uint8_t((*bytes)[data_at - 4 + i]);
      if (bytes->substr(pos + 4, header_len).find("op=\x04") != std::string::npos) {
        for (size_t e = data_at; e + 12 <= data_at + data_len; e += 12, ++edited) {
          AddToU32At(bytes, e + 8, 1);
        }
      }
      pos = data_at + data_len;
    }
    ASSERT_GT(edited, 0);
  });
  opened = BagSource(offset).Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_TRUE(Contains(opened.message(), "where no message record starts")) << opened.ToString();
}

// A chunk that says it expands to kMaxBagChunkBytes + 1 is refused by that size before anything
// is allocated for it.
TEST(BagSource, AChunkBeyondTheCapIsRefusedByItsSize) {
  const std::string path = EditedBag("chunk_cap", [](std::string* bytes) {
    const size_t field = bytes->find("size=");
    ASSERT_NE(field, std::string::npos);
    const uint32_t cap_plus_one = kMaxBagChunkBytes + 1;
    for (int i = 0; i < 4; ++i) (*bytes)[field + 5 + i] = char((cap_plus_one >> (8 * i)) & 0xff);
  });
  const Status opened = BagSource(path).Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_TRUE(Contains(opened.message(),
                       "is a chunk of 268435457 bytes, more than the reader's "
                       "limit of 268435456"))
      << opened.ToString();
}

TEST(BagSource, TwoImageTopicsWithoutLeftAndRightAskForTheOption) {
  const std::string path = TempDir("two_images") + "/two.bag";
  ASSERT_TRUE(testing::WriteDefectiveBag(path, "two_images").ok());
  BagSource source(path);
  const Status opened = source.Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_TRUE(Contains(opened.message(), "/cam/image_raw, /cam2/image_raw")) << opened.ToString();
  EXPECT_TRUE(Contains(opened.message(), "io.rosbag.image_topic")) << opened.ToString();
  RosBagOptions chosen;
  chosen.image_topic = "/cam2/image_raw";
  chosen.camera_info_topic = "/cam/camera_info";
  BagSource with_option(path, chosen);
  const Status chosen_open = with_option.Open();
  ASSERT_TRUE(chosen_open.ok()) << chosen_open.message();
  EXPECT_EQ(with_option.info().frame_count, 3);
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

// BagWriter (core/ros) bags read back; with two tf transforms the images' frame_id picks the
// ground truth.
TEST(BagWriter, WritesWhatTheReaderReadsAndTheImagesFramePicksTheTruth) {
  const std::string path = testing::TempDir("writer") + "/w.bag";
  PinholeCamera camera;
  camera.width = 40, camera.height = 30, camera.fx = camera.fy = 35, camera.cx = 20, camera.cy = 15;
  {
    StatusOr<std::unique_ptr<BagWriter>> bag = BagWriter::Create(path, "lz4");
    ASSERT_TRUE(bag.ok()) << bag.status().ToString();
    for (int i = 0; i < 4; ++i) {
      const double t = 5.0 + 0.1 * i;
      cv::Mat image(30, 40, CV_8UC1, cv::Scalar(40 * i));
      Eigen::Isometry3d camera_pose = Eigen::Isometry3d::Identity();
      camera_pose.translation() = Eigen::Vector3d(0.5 * i, 0, 1);
      Eigen::Isometry3d arm = Eigen::Isometry3d::Identity();
      arm.translation() = Eigen::Vector3d(0, 0.25 * i, 0);
      ASSERT_TRUE((*bag)->WriteImage("/mono/image_raw", t, image, "mono_camera").ok());
      ASSERT_TRUE((*bag)->WriteCameraInfo("/mono/camera_info", t, camera, "mono_camera").ok());
      ASSERT_TRUE((*bag)->WriteTransform(t, "world", "mono_camera", camera_pose).ok());
      ASSERT_TRUE((*bag)->WriteTransform(t, "base_link", "end_effector", arm).ok());
      ASSERT_TRUE((*bag)->WriteOdometry("/odom", t, arm, "odom", "base_link").ok());
    }
    EXPECT_FALSE((*bag)->WriteImage("/x", 0.0, cv::Mat(2, 2, CV_8UC1), "x").ok());
    ASSERT_TRUE((*bag)->Close().ok());
  }
  BagSource source(path);
  const Status opened = source.Open();
  ASSERT_TRUE(opened.ok()) << opened.message();
  EXPECT_EQ(source.summary().layout.CompressionText(), "lz4");
  EXPECT_EQ(source.info().kind, SourceKind::kMono);
  EXPECT_EQ(source.info().camera->fx, 35);
  ASSERT_NE(source.ground_truth(), nullptr);
  ASSERT_EQ(source.ground_truth()->size(), 4u);
  EXPECT_NEAR(source.ground_truth()->poses()[3].world_from_sensor.translation().x(), 1.5, 1e-12);
  ASSERT_NE(source.odometry(), nullptr);
  EXPECT_EQ(source.odometry()->size(), 4u);
  const std::vector<Frame> frames = ReadAll(source);
  ASSERT_EQ(frames.size(), 4u);
  EXPECT_EQ(std::get<MonoFrame>(frames[2]).image.at<uint8_t>(5, 5), 80);
}

}  // namespace
}  // namespace sightline
