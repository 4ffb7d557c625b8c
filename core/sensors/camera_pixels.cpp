#include "core/sensors/camera_pixels.h"

#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace sightline {
namespace {

struct FormatDesc {
  uint32_t code;
  const char* name;
  int bytes_per_pixel;
  int significant_bits;  // For 16-bit containers.
  int bayer_code;        // cv::COLOR_Bayer..2BGR, or -1.
};

// OpenCV names Bayer patterns by the second row, GenICam by the first: GenICam RG = OpenCV BG.
const FormatDesc kFormats[] = {
    {pfnc::kMono8, "Mono8", 1, 8, -1},
    {pfnc::kMono10, "Mono10", 2, 10, -1},
    {pfnc::kMono12, "Mono12", 2, 12, -1},
    {pfnc::kMono14, "Mono14", 2, 14, -1},
    {pfnc::kMono16, "Mono16", 2, 16, -1},
    {pfnc::kBayerGR8, "BayerGR8", 1, 8, cv::COLOR_BayerGB2BGR},
    {pfnc::kBayerRG8, "BayerRG8", 1, 8, cv::COLOR_BayerBG2BGR},
    {pfnc::kBayerGB8, "BayerGB8", 1, 8, cv::COLOR_BayerGR2BGR},
    {pfnc::kBayerBG8, "BayerBG8", 1, 8, cv::COLOR_BayerRG2BGR},
    {pfnc::kBayerGR16, "BayerGR16", 2, 16, cv::COLOR_BayerGB2BGR},
    {pfnc::kBayerRG16, "BayerRG16", 2, 16, cv::COLOR_BayerBG2BGR},
    {pfnc::kBayerGB16, "BayerGB16", 2, 16, cv::COLOR_BayerGR2BGR},
    {pfnc::kBayerBG16, "BayerBG16", 2, 16, cv::COLOR_BayerRG2BGR},
    {pfnc::kRgb8, "RGB8", 3, 8, -1},
    {pfnc::kBgr8, "BGR8", 3, 8, -1},
};

const FormatDesc* Find(uint32_t code) {
  for (const FormatDesc& f : kFormats) {
    if (f.code == code) return &f;
  }
  return nullptr;
}

}  // namespace

std::string PixelFormatName(uint32_t pixel_format) {
  if (const FormatDesc* f = Find(pixel_format)) return f->name;
  char hex[16];
  std::snprintf(hex, sizeof(hex), "0x%08x", pixel_format);
  return hex;
}

StatusOr<cv::Mat> ConvertCameraImage(uint32_t pixel_format, int width, int height, const void* data,
                                     size_t size, bool debayer, size_t stride) {
  const FormatDesc* f = Find(pixel_format);
  if (f == nullptr) {
    return InvalidArgument("pixel format " + PixelFormatName(pixel_format) +
                           " is not supported (use Mono8/10/12/14/16, Bayer 8/16, RGB8 or BGR8)");
  }
  if (width <= 0 || height <= 0 || data == nullptr) {
    return InvalidArgument(std::string(f->name) + " image has no pixels (" + std::to_string(width) +
                           "x" + std::to_string(height) + ")");
  }
  const size_t row_bytes = static_cast<size_t>(width) * f->bytes_per_pixel;
  if (stride == 0) stride = row_bytes;
  if (stride < row_bytes || size < stride * (height - 1) + row_bytes) {
    return InvalidArgument(std::string(f->name) + " " + std::to_string(width) + "x" +
                           std::to_string(height) + " image needs " +
                           std::to_string(stride * height) + " bytes, buffer holds " +
                           std::to_string(size));
  }
  void* pixels = const_cast<void*>(data);  // Wrapped read-only; every path below copies.
  cv::Mat out;
  if (f->bytes_per_pixel == 3) {
    cv::Mat in(height, width, CV_8UC3, pixels, stride);
    if (f->code == pfnc::kRgb8) {
      cv::cvtColor(in, out, cv::COLOR_RGB2BGR);
    } else {
      out = in.clone();
    }
    return out;
  }
  cv::Mat mono8;
  if (f->bytes_per_pixel == 2) {
    cv::Mat in(height, width, CV_16UC1, pixels, stride);
    in.convertTo(mono8, CV_8U, 1.0 / static_cast<double>(1 << (f->significant_bits - 8)));
  } else {
    mono8 = cv::Mat(height, width, CV_8UC1, pixels, stride).clone();
  }
  if (f->bayer_code >= 0 && debayer) {
    cv::cvtColor(mono8, out, f->bayer_code);
    return out;
  }
  return mono8;
}

}  // namespace sightline
