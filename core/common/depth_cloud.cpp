#include "core/common/depth_cloud.h"

#include <cmath>
#include <limits>

namespace sightline {

PointCloud DepthToCloud(const cv::Mat& depth_m, const cv::Mat& color_bgr,
                        const PinholeCamera& camera, int stride) {
  PointCloud cloud;
  if (depth_m.empty() || depth_m.type() != CV_32FC1 || stride < 1) return cloud;
  // The camera may be calibrated for another resolution than the depth image.
  const PinholeCamera cam = (camera.width == depth_m.cols && camera.height == depth_m.rows)
                                ? camera
                                : camera.Scaled(depth_m.cols, depth_m.rows);
  const bool with_color =
      !color_bgr.empty() && color_bgr.type() == CV_8UC3 && color_bgr.size() == depth_m.size();
  cloud.width = (depth_m.cols + stride - 1) / stride;
  cloud.height = (depth_m.rows + stride - 1) / stride;
  cloud.points.reserve(static_cast<size_t>(cloud.width) * cloud.height);
  if (with_color) cloud.colors.reserve(cloud.points.capacity());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inv_fx = static_cast<float>(1.0 / cam.fx), inv_fy = static_cast<float>(1.0 / cam.fy);
  const float cx = static_cast<float>(cam.cx), cy = static_cast<float>(cam.cy);
  for (int v = 0; v < depth_m.rows; v += stride) {
    const float* depth_row = depth_m.ptr<float>(v);
    const cv::Vec3b* color_row = with_color ? color_bgr.ptr<cv::Vec3b>(v) : nullptr;
    for (int u = 0; u < depth_m.cols; u += stride) {
      const float z = depth_row[u];
      if (std::isfinite(z) && z > 0) {
        cloud.points.emplace_back((u - cx) * z * inv_fx, (v - cy) * z * inv_fy, z);
      } else {
        cloud.points.emplace_back(nan, nan, nan);
      }
      if (with_color) {
        const cv::Vec3b& c = color_row[u];
        cloud.colors.emplace_back(c[2], c[1], c[0]);
      }
    }
  }
  return cloud;
}

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

}  // namespace sightline
