// Image headers are read before decoding: every loader refuses a file whose header declares
// more than kMaxImagePixels or kMaxImageSidePx (core/common/input_limits.h) without allocating
// it, and a truncated header is named as such.
#include "core/io/image_header.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "core/common/input_limits.h"
#include "core/io/image_loading.h"
#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;

std::vector<unsigned char> ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void WriteBytes(const std::string& path, const std::vector<unsigned char>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}
void PutBigEndian(std::vector<unsigned char>* bytes, size_t at, uint32_t value, int width) {
  for (int i = 0; i < width; ++i) (*bytes)[at + i] = (value >> (8 * (width - 1 - i))) & 0xFF;
}
// Offset of the JPEG frame header's height (after FFC0/FFC2 marker, length and precision).
size_t JpegFrameHeightOffset(const std::vector<unsigned char>& bytes) {
  for (size_t i = 2; i + 8 < bytes.size(); ++i) {
    if (bytes[i] == 0xFF && (bytes[i + 1] == 0xC0 || bytes[i + 1] == 0xC2)) return i + 5;
  }
  return 0;
}

TEST(ImageHeader, ReadsTheDeclaredSizeOfEachKnownFormat) {
  const std::string dir = TempDir("image_header_formats");
  const cv::Mat image(37, 53, CV_8UC3, cv::Scalar(10, 20, 30));
  for (const char* ext : {".png", ".jpg", ".ppm", ".bmp"}) {
    const std::string path = dir + "/image" + ext;
    ASSERT_TRUE(cv::imwrite(path, image)) << ext;
    StatusOr<std::optional<cv::Size>> size = ReadImageHeaderSize(path);
    ASSERT_TRUE(size.ok()) << ext << ": " << size.status().message();
    ASSERT_TRUE(size->has_value()) << ext;
    EXPECT_EQ(**size, cv::Size(53, 37)) << ext;
    EXPECT_TRUE(LoadColorImage(path).ok()) << ext;
  }
  const std::string grey = dir + "/grey.pgm";
  ASSERT_TRUE(cv::imwrite(grey, cv::Mat(5, 7, CV_8UC1, cv::Scalar(1))));
  EXPECT_EQ(**ReadImageHeaderSize(grey), cv::Size(7, 5));
}

TEST(ImageHeader, APngDeclaringMoreThanTheLimitIsRefusedBeforeDecoding) {
  const std::string dir = TempDir("image_header_png");
  const std::string small = dir + "/small.png";
  ASSERT_TRUE(cv::imwrite(small, cv::Mat(10, 10, CV_8UC1, cv::Scalar(0))));
  std::vector<unsigned char> bytes = ReadBytes(small);
  // 10001 x 10001 = 100,020,001 pixels: one row and column above 100 megapixels.
  PutBigEndian(&bytes, 16, 10001, 4);
  PutBigEndian(&bytes, 20, 10001, 4);
  WriteBytes(dir + "/huge.png", bytes);
  StatusOr<cv::Mat> huge = LoadColorImage(dir + "/huge.png");
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.status().code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(huge.status().message(), HasSubstr("huge.png"));
  EXPECT_THAT(huge.status().message(), HasSubstr("10001 x 10001"));
  EXPECT_THAT(huge.status().message(), HasSubstr("100000000"));

  // At the cap the header passes; the forged file then fails in the decoder (bad CRC).
  PutBigEndian(&bytes, 16, 10000, 4);
  PutBigEndian(&bytes, 20, 10000, 4);
  WriteBytes(dir + "/at_cap.png", bytes);
  EXPECT_TRUE(CheckImageHeaderSize(dir + "/at_cap.png").ok());
  StatusOr<cv::Mat> at_cap = LoadImage8(dir + "/at_cap.png");
  ASSERT_FALSE(at_cap.ok());
  EXPECT_THAT(at_cap.status().message(), HasSubstr("cannot decode"));

  // One side above kMaxImageSidePx, few pixels in all.
  PutBigEndian(&bytes, 16, kMaxImageSidePx + 1, 4);
  PutBigEndian(&bytes, 20, 1, 4);
  WriteBytes(dir + "/wide.png", bytes);
  StatusOr<cv::Mat> wide = LoadImage8(dir + "/wide.png");
  ASSERT_FALSE(wide.ok());
  EXPECT_THAT(wide.status().message(), HasSubstr("32769 x 1"));
}

TEST(ImageHeader, AJpegFrameHeaderAboveTheLimitIsRefused) {
  const std::string dir = TempDir("image_header_jpeg");
  const std::string small = dir + "/small.jpg";
  ASSERT_TRUE(cv::imwrite(small, cv::Mat(16, 16, CV_8UC3, cv::Scalar(5, 6, 7))));
  std::vector<unsigned char> bytes = ReadBytes(small);
  const size_t at = JpegFrameHeightOffset(bytes);
  ASSERT_GT(at, 0u);
  PutBigEndian(&bytes, at, 30000, 2);      // Height.
  PutBigEndian(&bytes, at + 2, 30000, 2);  // Width: 900 megapixels.
  WriteBytes(dir + "/huge.jpg", bytes);
  StatusOr<cv::Mat> huge = LoadColorImage(dir + "/huge.jpg");
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.status().code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(huge.status().message(), HasSubstr("30000 x 30000"));
}

TEST(ImageHeader, TruncatedOrZeroSizedHeadersAreNamed) {
  const std::string dir = TempDir("image_header_truncated");
  const std::string small = dir + "/small.png";
  ASSERT_TRUE(cv::imwrite(small, cv::Mat(4, 4, CV_8UC1, cv::Scalar(0))));
  std::vector<unsigned char> bytes = ReadBytes(small);
  WriteBytes(dir + "/cut.png", std::vector<unsigned char>(bytes.begin(), bytes.begin() + 12));
  StatusOr<cv::Mat> cut = LoadImage8(dir + "/cut.png");
  ASSERT_FALSE(cut.ok());
  EXPECT_EQ(cut.status().code(), StatusCode::kParseError);
  EXPECT_THAT(cut.status().message(), HasSubstr("truncated PNG header"));

  PutBigEndian(&bytes, 16, 0, 4);
  WriteBytes(dir + "/zero.png", bytes);
  StatusOr<cv::Mat> zero = LoadImage8(dir + "/zero.png");
  ASSERT_FALSE(zero.ok());
  EXPECT_THAT(zero.status().message(), HasSubstr("declares a size of 0 x 4"));

  WriteBytes(dir + "/cut.jpg", {0xFF, 0xD8, 0xFF, 0xE0, 0x00});
  StatusOr<cv::Mat> cut_jpeg = LoadImage8(dir + "/cut.jpg");
  ASSERT_FALSE(cut_jpeg.ok());
  EXPECT_THAT(cut_jpeg.status().message(), HasSubstr("truncated JPEG header"));

  testing::WriteText(dir + "/huge.pgm", "P5\n# a comment\n40000 40000\n255\n");
  StatusOr<cv::Mat> pgm = LoadImage8(dir + "/huge.pgm");
  ASSERT_FALSE(pgm.ok());
  EXPECT_THAT(pgm.status().message(), HasSubstr("40000 x 40000"));
}

}  // namespace
}  // namespace sightline
