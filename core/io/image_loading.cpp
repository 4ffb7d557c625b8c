#include "core/io/image_loading.h"

#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/text_file.h"
#include "core/io/image_header.h"

namespace sightline {
namespace {

// imread with the reason for an empty result, after the header's declared size is checked. OpenCV
// may throw on some corrupt files.
StatusOr<cv::Mat> Decode(const std::string& path, int flags) {
  SIGHTLINE_RETURN_IF_ERROR(CheckFileExists(path));
  SIGHTLINE_RETURN_IF_ERROR(CheckImageHeaderSize(path));
  cv::Mat image;
  try {
    image = cv::imread(path, flags);
  } catch (const cv::Exception& e) {
    return ParseError(path + ": cannot decode image (" + e.what() + ")");
  }
  if (image.empty()) return ParseError(path + ": cannot decode image (corrupt or unknown format)");
  return image;
}

}  // namespace

Status CheckFileExists(const std::string& path) { return CheckRegularFile(path, path); }

std::string DescribeMatType(int type) {
  const char* depth = "?";
  switch (CV_MAT_DEPTH(type)) {
    case CV_8U:
      depth = "8-bit";
      break;
    case CV_8S:
      depth = "8-bit signed";
      break;
    case CV_16U:
      depth = "16-bit";
      break;
    case CV_16S:
      depth = "16-bit signed";
      break;
    case CV_32S:
      depth = "32-bit integer";
      break;
    case CV_32F:
      depth = "32-bit float";
      break;
    case CV_64F:
      depth = "64-bit float";
      break;
  }
  return std::string(depth) + " " + std::to_string(CV_MAT_CN(type)) + "-channel";
}

StatusOr<cv::Mat> LoadImage8(const std::string& path) {
  StatusOr<cv::Mat> image = Decode(path, cv::IMREAD_UNCHANGED);
  if (!image.ok()) return image.status();
  cv::Mat& m = *image;
  if (m.depth() != CV_8U) {
    return ParseError(path + ": expected an 8-bit image, found " + DescribeMatType(m.type()));
  }
  switch (m.channels()) {
    case 1:
    case 3:
      return std::move(m);
    case 4: {
      cv::Mat bgr;
      cv::cvtColor(m, bgr, cv::COLOR_BGRA2BGR);
      return bgr;
    }
    default:
      return ParseError(path + ": expected a grey or colour image, found " +
                        DescribeMatType(m.type()));
  }
}

StatusOr<cv::Mat> LoadColorImage(const std::string& path) {
  StatusOr<cv::Mat> image = LoadImage8(path);
  if (!image.ok()) return image.status();
  if (image->channels() == 3) return std::move(*image);
  cv::Mat bgr;
  cv::cvtColor(*image, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

StatusOr<cv::Mat> LoadDepthImage(const std::string& path, double units_per_metre) {
  if (!(units_per_metre > 0)) {
    return InvalidArgument(path + ": depth scale " + std::to_string(units_per_metre) +
                           " must be positive");
  }
  StatusOr<cv::Mat> raw = Decode(path, cv::IMREAD_UNCHANGED);
  if (!raw.ok()) return raw.status();
  if (raw->type() != CV_16UC1) {
    return ParseError(path + ": expected a 16-bit single-channel depth image, found " +
                      DescribeMatType(raw->type()));
  }
  cv::Mat depth_m;
  raw->convertTo(depth_m, CV_32F, 1.0 / units_per_metre);
  depth_m.setTo(std::numeric_limits<float>::quiet_NaN(), *raw == 0);
  return depth_m;
}

StatusOr<StereoFrame> LoadStereoPair(const std::string& left_path, const std::string& right_path) {
  auto left = LoadImage8(left_path);
  if (!left.ok()) return left.status();
  auto right = LoadImage8(right_path);
  if (!right.ok()) return right.status();
  if (left->size() != right->size() || left->type() != right->type()) {
    return ParseError(right_path + ": size or type differs from the left image " + left_path);
  }
  StereoFrame frame;
  frame.left = std::move(*left);
  frame.right = std::move(*right);
  return frame;
}

}  // namespace sightline
