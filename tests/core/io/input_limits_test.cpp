// The readers' limits (core/common/input_limits.h): an input one above each limit is refused
// before it is read whole, with an error naming the file, the field and the limit. Files of the
// size limits are sparse, so the tests write almost nothing.
#include "core/common/input_limits.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "core/common/trajectory.h"
#include "core/io/camera_yaml.h"
#include "core/io/floor_file.h"
#include "core/io/hand_eye_file.h"
#include "core/io/stereo_calibration_file.h"
#include "core/io/timed_file_list.h"
#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using testing::WriteText;

std::string CameraYaml(int width, int height) {
  return "width: " + std::to_string(width) + "\nheight: " + std::to_string(height) +
         "\nfx: 500\nfy: 500\ncx: 16\ncy: 12\n";
}

// A valid `text` followed by a comment line up to `size` bytes in all. Files above 2 MB are
// sparse (zero bytes after the '#', never written): only their size is looked at.
std::string PaddedFile(const std::string& path, const std::string& text, size_t size) {
  if (size > (size_t{2} << 20)) {
    WriteText(path, text + "#");
    std::filesystem::resize_file(path, size);
  } else {
    WriteText(path, text + "#" + std::string(size - text.size() - 2, 'x') + "\n");
  }
  EXPECT_EQ(std::filesystem::file_size(path), size);
  return path;
}

TEST(InputLimits, CameraYamlSidesAboveTheLimitNameTheField) {
  const std::string dir = TempDir("limits_camera");
  WriteText(dir + "/at.yaml", CameraYaml(kMaxImageSidePx, kMaxImageSidePx));
  EXPECT_TRUE(ReadCameraYaml(dir + "/at.yaml").ok());

  WriteText(dir + "/wide.yaml", CameraYaml(kMaxImageSidePx + 1, 24));
  StatusOr<CameraFile> wide = ReadCameraYaml(dir + "/wide.yaml");
  ASSERT_FALSE(wide.ok());
  EXPECT_THAT(wide.status().message(), HasSubstr("'width'"));
  EXPECT_THAT(wide.status().message(), HasSubstr("32769"));
  EXPECT_THAT(wide.status().message(), HasSubstr("limit of 32768 px"));

  WriteText(dir + "/tall.yaml", CameraYaml(32, kMaxImageSidePx + 1));
  StatusOr<CameraFile> tall = ReadCameraYaml(dir + "/tall.yaml");
  ASSERT_FALSE(tall.ok());
  EXPECT_THAT(tall.status().message(), HasSubstr("'height'"));
}

TEST(InputLimits, StereoCalibrationImageWidthAboveTheLimitNamesTheField) {
  const std::string dir = TempDir("limits_stereo");
  const std::string k = "[500, 0, 16, 0, 500, 12, 0, 0, 1]";
  WriteText(dir + "/rig.yml", "image_width: " + std::to_string(kMaxImageSidePx + 1) +
                                  "\nimage_height: 24\nM1: " + k + "\nD1: [0, 0, 0, 0]\nM2: " + k +
                                  "\nD2: [0, 0, 0, 0]\nR: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n"
                                  "T: [-0.1, 0, 0]\n");
  StatusOr<StereoRig> rig = ReadStereoCalibration(dir + "/rig.yml");
  ASSERT_FALSE(rig.ok());
  EXPECT_THAT(rig.status().message(), HasSubstr("image_width"));
  EXPECT_THAT(rig.status().message(), HasSubstr("limit of 32768 px"));
}

TEST(InputLimits, CalibrationFilesAboveTheSizeLimitAreNotRead) {
  const std::string dir = TempDir("limits_yaml");
  const size_t over = kMaxCalibrationFileBytes + 1;
  const std::string at = PaddedFile(dir + "/at.yaml", CameraYaml(32, 24), over - 1);
  EXPECT_TRUE(ReadCameraYaml(at).ok()) << ReadCameraYaml(at).status().message();

  const std::string camera = PaddedFile(dir + "/camera.yaml", CameraYaml(32, 24), over);
  const std::string floor = PaddedFile(dir + "/floor.yaml", "a: 0\nb: -1\nc: 0\nd: 1\n", over);
  const std::string hand_eye = PaddedFile(
      dir + "/hand_eye.yaml",
      "end_effector_from_camera:\n  translation: [0, 0, 0]\n  quaternion_xyzw: [0, 0, 0, 1]\n",
      over);
  const std::string stereo = PaddedFile(dir + "/stereo.yml", "image_width: 32\n", over);
  const std::vector<Status> statuses = {
      ReadCameraYaml(camera).status(), ReadFloorCalibration(floor).status(),
      ReadHandEyeFile(hand_eye).status(), ReadStereoCalibration(stereo).status()};
  const std::vector<std::string> paths = {camera, floor, hand_eye, stereo};
  for (size_t i = 0; i < statuses.size(); ++i) {
    EXPECT_EQ(statuses[i].code(), StatusCode::kInvalidArgument) << paths[i];
    EXPECT_THAT(statuses[i].message(), HasSubstr(paths[i] + " is 1048577 bytes"));
    EXPECT_THAT(statuses[i].message(), HasSubstr("at most 1048576 bytes"));
  }
}

TEST(InputLimits, IndexFilesAboveTheSizeLimitAreNotRead) {
  const std::string dir = TempDir("limits_index");
  const size_t over = kMaxIndexFileBytes + 1;
  const std::string list = PaddedFile(dir + "/rgb.txt", "1.0 rgb/a.png\n", over);
  const std::string truth = PaddedFile(dir + "/groundtruth.txt", "1.0 0 0 0 0 0 0 1\n", over);
  const std::string times = PaddedFile(dir + "/times.txt", "0.0\n", over);
  const std::vector<Status> statuses = {ReadTimedFileList(list).status(),
                                        ReadTumTrajectory(truth).status(),
                                        ReadTimesFile(times).status()};
  const std::vector<std::string> paths = {list, truth, times};
  for (size_t i = 0; i < statuses.size(); ++i) {
    EXPECT_EQ(statuses[i].code(), StatusCode::kInvalidArgument) << paths[i];
    EXPECT_THAT(statuses[i].message(), HasSubstr(paths[i] + " is 268435457 bytes"));
    EXPECT_THAT(statuses[i].message(), HasSubstr("at most 268435456 bytes"));
  }
}

}  // namespace
}  // namespace sightline
