#include "core/common/camera.h"

#include <cmath>

namespace sightline {

bool PinholeCamera::HasDistortion() const {
  for (double d : distortion) {
    if (d != 0) return true;
  }
  return false;
}

Status PinholeCamera::Validate() const {
  if (width <= 0 || height <= 0) {
    return InvalidArgument("camera size " + std::to_string(width) + "x" + std::to_string(height) +
                           " must be positive");
  }
  if (!(fx > 0) || !(fy > 0) || !std::isfinite(fx) || !std::isfinite(fy)) {
    return InvalidArgument("camera focal length fx=" + std::to_string(fx) +
                           " fy=" + std::to_string(fy) + " must be positive and finite");
  }
  if (!std::isfinite(cx) || !std::isfinite(cy)) {
    return InvalidArgument("camera principal point is not finite");
  }
  for (double d : distortion) {
    if (!std::isfinite(d)) return InvalidArgument("camera distortion coefficient is not finite");
  }
  return Status::Ok();
}

Eigen::Matrix3d PinholeCamera::K() const {
  Eigen::Matrix3d k;
  k << fx, 0, cx, 0, fy, cy, 0, 0, 1;
  return k;
}

Eigen::Vector2d PinholeCamera::Project(const Eigen::Vector3d& x) const {
  return {fx * x.x() / x.z() + cx, fy * x.y() / x.z() + cy};
}

Eigen::Vector3d PinholeCamera::Unproject(double u, double v, double depth_m) const {
  return {(u - cx) / fx * depth_m, (v - cy) / fy * depth_m, depth_m};
}

PinholeCamera PinholeCamera::Scaled(int new_width, int new_height) const {
  PinholeCamera c = *this;
  const double sx = static_cast<double>(new_width) / width;
  const double sy = static_cast<double>(new_height) / height;
  c.width = new_width;
  c.height = new_height;
  c.fx *= sx;
  c.fy *= sy;
  // Pixel centres: (u + 0.5) * s - 0.5.
  c.cx = (cx + 0.5) * sx - 0.5;
  c.cy = (cy + 0.5) * sy - 0.5;
  return c;
}

Status StereoRig::Validate() const {
  SIGHTLINE_RETURN_IF_ERROR(left.Validate().WithContext("left camera"));
  SIGHTLINE_RETURN_IF_ERROR(right.Validate().WithContext("right camera"));
  if (!(BaselineM() > 1e-4) || !std::isfinite(BaselineM())) {
    return InvalidArgument("stereo baseline " + std::to_string(BaselineM()) +
                           " m must be positive and finite");
  }
  return Status::Ok();
}

}  // namespace sightline
