#include "core/io/euroc_source.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

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

// cam0's T_BS (body_from_cam0) from mav0/cam0/sensor.yaml.
Eigen::Isometry3d BodyFromCam0() {
  Eigen::Matrix4d m;
  m << 0.0148655429818, -0.999880929698, 0.00414029679422, -0.0216401454975,  //
      0.999557249008, 0.0149672133247, 0.025715529948, -0.064676986768,       //
      -0.0257744366974, 0.00375618835797, 0.999660727178, 0.00981073058949,   //
      0, 0, 0, 1;
  return Eigen::Isometry3d(m);
}

// A copy of the EuRoC tree with everything linked except cam1/ (its files linked one by one).
std::string CopyEuroc(const std::string& data, const std::string& name,
                      const std::vector<std::string>& skip_cam1_images = {}) {
  const std::string dir = TempDir(name);
  const std::string mav0 = data + "/mav0";
  for (const char* part : {"cam0", "imu0", "state_groundtruth_estimate0", "body.yaml"}) {
    LinkTo(mav0 + "/" + part, dir + "/mav0/" + part);
  }
  LinkFolderFiles(mav0 + "/cam1/data", dir + "/mav0/cam1/data", skip_cam1_images);
  testing::CopyFileTo(mav0 + "/cam1/data.csv", dir + "/mav0/cam1/data.csv");
  testing::CopyFileTo(mav0 + "/cam1/sensor.yaml", dir + "/mav0/cam1/sensor.yaml");
  return dir;
}

TEST(EurocSourceTest, OpensTwentyRawStereoPairs) {
  SIGHTLINE_REQUIRE_DATA(data, "euroc_v1_01_static");
  EurocSource source(data);
  ASSERT_TRUE(source.Open().ok()) << source.Open().ToString();
  const SourceInfo& info = source.info();
  EXPECT_EQ(info.format, "EuRoC MAV");
  EXPECT_EQ(info.kind, SourceKind::kStereo);
  EXPECT_EQ(info.frame_count, 20);
  EXPECT_EQ(info.width, 752);
  EXPECT_EQ(info.height, 480);
  EXPECT_DOUBLE_EQ(info.rate_hz, 20);
  EXPECT_NEAR(info.duration_s, 19 * 0.05, 1e-3);
  ASSERT_TRUE(info.stereo.has_value());
  const StereoRig& rig = *info.stereo;
  EXPECT_FALSE(rig.rectified);
  EXPECT_DOUBLE_EQ(rig.left.fx, 458.654);
  EXPECT_DOUBLE_EQ(rig.left.fy, 457.296);
  EXPECT_DOUBLE_EQ(rig.left.cx, 367.215);
  EXPECT_DOUBLE_EQ(rig.left.cy, 248.375);
  EXPECT_DOUBLE_EQ(rig.left.distortion[0], -0.28340811);
  EXPECT_DOUBLE_EQ(rig.left.distortion[1], 0.07395907);
  EXPECT_DOUBLE_EQ(rig.left.distortion[2], 0.00019359);
  EXPECT_DOUBLE_EQ(rig.left.distortion[3], 1.76187114e-05);
  EXPECT_DOUBLE_EQ(rig.left.distortion[4], 0);
  EXPECT_DOUBLE_EQ(rig.right.fx, 457.587);
  EXPECT_DOUBLE_EQ(rig.right.distortion[0], -0.28368365);
  EXPECT_EQ(info.camera->fx, rig.left.fx);
  // Baseline from the two T_BS: |t_B_cam1 - t_B_cam0| = 0.1101 m.
  const Eigen::Vector3d t0(-0.0216401454975, -0.064676986768, 0.00981073058949);
  const Eigen::Vector3d t1(-0.0198435579556, 0.0453689425024, 0.00786212447038);
  EXPECT_NEAR((t1 - t0).norm(), 0.1101, 0.001);
  EXPECT_NEAR(rig.BaselineM(), (t1 - t0).norm(), 1e-9);
  // cam1 sits to the right of cam0 (x right): the left centre is at negative x in cam1.
  EXPECT_LT(rig.right_from_left.translation().x(), -0.10);
  // The two cameras are mounted nearly parallel (0.8 deg apart).
  EXPECT_LT(Eigen::AngleAxisd(rig.right_from_left.linear()).angle(), 0.03);
  EXPECT_TRUE(info.has_ground_truth);
}

TEST(EurocSourceTest, FramesCarryDataCsvTimesAndGreyImages) {
  SIGHTLINE_REQUIRE_DATA(data, "euroc_v1_01_static");
  EurocSource source(data + "/mav0");  // The mav0 folder itself also opens.
  ASSERT_TRUE(source.Open().ok());
  ASSERT_TRUE(source.Grab().ok());
  auto frame = source.Retrieve();
  ASSERT_TRUE(frame.ok()) << frame.status().ToString();
  const auto& stereo = std::get<StereoFrame>(*frame);
  EXPECT_EQ(stereo.stamp.sequence_id, 0);
  EXPECT_NEAR(stereo.stamp.sensor_time_s, 1403715273.262142976, 1e-6);
  EXPECT_EQ(stereo.left.type(), CV_8UC1);
  EXPECT_EQ(stereo.right.type(), CV_8UC1);
  EXPECT_EQ(stereo.left.cols, 752);
  EXPECT_EQ(stereo.right.rows, 480);
  EXPECT_GT(cv::norm(stereo.left, stereo.right, cv::NORM_L1), 0);  // Two different cameras.
  int count = 1;
  while (source.Grab().ok()) ++count;
  EXPECT_EQ(count, 20);
}

TEST(EurocSourceTest, GroundTruthIsTheLeftCameraPose) {
  SIGHTLINE_REQUIRE_DATA(data, "euroc_v1_01_static");
  EurocSource source(data);
  ASSERT_TRUE(source.Open().ok());
  const Trajectory* gt = source.ground_truth();
  ASSERT_NE(gt, nullptr);
  for (int64_t i = 0; i < source.info().frame_count; ++i) {
    EXPECT_TRUE(gt->Nearest(source.FrameTimeS(i), 0.01).has_value()) << "frame " << i;
  }
  // First row of groundtruth_tum.txt: body pose; expected = world_from_body * body_from_cam0.
  Eigen::Isometry3d world_from_body = Eigen::Isometry3d::Identity();
  world_from_body.linear() =
      Eigen::Quaterniond(0.069433, -0.824237, -0.106942, -0.551702).normalized().matrix();
  world_from_body.translation() = Eigen::Vector3d(0.878895, 2.183400, 0.948427);
  const Eigen::Isometry3d expected = world_from_body * BodyFromCam0();
  const TimedPose& first = gt->poses().front();
  EXPECT_NEAR(first.time_s, 1403715273.26214, 1e-6);
  EXPECT_LT((first.world_from_sensor.translation() - expected.translation()).norm(), 1e-6);
  EXPECT_LT(
      Eigen::AngleAxisd(first.world_from_sensor.linear().transpose() * expected.linear()).angle(),
      1e-6);
  // The MAV sits still: < 3 mm of motion.
  EXPECT_LT(gt->LengthM(), 0.01);
  EXPECT_TRUE(
      std::any_of(source.info().notes.begin(), source.info().notes.end(),
                  [](const std::string& n) { return n.find("body") != std::string::npos; }));
}

TEST(EurocSourceTest, MissingRightImageIsNotFoundNamingTheFile) {
  SIGHTLINE_REQUIRE_DATA(data, "euroc_v1_01_static");
  const std::string dir = CopyEuroc(data, "euroc_missing", {"1403715273462142976.png"});
  const Status status = EurocSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("cam1/data/1403715273462142976.png"));
}

TEST(EurocSourceTest, UnpairedTimestampsAreSkippedWithANote) {
  SIGHTLINE_REQUIRE_DATA(data, "euroc_v1_01_static");
  const std::string dir = CopyEuroc(data, "euroc_unpaired");
  std::vector<std::string> lines = ReadLines(dir + "/mav0/cam1/data.csv");
  lines.erase(lines.begin() + 3);  // Drops the third image of cam1.
  WriteLines(dir + "/mav0/cam1/data.csv", lines);
  EurocSource source(dir);
  ASSERT_TRUE(source.Open().ok());
  EXPECT_EQ(source.info().frame_count, 19);
  EXPECT_TRUE(
      std::any_of(source.info().notes.begin(), source.info().notes.end(),
                  [](const std::string& n) { return n.find("skipped") != std::string::npos; }));
}

TEST(EurocSourceTest, MalformedSensorYamlIsParseErrorNamingFileAndKey) {
  SIGHTLINE_REQUIRE_DATA(data, "euroc_v1_01_static");
  const std::string dir = CopyEuroc(data, "euroc_yaml");
  std::vector<std::string> lines = ReadLines(dir + "/mav0/cam1/sensor.yaml");
  for (std::string& line : lines) {
    if (line.rfind("intrinsics:", 0) == 0) line = "intrinsics: [457.587, 456.134, 379.999]";
  }
  WriteLines(dir + "/mav0/cam1/sensor.yaml", lines);
  const Status status = EurocSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("cam1/sensor.yaml"));
  EXPECT_THAT(status.message(), HasSubstr("'intrinsics'"));
  EXPECT_THAT(status.message(), HasSubstr("expected 4 numbers, found 3"));
}

TEST(EurocSourceTest, BadTimestampInDataCsvNamesLine) {
  SIGHTLINE_REQUIRE_DATA(data, "euroc_v1_01_static");
  const std::string dir = CopyEuroc(data, "euroc_csv");
  std::vector<std::string> lines = ReadLines(dir + "/mav0/cam1/data.csv");
  lines[4] = "14037152734621x2976,1403715273462142976.png";
  WriteLines(dir + "/mav0/cam1/data.csv", lines);
  const Status status = EurocSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("cam1/data.csv line 5"));
}

TEST(EurocSourceTest, FolderWithoutMav0IsNotFound) {
  const Status status = EurocSource(TempDir("euroc_empty")).Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("mav0"));
}

}  // namespace
}  // namespace sightline
