#include "core/io/image_folder_source.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::LinkTo;
using testing::TempDir;
using testing::WriteLines;
using testing::WriteText;

// Writes a small image whose pixels all equal `value` (grey) or (value, 0, 255 - value) (BGR).
void WriteImage(const std::string& path, int value, bool colour = false) {
  const cv::Mat image = colour ? cv::Mat(24, 32, CV_8UC3, cv::Scalar(value, 0, 255 - value))
                               : cv::Mat(24, 32, CV_8UC1, cv::Scalar(value));
  ASSERT_TRUE(cv::imwrite(path, image));
}

// Reads the first pixel of each frame.
std::vector<int> FirstPixels(ImageFolderSource* source) {
  std::vector<int> values;
  while (source->Grab().ok()) {
    auto frame = source->Retrieve();
    if (!frame.ok()) break;
    values.push_back(std::get<MonoFrame>(*frame).image.data[0]);
  }
  return values;
}

TEST(ImageFolderSourceTest, OpensKittiLeftImagesWithSynthesizedTimes) {
  SIGHTLINE_REQUIRE_DATA(data, "kitti_clip1/image_l");
  ImageFolderSource source(data, 10.0);
  ASSERT_TRUE(source.Open().ok());
  const SourceInfo& info = source.info();
  EXPECT_EQ(info.format, "image folder");
  EXPECT_EQ(info.kind, SourceKind::kMono);
  EXPECT_EQ(info.frame_count, 51);
  EXPECT_EQ(info.width, 1226);
  EXPECT_EQ(info.height, 370);
  EXPECT_FALSE(info.camera.has_value());
  EXPECT_DOUBLE_EQ(info.rate_hz, 10);
  EXPECT_NEAR(info.duration_s, 5.0, 1e-9);
  EXPECT_TRUE(std::any_of(info.notes.begin(), info.notes.end(), [](const std::string& n) {
    return n.find("synthesized at 10 Hz") != std::string::npos;
  }));
  ASSERT_TRUE(source.Seek(3).ok());
  ASSERT_TRUE(source.Grab().ok());
  auto frame = source.Retrieve();
  ASSERT_TRUE(frame.ok());
  EXPECT_EQ(std::get<MonoFrame>(*frame).image.type(), CV_8UC1);
  EXPECT_NEAR(StampOf(*frame).sensor_time_s, 0.3, 1e-12);
  EXPECT_THAT(source.files()[3], HasSubstr("000003.png"));
}

TEST(ImageFolderSourceTest, OrdersNamesNaturally) {
  const std::string dir = TempDir("images_natural");
  WriteImage(dir + "/img10.png", 10);
  WriteImage(dir + "/img2.png", 2);
  WriteImage(dir + "/img1.png", 1);
  WriteText(dir + "/notes.txt", "not an image\n");
  ImageFolderSource source(dir);
  ASSERT_TRUE(source.Open().ok());
  EXPECT_EQ(FirstPixels(&source), (std::vector<int>{1, 2, 10}));
  EXPECT_DOUBLE_EQ(source.info().rate_hz, 30);  // The default rate.
}

TEST(ImageFolderSourceTest, ReadsOneTimePerLineAndCameraYaml) {
  const std::string dir = TempDir("images_times");
  for (int i = 0; i < 3; ++i) WriteImage(dir + "/frame" + std::to_string(i) + ".png", i, true);
  WriteLines(dir + "/times.txt", {"# seconds", "100.0", "100.5", "101.25"});
  WriteText(dir + "/camera.yaml",
            "width: 32\nheight: 24\nfx: 40\nfy: 41\ncx: 15.5\ncy: 11.5\n"
            "distortion: [0.1, -0.2, 0, 0]\n");
  ImageFolderSource source(dir);
  ASSERT_TRUE(source.Open().ok()) << source.Open().ToString();
  const SourceInfo& info = source.info();
  EXPECT_EQ(info.frame_count, 3);
  EXPECT_NEAR(info.duration_s, 1.25, 1e-12);
  ASSERT_TRUE(info.camera.has_value());
  EXPECT_DOUBLE_EQ(info.camera->fy, 41);
  EXPECT_DOUBLE_EQ(info.camera->distortion[1], -0.2);
  ASSERT_TRUE(source.Seek(2).ok());
  ASSERT_TRUE(source.Grab().ok());
  auto frame = source.Retrieve();
  ASSERT_TRUE(frame.ok());
  EXPECT_DOUBLE_EQ(StampOf(*frame).sensor_time_s, 101.25);
  EXPECT_EQ(std::get<MonoFrame>(*frame).image.type(), CV_8UC3);
}

TEST(ImageFolderSourceTest, ReadsTimeAndFileNameLines) {
  const std::string dir = TempDir("images_named_times");
  WriteImage(dir + "/b.png", 20);
  WriteImage(dir + "/a.png", 10);
  WriteImage(dir + "/unlisted.png", 99);
  WriteLines(dir + "/timestamps.txt", {"5.0 b.png", "6.0 a.png"});
  ImageFolderSource source(dir);
  ASSERT_TRUE(source.Open().ok()) << source.Open().ToString();
  EXPECT_EQ(source.info().frame_count, 2);
  EXPECT_EQ(FirstPixels(&source), (std::vector<int>{20, 10}));  // The list's order.
}

TEST(ImageFolderSourceTest, TimesCountMismatchIsParseError) {
  const std::string dir = TempDir("images_bad_times");
  WriteImage(dir + "/0.png", 0);
  WriteImage(dir + "/1.png", 1);
  WriteLines(dir + "/times.txt", {"0.0"});
  const Status status = ImageFolderSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("times.txt: 1 times for 2 images"));
}

TEST(ImageFolderSourceTest, CameraYamlOfAnotherSizeIsParseError) {
  const std::string dir = TempDir("images_bad_camera");
  WriteImage(dir + "/0.png", 0);
  WriteText(dir + "/camera.yaml", "width: 640\nheight: 480\nfx: 1\nfy: 1\ncx: 1\ncy: 1\n");
  const Status status = ImageFolderSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("camera.yaml"));
  EXPECT_THAT(status.message(), HasSubstr("640x480"));
}

TEST(ImageFolderSourceTest, UndecodableImageIsParseErrorNamingTheFile) {
  const std::string dir = TempDir("images_corrupt");
  WriteText(dir + "/broken.png", "this is not a PNG");
  const Status status = ImageFolderSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_THAT(status.message(), HasSubstr("broken.png"));
}

TEST(ImageFolderSourceTest, EmptyAndMissingFoldersAreNotFound) {
  const std::string dir = TempDir("images_empty");
  Status status = ImageFolderSource(dir).Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("no images"));
  status = ImageFolderSource(dir + "/missing").Open();
  EXPECT_EQ(status.code(), StatusCode::kNotFound);
  EXPECT_THAT(status.message(), HasSubstr("missing"));
}

}  // namespace
}  // namespace sightline
