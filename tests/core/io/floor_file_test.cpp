// The floor file: round trip, the layout earlier versions wrote, and every check rejecting a bad
// value naming the file, the line and the key.
#include "core/io/floor_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using testing::WriteText;

TEST(FloorFile, WritesAndReadsBack) {
  FloorCalibration calibration;
  calibration.plane.normal = Eigen::Vector3d(0.01, -0.95, -0.3).normalized();
  calibration.plane.d = 0.812345678;
  calibration.plane.epsilon_m = 0.04;
  calibration.inlier_ratio = 0.61;
  calibration.frames = 5;
  calibration.source = "rec/rgbd \"quoted\" C:\\data";
  const std::string path = TempDir("floor_round_trip") + "/floor.yaml";
  ASSERT_TRUE(WriteFloorCalibration(calibration, path).ok());
  StatusOr<FloorCalibration> read = ReadFloorCalibration(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_LT((read->plane.normal - calibration.plane.normal).norm(), 1e-15);
  EXPECT_EQ(read->plane.d, calibration.plane.d);
  EXPECT_EQ(read->plane.epsilon_m, 0.04);
  EXPECT_EQ(read->inlier_ratio, 0.61);
  EXPECT_EQ(read->frames, 5);
  EXPECT_EQ(read->source, calibration.source);
}

// As `sightline-cli floor` wrote it before the file moved to core/io (9 decimals).
TEST(FloorFile, ReadsTheEarlierLayout) {
  const std::string path = TempDir("floor_earlier") + "/floor.yaml";
  WriteText(path,
            "# Sightline floor plane: a x + b y + c z + d = 0 in the camera frame (x right,\n"
            "# y down, z forward, metres); (a, b, c) is the unit normal pointing up, so d is\n"
            "# the camera height. A point is floor when |a x + b y + c z + d| <= epsilon_m.\n"
            "a: 0.010037207\nb: -0.953534629\nc: -0.301116199\nd: 0.812345678\n"
            "epsilon_m: 0.040000\ncamera_height_m: 0.812346\npitch_down_deg: 17.4542\n"
            "inlier_ratio: 0.6100\nframes: 5\nsource: \"rec/rgbd\"\n");
  StatusOr<FloorCalibration> read = ReadFloorCalibration(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_NEAR(read->plane.normal.norm(), 1.0, 1e-15);
  EXPECT_NEAR(read->plane.normal.y(), -0.953534629, 1e-8);
  EXPECT_NEAR(read->plane.d, 0.812345678, 1e-8);
  EXPECT_EQ(read->source, "rec/rgbd");
  EXPECT_EQ(read->frames, 5);
}

TEST(FloorFile, ANormalWithinOnePercentIsNormalisedWithD) {
  const std::string path = TempDir("floor_normalise") + "/floor.yaml";
  WriteText(path, "a: 0\nb: -1.008\nc: 0\nd: 1.008\n");
  StatusOr<FloorCalibration> read = ReadFloorCalibration(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_EQ(read->plane.normal, Eigen::Vector3d(0, -1, 0));
  EXPECT_NEAR(read->plane.d, 1.0, 1e-15);
  EXPECT_EQ(read->plane.epsilon_m, 0.035);  // The default.
}

TEST(FloorFile, EachRuleRejectsNamingFileLineAndKey) {
  const std::string dir = TempDir("floor_rules");
  const std::string plane = "a: 0\nb: -1\nc: 0\nd: 0.8\n";
  struct Case {
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"a: 0\nb: -2\nc: 0\nd: 1.6\n",
       " line 1: key 'a, b, c': the normal has length 2: it must be of unit length within 1 %"},
      {"a: 0\nb: -0.98\nc: 0\nd: 1\n", " line 1: key 'a, b, c': the normal has length 0.98"},
      {"a: 0\nb: 1\nc: 0\nd: -0.8\n",
       " line 4: key 'd': the camera height -0.8 m must be positive, with (a, b, c) pointing up"},
      {"a: 0\nb: -1\nc: 0\nd: 0\n", " line 4: key 'd': the camera height 0 m must be positive"},
      {"a: 0\nb: -1\nc: 0\nd: .inf\n", " line 4: key 'd': .inf is not finite"},
      {"a: 0\nb: -1\nc: 0\nd: zero\n", " line 4: key 'd': 'zero' is not a number"},
      {"a: 0\nb: -1\nd: 0.5\n", ": key 'c': missing"},
      {plane + "height: 3\n", " line 5: unknown key 'height'"},
      {plane + "epsilon_m: 0\n", " line 5: key 'epsilon_m': must be positive"},
      {plane + "inlier_ratio: 1.5\n", " line 5: key 'inlier_ratio': must lie in [0, 1]"},
      {plane + "frames: 2.5\n", " line 5: key 'frames': 2.5 is not a whole number"},
      {plane + "frames: -1\n", " line 5: key 'frames': must not be negative"},
      {plane + "camera_height_m: high\n", " line 5: key 'camera_height_m': 'high' is not"},
      {plane + "source: [a, b]\n", " line 5: key 'source': expected text"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string path = dir + "/case" + std::to_string(i) + ".yaml";
    WriteText(path, cases[i].text);
    const Status status = ReadFloorCalibration(path).status();
    EXPECT_EQ(status.code(), StatusCode::kParseError) << path;
    EXPECT_THAT(status.message(), HasSubstr(path + cases[i].expected));
  }
}

TEST(FloorFile, WriterRefusesAnInvalidPlane) {
  const std::string path = TempDir("floor_refuse") + "/floor.yaml";
  FloorCalibration calibration;
  calibration.plane.d = -1;
  EXPECT_THAT(WriteFloorCalibration(calibration, path).message(),
              HasSubstr("d (camera height) must be positive"));
  calibration.plane.d = 1;
  calibration.inlier_ratio = 2;
  EXPECT_THAT(WriteFloorCalibration(calibration, path).message(),
              HasSubstr("inlier_ratio must lie in [0, 1]"));
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace sightline
