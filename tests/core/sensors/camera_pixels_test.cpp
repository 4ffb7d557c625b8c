#include "core/sensors/camera_pixels.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace sightline {
namespace {

// An 8-bit Bayer mosaic lit only at even rows and columns: the R sites of an RGGB sensor, the
// B sites of a BGGR sensor.
std::vector<uint8_t> Mosaic(int w, int h, uint8_t value) {
  std::vector<uint8_t> m(static_cast<size_t>(w) * h, 0);
  for (int y = 0; y < h; y += 2) {
    for (int x = 0; x < w; x += 2) m[y * w + x] = value;
  }
  return m;
}

TEST(CameraPixels, Mono8IsCopied) {
  std::vector<uint8_t> data = {1, 2, 3, 4, 5, 6};
  StatusOr<cv::Mat> image = ConvertCameraImage(pfnc::kMono8, 3, 2, data.data(), data.size(), true);
  ASSERT_TRUE(image.ok()) << image.status().ToString();
  EXPECT_EQ(image->type(), CV_8UC1);
  EXPECT_EQ(image->cols, 3);
  EXPECT_EQ(image->at<uint8_t>(1, 2), 6);
  data[5] = 99;
  EXPECT_EQ(image->at<uint8_t>(1, 2), 6) << "the image must own its pixels";
}

TEST(CameraPixels, SixteenBitFormatsAreScaledToEightBits) {
  std::vector<uint16_t> mono16 = {0, 0x8000, 0xFFFF, 0x1000};
  StatusOr<cv::Mat> a = ConvertCameraImage(pfnc::kMono16, 2, 2, mono16.data(), 8, true);
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(a->type(), CV_8UC1);
  EXPECT_EQ(a->at<uint8_t>(0, 1), 128);
  EXPECT_EQ(a->at<uint8_t>(1, 0), 255);
  EXPECT_EQ(a->at<uint8_t>(1, 1), 16);
  std::vector<uint16_t> mono12 = {4095, 2048};
  StatusOr<cv::Mat> b = ConvertCameraImage(pfnc::kMono12, 2, 1, mono12.data(), 4, true);
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(b->at<uint8_t>(0, 0), 255);
  EXPECT_EQ(b->at<uint8_t>(0, 1), 128);
}

TEST(CameraPixels, BayerRgDemosaicsARedSceneToRed) {
  const int w = 8, h = 8;
  std::vector<uint8_t> m = Mosaic(w, h, 200);  // RGGB with only red lit.
  StatusOr<cv::Mat> image = ConvertCameraImage(pfnc::kBayerRG8, w, h, m.data(), m.size(), true);
  ASSERT_TRUE(image.ok());
  ASSERT_EQ(image->type(), CV_8UC3);
  const cv::Vec3b centre = image->at<cv::Vec3b>(4, 4);  // BGR.
  EXPECT_EQ(centre[0], 0);
  EXPECT_EQ(centre[1], 0);
  EXPECT_GT(centre[2], 150);
}

TEST(CameraPixels, BayerBgDemosaicsABlueSceneToBlue) {
  const int w = 8, h = 8;
  std::vector<uint8_t> m = Mosaic(w, h, 200);  // BGGR with only blue lit.
  StatusOr<cv::Mat> image = ConvertCameraImage(pfnc::kBayerBG8, w, h, m.data(), m.size(), true);
  ASSERT_TRUE(image.ok());
  const cv::Vec3b centre = image->at<cv::Vec3b>(4, 4);
  EXPECT_GT(centre[0], 150);
  EXPECT_EQ(centre[1], 0);
  EXPECT_EQ(centre[2], 0);
}

TEST(CameraPixels, BayerWithoutDebayerStaysRawMosaic) {
  std::vector<uint8_t> m = Mosaic(4, 4, 7);
  StatusOr<cv::Mat> image = ConvertCameraImage(pfnc::kBayerGR8, 4, 4, m.data(), m.size(), false);
  ASSERT_TRUE(image.ok());
  EXPECT_EQ(image->type(), CV_8UC1);
  EXPECT_EQ(image->at<uint8_t>(0, 0), 7);
}

TEST(CameraPixels, Rgb8BecomesBgr) {
  std::vector<uint8_t> rgb = {10, 20, 30};
  StatusOr<cv::Mat> image = ConvertCameraImage(pfnc::kRgb8, 1, 1, rgb.data(), 3, true);
  ASSERT_TRUE(image.ok());
  EXPECT_EQ(image->at<cv::Vec3b>(0, 0), cv::Vec3b(30, 20, 10));
}

TEST(CameraPixels, HonoursRowStride) {
  std::vector<uint8_t> data = {1, 2, 0, 0, 3, 4, 0, 0};  // 2x2 with 2 bytes padding per row.
  StatusOr<cv::Mat> image =
      ConvertCameraImage(pfnc::kMono8, 2, 2, data.data(), data.size(), true, 4);
  ASSERT_TRUE(image.ok());
  EXPECT_EQ(image->at<uint8_t>(1, 0), 3);
  EXPECT_EQ(image->at<uint8_t>(1, 1), 4);
}

TEST(CameraPixels, ShortBufferAndUnknownFormatAreClearErrors) {
  std::vector<uint8_t> data(10);
  StatusOr<cv::Mat> short_buffer =
      ConvertCameraImage(pfnc::kMono8, 4, 4, data.data(), data.size(), true);
  ASSERT_FALSE(short_buffer.ok());
  EXPECT_NE(short_buffer.status().message().find("needs 16 bytes, buffer holds 10"),
            std::string::npos)
      << short_buffer.status().message();
  StatusOr<cv::Mat> unknown = ConvertCameraImage(0x010c0006u, 2, 2, data.data(), 10, true);
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.status().message().find("0x010c0006"), std::string::npos);
  EXPECT_EQ(PixelFormatName(pfnc::kBayerRG8), "BayerRG8");
}

}  // namespace
}  // namespace sightline
