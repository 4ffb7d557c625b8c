#include "core/sensors/depth_conversion.h"

#include <cmath>
#include <limits>

namespace sightline {

cv::Mat RawDepthToMetres(const cv::Mat& raw, double units_per_metre) {
  CV_Assert(raw.type() == CV_16UC1 && units_per_metre > 0);
  cv::Mat metres(raw.size(), CV_32FC1);
  const float scale = static_cast<float>(1.0 / units_per_metre);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int r = 0; r < raw.rows; ++r) {
    const uint16_t* in = raw.ptr<uint16_t>(r);
    float* out = metres.ptr<float>(r);
    for (int c = 0; c < raw.cols; ++c) out[c] = in[c] == 0 ? nan : in[c] * scale;
  }
  return metres;
}

PinholeCamera PinholeFromFov(int width, int height, double hfov_rad, double vfov_rad) {
  PinholeCamera camera;
  camera.width = width;
  camera.height = height;
  camera.fx = width / (2.0 * std::tan(hfov_rad / 2.0));
  camera.fy = height / (2.0 * std::tan(vfov_rad / 2.0));
  camera.cx = width / 2.0;
  camera.cy = height / 2.0;
  return camera;
}

}  // namespace sightline
