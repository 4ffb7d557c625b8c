#include "core/io/tum_rgbd_source.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::LinkFolderFiles;
using testing::LinkTo;
using testing::ReadLines;
using testing::TempDir;
using testing::WriteLines;
using testing::WriteText;

constexpr const char* kFirstDepth = "depth/1305031453.374112.png";

// A copy of the TUM folder: lists copied (so a test may break them), images linked.
std::string CopyTum(const std::string& data, const std::string& name, bool with_associations) {
  const std::string dir = TempDir(name) + "/rgbd_dataset_freiburg1_desk";
  LinkFolderFiles(data + "/rgb", dir + "/rgb");
  LinkFolderFiles(data + "/depth", dir + "/depth");
  for (const char* file : {"rgb.txt", "depth.txt", "groundtruth.txt"}) {
    testing::CopyFileTo(data + "/" + file, dir + "/" + file);
  }
  if (with_associations) {
    testing::CopyFileTo(data + "/associations.txt", dir + "/associations.txt");
  }
  return dir;
}

TEST(TumRgbdSourceTest, OpensNineFramesWithFreiburg1Intrinsics) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  TumRgbdSource source(data);
  ASSERT_TRUE(source.Open().ok());
  const SourceInfo& info = source.info();
  EXPECT_EQ(info.format, "TUM RGB-D");
  EXPECT_EQ(info.kind, SourceKind::kRgbd);
  EXPECT_EQ(info.frame_count, 9);
  EXPECT_EQ(info.width, 640);
  EXPECT_EQ(info.height, 480);
  EXPECT_TRUE(info.seekable);
  EXPECT_FALSE(info.live);
  EXPECT_NEAR(info.duration_s, 1305031453.627706 - 1305031453.359684, 1e-6);
  EXPECT_NEAR(info.rate_hz, 30, 3);
  ASSERT_TRUE(info.camera.has_value());
  ASSERT_TRUE(info.rgbd.has_value());
  const PinholeCamera& c = *info.camera;
  EXPECT_DOUBLE_EQ(c.fx, 517.3);
  EXPECT_DOUBLE_EQ(c.fy, 516.5);
  EXPECT_DOUBLE_EQ(c.cx, 318.6);
  EXPECT_DOUBLE_EQ(c.cy, 255.3);
  EXPECT_DOUBLE_EQ(c.distortion[0], 0.2624);
  EXPECT_DOUBLE_EQ(c.distortion[4], 1.1633);
  EXPECT_EQ(info.rgbd->color.fx, c.fx);
  EXPECT_DOUBLE_EQ(info.rgbd->depth_scale, 5000);
  EXPECT_TRUE(info.has_ground_truth);
  EXPECT_TRUE(std::any_of(info.notes.begin(), info.notes.end(), [](const std::string& n) {
    return n.find("freiburg1") != std::string::npos;
  }));
}

TEST(TumRgbdSourceTest, EveryFrameHasGroundTruthWithin20Ms) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  TumRgbdSource source(data);
  ASSERT_TRUE(source.Open().ok());
  const Trajectory* gt = source.ground_truth();
  ASSERT_NE(gt, nullptr);
  EXPECT_GT(gt->size(), 1000u);  // The full-sequence mocap file.
  int frames = 0;
  double previous_time = 0;
  while (source.Grab().ok()) {
    StatusOr<Frame> frame = source.Retrieve();
    ASSERT_TRUE(frame.ok()) << frame.status().ToString();
    const auto& rgbd = std::get<RgbdFrame>(*frame);
    EXPECT_EQ(rgbd.stamp.sequence_id, frames);
    EXPECT_GT(rgbd.stamp.host_time_s, 0);
    if (frames > 0) EXPECT_GT(rgbd.stamp.sensor_time_s, previous_time);
    previous_time = rgbd.stamp.sensor_time_s;
    EXPECT_TRUE(gt->Nearest(rgbd.stamp.sensor_time_s, 0.02).has_value())
        << "no ground truth near frame " << frames;
    EXPECT_EQ(rgbd.color.type(), CV_8UC3);
    EXPECT_EQ(rgbd.depth_m.type(), CV_32FC1);
    EXPECT_EQ(rgbd.depth_m.size(), rgbd.color.size());
    ++frames;
  }
  EXPECT_EQ(frames, 9);
  EXPECT_EQ(source.Grab().code(), StatusCode::kOutOfRange);
  EXPECT_NEAR(previous_time, 1305031453.627706, 1e-6);
}

TEST(TumRgbdSourceTest, DepthIsPngValueOver5000WithNanForZero) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  TumRgbdSource source(data);
  ASSERT_TRUE(source.Open().ok());
  ASSERT_TRUE(source.Grab().ok());
  StatusOr<Frame> frame = source.Retrieve();
  ASSERT_TRUE(frame.ok());
  const cv::Mat& depth = std::get<RgbdFrame>(*frame).depth_m;
  const cv::Mat raw = cv::imread(data + "/" + kFirstDepth, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(raw.type(), CV_16UC1);
  ASSERT_EQ(raw.size(), depth.size());
  // One value checked by hand: pixel (u=320, v=240) holds 5398 -> 1.0796 m.
  EXPECT_EQ(raw.at<uint16_t>(240, 320), 5398);
  EXPECT_NEAR(depth.at<float>(240, 320), 1.0796f, 1e-6f);
  int zeros = 0, checked = 0;
  for (int v = 0; v < raw.rows; v += 7) {
    for (int u = 0; u < raw.cols; u += 5) {
      const uint16_t value = raw.at<uint16_t>(v, u);
      const float metres = depth.at<float>(v, u);
      if (value == 0) {
        EXPECT_TRUE(std::isnan(metres)) << "at " << u << "," << v;
        ++zeros;
      } else {
        EXPECT_FLOAT_EQ(metres, static_cast<float>(value / 5000.0)) << "at " << u << "," << v;
      }
      ++checked;
    }
  }
  EXPECT_GT(zeros, 0);  // The Kinect leaves holes; they must be NaN.
  EXPECT_GT(checked - zeros, checked / 2);
}

TEST(TumRgbdSourceTest, PairsByNearestTimeWithoutAssociationsFile) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  const std::string dir = CopyTum(data, "tum_noassoc", false);
  TumRgbdSource source(dir);
  ASSERT_TRUE(source.Open().ok());
  ASSERT_EQ(source.associations().size(), 9u);
  // Same pairs as the associations.txt published with the data.
  const std::vector<std::string> published = ReadLines(data + "/associations.txt");
  for (size_t i = 0; i < 9; ++i) {
    const TumAssociation& a = source.associations()[i];
    EXPECT_THAT(published[i], HasSubstr(std::filesystem::path(a.rgb.file).filename().string()));
    EXPECT_THAT(published[i], HasSubstr(std::filesystem::path(a.depth.file).filename().string()));
  }
}

TEST(TumRgbdSourceTest, AssociateByTimeKeepsPairsUniqueAndClose) {
  const std::vector<TimedFile> rgb = {{0.00, "r0"}, {0.03, "r1"}, {0.06, "r2"}, {0.50, "r3"}};
  const std::vector<TimedFile> depth = {{0.035, "d1"}, {0.005, "d0"}, {0.045, "d2"}};
  const std::vector<TumAssociation> pairs = AssociateByTime(rgb, depth, 0.02);
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(pairs[0].rgb.file, "r0");
  EXPECT_EQ(pairs[0].depth.file, "d0");
  EXPECT_EQ(pairs[1].rgb.file, "r1");
  EXPECT_EQ(pairs[1].depth.file, "d1");  // 0.005 apart beats d2's 0.015.
  EXPECT_EQ(pairs[2].rgb.file, "r2");
  EXPECT_EQ(pairs[2].depth.file, "d2");  // d1 is taken; d2 is 0.015 away.
}

TEST(TumRgbdSourceTest, DetectsFreiburgCameraFromNames) {
  EXPECT_EQ(DetectFreiburgCamera(" file: 'rgbd_dataset_freiburg2_xyz.bag'"), 2);
  EXPECT_EQ(DetectFreiburgCamera("tum_fr3_office"), 3);
  EXPECT_EQ(DetectFreiburgCamera("TUM_FR1_DESK"), 1);
  EXPECT_FALSE(DetectFreiburgCamera("xfr1").has_value());
  EXPECT_FALSE(DetectFreiburgCamera("frames").has_value());
  EXPECT_FALSE(DetectFreiburgCamera("fr12").has_value());
  EXPECT_DOUBLE_EQ(TumCamera(2).fx, 520.9);
  EXPECT_DOUBLE_EQ(TumCamera(3).cy, 247.6);
  EXPECT_FALSE(TumCamera(3).HasDistortion());
  EXPECT_DOUBLE_EQ(TumCamera(0).fx, 525.0);
  EXPECT_DOUBLE_EQ(TumCamera(0).cx, 319.5);
}

TEST(TumRgbdSourceTest, CameraYamlOverridesIntrinsicsAndDepthScale) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  const std::string dir = CopyTum(data, "tum_yaml", true);
  WriteText(dir + "/camera.yaml",
            "%YAML:1.0\nwidth: 640\nheight: 480\nfx: 600\nfy: 601\ncx: 320\ncy: 240\n"
            "depth_scale: 1000\n");
  TumRgbdSource source(dir);
  ASSERT_TRUE(source.Open().ok());
  EXPECT_DOUBLE_EQ(source.info().camera->fx, 600);
  EXPECT_DOUBLE_EQ(source.info().camera->fy, 601);
  EXPECT_FALSE(source.info().camera->HasDistortion());
  EXPECT_DOUBLE_EQ(source.info().rgbd->depth_scale, 1000);
  ASSERT_TRUE(source.Grab().ok());
  auto frame = source.Retrieve();
  ASSERT_TRUE(frame.ok());
  EXPECT_NEAR(std::get<RgbdFrame>(*frame).depth_m.at<float>(240, 320), 5.398f, 1e-5f);
}

TEST(TumRgbdSourceTest, DefaultIntrinsicsWhenSequenceUnknown) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  const std::string dir = TempDir("tum_unknown") + "/my_recording";
  LinkTo(data + "/rgb", dir + "/rgb");
  LinkTo(data + "/depth", dir + "/depth");
  testing::CopyFileTo(data + "/associations.txt", dir + "/associations.txt");
  TumRgbdSource source(dir);
  ASSERT_TRUE(source.Open().ok());
  EXPECT_DOUBLE_EQ(source.info().camera->fx, 525.0);
  EXPECT_FALSE(source.info().has_ground_truth);
  EXPECT_EQ(source.ground_truth(), nullptr);
}

TEST(TumRgbdSourceTest, SeekPositionAndRetrieveOrder) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  TumRgbdSource source(data);
  EXPECT_EQ(source.Grab().code(), StatusCode::kFailedPrecondition);  // Not open.
  ASSERT_TRUE(source.Open().ok());
  EXPECT_EQ(source.Retrieve().status().code(), StatusCode::kFailedPrecondition);
  EXPECT_EQ(source.Position(), 0);
  ASSERT_TRUE(source.Seek(5).ok());
  EXPECT_EQ(source.Position(), 5);
  ASSERT_TRUE(source.Grab().ok());
  EXPECT_EQ(source.Position(), 6);
  auto frame = source.Retrieve();
  ASSERT_TRUE(frame.ok());
  EXPECT_EQ(StampOf(*frame).sequence_id, 5);
  EXPECT_NEAR(StampOf(*frame).sensor_time_s, 1305031453.523684, 1e-6);
  EXPECT_EQ(source.Seek(10).code(), StatusCode::kOutOfRange);
  ASSERT_TRUE(source.Seek(9).ok());
  EXPECT_EQ(source.Grab().code(), StatusCode::kOutOfRange);
  EXPECT_EQ(source.Retrieve().status().code(), StatusCode::kFailedPrecondition);
}

TEST(TumRgbdSourceTest, MissingImageIsNotFoundNamingTheFile) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  const std::string dir = TempDir("tum_missing") + "/rgbd_dataset_freiburg1_desk";
  LinkFolderFiles(data + "/rgb", dir + "/rgb", {"1305031453.459685.png"});
  LinkTo(data + "/depth", dir + "/depth");
  testing::CopyFileTo(data + "/associations.txt", dir + "/associations.txt");
  TumRgbdSource source(dir);
  const Status status = source.Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("rgb/1305031453.459685.png"));
}

TEST(TumRgbdSourceTest, TruncatedListLineIsParseErrorNamingFileAndLine) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  const std::string dir = CopyTum(data, "tum_truncated", false);
  std::vector<std::string> lines = ReadLines(dir + "/rgb.txt");
  ASSERT_GE(lines.size(), 6u);
  lines[4] = "1305031453.391690";  // Line 5 loses its file name.
  WriteLines(dir + "/rgb.txt", lines);
  const Status status = TumRgbdSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("rgb.txt line 5"));
}

TEST(TumRgbdSourceTest, TruncatedAssociationLineIsParseError) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  const std::string dir = CopyTum(data, "tum_truncated_assoc", true);
  std::vector<std::string> lines = ReadLines(dir + "/associations.txt");
  lines[2] = "1305031453.423683 rgb/1305031453.423683.png 1305031453.436941";
  WriteLines(dir + "/associations.txt", lines);
  const Status status = TumRgbdSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("associations.txt line 3"));
}

TEST(TumRgbdSourceTest, EightBitDepthIsParseErrorSayingWhatWasExpected) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  const std::string dir = TempDir("tum_8bit") + "/rgbd_dataset_freiburg1_desk";
  const std::string bad = "1305031453.436941.png";  // Third frame's depth.
  LinkTo(data + "/rgb", dir + "/rgb");
  LinkFolderFiles(data + "/depth", dir + "/depth", {bad});
  cv::Mat eight_bit;
  cv::imread(data + "/depth/" + bad, cv::IMREAD_UNCHANGED).convertTo(eight_bit, CV_8U, 1 / 256.0);
  ASSERT_TRUE(cv::imwrite(dir + "/depth/" + bad, eight_bit));
  testing::CopyFileTo(data + "/associations.txt", dir + "/associations.txt");
  TumRgbdSource source(dir);
  ASSERT_TRUE(source.Open().ok());  // Only the first pair is decoded by Open().
  ASSERT_TRUE(source.Seek(2).ok());
  ASSERT_TRUE(source.Grab().ok());
  const Status status = source.Retrieve().status();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("depth/" + bad));
  EXPECT_THAT(status.message(), HasSubstr("expected a 16-bit single-channel depth image"));
  EXPECT_THAT(status.message(), HasSubstr("8-bit"));
  // The other frames still read.
  ASSERT_TRUE(source.Grab().ok());
  EXPECT_TRUE(source.Retrieve().ok());
}

TEST(TumRgbdSourceTest, NanInGroundTruthIsParseErrorNamingLine) {
  SIGHTLINE_REQUIRE_DATA(data, "tum_fr1_desk");
  const std::string dir = CopyTum(data, "tum_gt_nan", true);
  std::vector<std::string> lines = ReadLines(dir + "/groundtruth.txt");
  lines[5] = "1305031449.8296 nan -0.0113 1.6941 0.7907 0.4393 -0.1770 -0.3879";
  WriteLines(dir + "/groundtruth.txt", lines);
  const Status status = TumRgbdSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("groundtruth.txt line 6"));
}

TEST(TumRgbdSourceTest, EmptyAndMissingFoldersAreNotFound) {
  const std::string empty = TempDir("tum_empty");
  Status status = TumRgbdSource(empty).Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("rgb.txt"));
  status = TumRgbdSource(empty + "/nope").Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("nope"));
}

}  // namespace
}  // namespace sightline
