#include "core/io/camera_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/core/persistence.hpp>

#include "core/io/dataset.h"
#include "core/sim/simulate.h"
#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using testing::WriteText;

TEST(CameraYamlTest, WritesAndReadsBack) {
  const std::string path = TempDir("camera_yaml") + "/camera.yaml";
  CameraFile file;
  file.camera.width = 640;
  file.camera.height = 480;
  file.camera.fx = 517.3;
  file.camera.fy = 516.5;
  file.camera.cx = 318.6;
  file.camera.cy = 255.3;
  file.camera.distortion = {0.2624, -0.9531, -0.0054, 0.0026, 1.1633};
  file.depth_scale = 5000;
  file.rate_hz = 30;
  ASSERT_TRUE(WriteCameraYaml(file, path).ok());
  auto read = ReadCameraYaml(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_EQ(read->camera.width, 640);
  EXPECT_EQ(read->camera.height, 480);
  EXPECT_DOUBLE_EQ(read->camera.fx, 517.3);
  EXPECT_DOUBLE_EQ(read->camera.cy, 255.3);
  EXPECT_EQ(read->camera.distortion, file.camera.distortion);
  EXPECT_EQ(read->depth_scale, 5000);
  EXPECT_EQ(read->rate_hz, 30);
  EXPECT_FALSE(read->max_depth_m.has_value());
}

TEST(CameraYamlTest, AcceptsOpenCvHeaderAndFourDistortionValues) {
  const std::string path = TempDir("camera_yaml_cv") + "/camera.yaml";
  WriteText(path,
            "%YAML:1.0\n---\nwidth: 752\nheight: 480\nfx: 458.654\nfy: 457.296\n"
            "cx: 367.215\ncy: 248.375\ndistortion: [ -0.2834, 0.0739, 1.9e-4, 1.7e-05 ]\n");
  auto read = ReadCameraYaml(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_DOUBLE_EQ(read->camera.distortion[3], 1.7e-05);
  EXPECT_DOUBLE_EQ(read->camera.distortion[4], 0);
  EXPECT_FALSE(read->depth_scale.has_value());
}

TEST(CameraYamlTest, UnknownKeyIsParseErrorNamingIt) {
  const std::string path = TempDir("camera_yaml_unknown") + "/camera.yaml";
  WriteText(path, "width: 64\nheight: 48\nfx: 50\nfy: 50\ncx: 32\ncy: 24\nfocal: 3\n");
  auto read = ReadCameraYaml(path);
  EXPECT_EQ(read.status().code(), StatusCode::kParseError);
  EXPECT_THAT(read.status().message(), HasSubstr("camera.yaml"));
  EXPECT_THAT(read.status().message(), HasSubstr("'focal'"));
}

TEST(CameraYamlTest, MissingOrBadFieldsAreParseErrors) {
  const std::string dir = TempDir("camera_yaml_bad");
  WriteText(dir + "/a.yaml", "width: 64\nheight: 48\nfy: 50\ncx: 32\ncy: 24\n");
  EXPECT_THAT(ReadCameraYaml(dir + "/a.yaml").status().message(), HasSubstr("'fx': missing"));
  WriteText(dir + "/b.yaml", "width: 64\nheight: 48\nfx: abc\nfy: 50\ncx: 32\ncy: 24\n");
  EXPECT_THAT(ReadCameraYaml(dir + "/b.yaml").status().message(), HasSubstr("'abc'"));
  WriteText(dir + "/c.yaml", "width: 64\nheight: 48\nfx: -5\nfy: 50\ncx: 32\ncy: 24\n");
  EXPECT_EQ(ReadCameraYaml(dir + "/c.yaml").status().code(), StatusCode::kParseError);
  WriteText(dir + "/d.yaml", "width: [64\n");
  auto d = ReadCameraYaml(dir + "/d.yaml");
  EXPECT_EQ(d.status().code(), StatusCode::kParseError);
  EXPECT_THAT(d.status().message(), HasSubstr("d.yaml line"));
  EXPECT_EQ(ReadCameraYaml(dir + "/none.yaml").status().code(), StatusCode::kNotFound);
}

TEST(CameraYamlTest, EachRuleRejectsNamingFileLineAndKey) {
  const std::string dir = TempDir("camera_yaml_rules");
  const std::string good = "width: 64\nheight: 48\nfx: 50\nfy: 50\ncx: 32\ncy: 24\n";
  struct Case {
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"width: 0\nheight: 48\nfx: 50\nfy: 50\ncx: 32\ncy: 24\n",
       "line 1: key 'width': image width 0 must be positive"},
      {"width: 64.5\nheight: 48\nfx: 50\nfy: 50\ncx: 32\ncy: 24\n",
       "line 1: key 'width': 64.5 is not a whole number"},
      {"width: 64\nheight: 48\nfx: -5\nfy: 50\ncx: 32\ncy: 24\n",
       "line 3: key 'fx': focal length fx = -5 must be positive and finite"},
      {"width: 64\nheight: 48\nfx: 50\nfy: .inf\ncx: 32\ncy: 24\n",
       "line 4: key 'fy': .inf is not finite"},
      {"width: 64\nheight: 48\nfx: 50\nfy: 50\ncx: 99\ncy: 24\n",
       "line 5: key 'cx': principal point cx = 99 must lie inside the image [0, 64]"},
      {"width: 64\nheight: 48\nfx: 50\nfy: 50\ncx: 32\ncy: -3\n",
       "line 6: key 'cy': principal point cy = -3 must lie inside the image [0, 48]"},
      {good + "distortion: [0.1, 2000, 0, 0]\n",
       "line 7: key 'distortion': distortion k2 = 2000 must be finite with magnitude below 1000"},
      {good + "distortion: [0.1, 0, 0]\n", "line 7: key 'distortion': expected 4 to 5 numbers"},
      {good + "rate_hz: 0\n", "line 7: key 'rate_hz': must be positive"},
      {good + "model: fisheye\n", "line 7: key 'model': 'fisheye' is not supported"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string path = dir + "/case" + std::to_string(i) + ".yaml";
    WriteText(path, cases[i].text);
    const Status status = ReadCameraYaml(path).status();
    EXPECT_EQ(status.code(), StatusCode::kParseError) << path;
    EXPECT_THAT(status.message(), HasSubstr(path + " " + cases[i].expected));
  }
}

TEST(CameraYamlTest, WriterRefusesWhatTheReaderWouldReject) {
  const std::string path = TempDir("camera_yaml_refuse") + "/camera.yaml";
  CameraFile file;
  file.camera.width = 640;
  file.camera.height = 480;
  file.camera.fx = file.camera.fy = 500;
  file.camera.cx = 900;
  file.camera.cy = 240;
  const Status status = WriteCameraYaml(file, path);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("'cx': principal point cx = 900"));
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(CameraYamlTest, CommentsAreWrittenAndOpenCvReadsTheFile) {
  const std::string path = TempDir("camera_yaml_comments") + "/camera.yaml";
  CameraFile file;
  file.camera.width = 752;
  file.camera.height = 480;
  file.camera.fx = 458.654;
  file.camera.fy = 457.296;
  file.camera.cx = 367.215;
  file.camera.cy = 248.375;
  file.camera.distortion = {-0.28340811, 0.07395907, 0.00019359, 1.76187114e-05, 0};
  ASSERT_TRUE(WriteCameraYaml(file, path, {{"a header"}, {"a footer"}}).ok());
  const std::vector<std::string> lines = testing::ReadLines(path);
  ASSERT_GE(lines.size(), 4u);
  EXPECT_EQ(lines[0], "%YAML:1.0");
  EXPECT_EQ(lines[2], "# a header");
  EXPECT_EQ(lines.back(), "# a footer");
  auto read = ReadCameraYaml(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_EQ(read->camera.distortion, file.camera.distortion);
  cv::FileStorage fs(path, cv::FileStorage::READ);
  ASSERT_TRUE(fs.isOpened());
  EXPECT_EQ(static_cast<int>(fs["width"]), 752);
  EXPECT_DOUBLE_EQ(static_cast<double>(fs["fx"]), 458.654);
  EXPECT_EQ(static_cast<std::string>(fs["model"]), "pinhole");
}

// A real dataset's camera passes the checks and survives a camera.yaml round trip.
void RoundTripDatasetCamera(const std::string& dir, const std::string& name) {
  auto source = OpenDataset(dir);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  ASSERT_TRUE((*source)->info().camera.has_value());
  CameraFile file;
  file.camera = *(*source)->info().camera;
  const std::string path = TempDir("camera_yaml_" + name) + "/camera.yaml";
  ASSERT_TRUE(WriteCameraYaml(file, path).ok());
  auto read = ReadCameraYaml(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_EQ(read->camera.width, file.camera.width);
  EXPECT_EQ(read->camera.height, file.camera.height);
  EXPECT_EQ(read->camera.fx, file.camera.fx);
  EXPECT_EQ(read->camera.cy, file.camera.cy);
  EXPECT_EQ(read->camera.distortion, file.camera.distortion);
}

TEST(CameraYamlTest, TumCameraRoundTrips) {
  SIGHTLINE_REQUIRE_DATA(dir, "tum_fr1_desk");
  RoundTripDatasetCamera(dir, "tum");
}

TEST(CameraYamlTest, EurocCameraRoundTrips) {
  SIGHTLINE_REQUIRE_DATA(dir, "euroc_v1_01_static");
  RoundTripDatasetCamera(dir, "euroc");
}

TEST(CameraYamlTest, KittiCameraRoundTrips) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  RoundTripDatasetCamera(dir, "kitti");
}

TEST(CameraYamlTest, ReadsWhatTheSimulatorWrites) {
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  options.frames = 2;
  options.mono.width = 160;
  options.mono.height = 120;
  options.mono.focal_px = 131.25;
  const std::string dir = TempDir("camera_yaml_sim");
  auto summary = sim::Simulate(options, dir);
  ASSERT_TRUE(summary.ok()) << summary.status().ToString();
  auto read = ReadCameraYaml(dir + "/mono/camera.yaml");
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_EQ(read->camera.width, 160);
  EXPECT_DOUBLE_EQ(read->camera.fx, 131.25);
}

}  // namespace
}  // namespace sightline
