#include "widgets/color_map.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace sightline {
namespace {

std::array<Rgb8, 256> BuildTurbo() {
  cv::Mat ramp(1, 256, CV_8UC1);
  for (int i = 0; i < 256; ++i) ramp.at<uint8_t>(0, i) = static_cast<uint8_t>(i);
  cv::Mat bgr;
  cv::applyColorMap(ramp, bgr, cv::COLORMAP_TURBO);
  std::array<Rgb8, 256> table;
  for (int i = 0; i < 256; ++i) {
    const cv::Vec3b c = bgr.at<cv::Vec3b>(0, i);
    table[i] = Rgb8{c[2], c[1], c[0]};
  }
  return table;
}

}  // namespace

const std::array<Rgb8, 256>& TurboColorMap() {
  static const std::array<Rgb8, 256> table = BuildTurbo();  // Immutable after first use.
  return table;
}

Rgb8 TurboColor(double value, double low, double high) {
  const double span = high - low;
  double t = span > 0 ? (value - low) / span : 0.5;
  t = std::clamp(t, 0.0, 1.0);
  return TurboColorMap()[static_cast<size_t>(std::lround(t * 255.0))];
}

}  // namespace sightline
