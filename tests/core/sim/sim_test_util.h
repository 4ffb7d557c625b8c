// Helpers shared by the simulator tests: cameras and poses.
#pragma once

#include <Eigen/Geometry>
#include <cmath>

#include "core/common/camera.h"

namespace sightline::sim::testing {

// A distortion-free pinhole camera with the principal point at the image centre.
inline PinholeCamera MakeCamera(int width, int height, double focal) {
  PinholeCamera c;
  c.width = width;
  c.height = height;
  c.fx = c.fy = focal;
  c.cx = 0.5 * (width - 1);
  c.cy = 0.5 * (height - 1);
  return c;
}

// A camera (optical frame) at `position` looking horizontally along the map direction `yaw`
// (0 = +x), z up in the image.
inline Eigen::Isometry3d LookHorizontally(const Eigen::Vector3d& position, double yaw_rad) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d forward(std::cos(yaw_rad), std::sin(yaw_rad), 0);
  pose.linear().col(2) = forward;
  pose.linear().col(0) = forward.cross(Eigen::Vector3d::UnitZ());
  pose.linear().col(1) = pose.linear().col(2).cross(pose.linear().col(0));
  pose.translation() = position;
  return pose;
}

}  // namespace sightline::sim::testing
