// The rectified stereo camera the odometry works in: one focal length, one principal point and
// a baseline along x. Triangulation and projection into both images.
#pragma once

#include <Eigen/Core>

#include "core/common/camera.h"
#include "core/common/status.h"

namespace sightline {

// A rectified pair: both images share fx = fy = f and (cx, cy); the right camera sits
// baseline_m along the left camera's +x axis, so a point at depth Z has disparity f b / Z.
struct RectifiedStereoCamera {
  double f = 0;               // Focal length [px].
  double cx = 0, cy = 0;      // Principal point [px].
  double baseline_m = 0;      // Distance between optical centres [m], > 0.
  int width = 0, height = 0;  // Image size [px].

  // From a rectified rig: checks that the right camera sits to the right of the left one
  // (right_from_left.x < 0, as KITTI's P1 says) and that rows are aligned.
  static StatusOr<RectifiedStereoCamera> FromRig(const StereoRig& rig);

  // The point in the left camera frame seen at left pixel (u, v) with disparity d > 0 [px].
  Eigen::Vector3d Triangulate(double u, double v, double disparity_px) const {
    const double z = f * baseline_m / disparity_px;
    return {(u - cx) * z / f, (v - cy) * z / f, z};
  }
  // Left pixel of a point in the left camera frame (z > 0 required by the caller).
  Eigen::Vector2d ProjectLeft(const Eigen::Vector3d& x) const {
    return {f * x.x() / x.z() + cx, f * x.y() / x.z() + cy};
  }
  // Right pixel of a point in the left camera frame.
  Eigen::Vector2d ProjectRight(const Eigen::Vector3d& x) const {
    return {f * (x.x() - baseline_m) / x.z() + cx, f * x.y() / x.z() + cy};
  }
  // Standard deviation of the depth of a point at depth z for disparity noise sigma_d [m].
  double DepthSigma(double z, double disparity_sigma_px) const {
    return z * z * disparity_sigma_px / (f * baseline_m);
  }
};

}  // namespace sightline
