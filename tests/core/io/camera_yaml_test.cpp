#include "core/io/camera_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace sightline
