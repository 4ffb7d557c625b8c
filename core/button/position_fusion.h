// Fusion of the button positions located frame by frame during one approach (the button and the
// arm's base stay put, so they estimate one point). Each estimate is kept in the camera frame in
// the SLAM map's units with the camera's measured pose, so that every new metric scale places
// all of them again (an early frame located with an early scale no longer carries that scale's
// error), and weighs by its own variance: the error of a plane fit, of the tracked centre and of
// the scale grows with the distance, so the near frames of the approach count most.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

namespace sightline {

// One located position.
struct FusedEstimate {
  Eigen::Vector3d in_camera_map = Eigen::Vector3d::Zero();  // Camera frame, map units.
  double lambda = 1;  // Map units per metre when it was located.
  Eigen::Isometry3d base_from_camera = Eigen::Isometry3d::Identity();
  double sigma_m = 0;  // Its own 1-sigma (plane fit, tracking) [m]; 0 = unknown.
};

// The fused position and its spread.
struct FusedPosition {
  Eigen::Vector3d in_base = Eigen::Vector3d::Constant(std::nan(""));
  double spread_m = 0;  // 1.4826 x the weighted median distance of the estimates from it.
  int estimates = 0;
  bool weighted = false;  // The estimates were weighed by their own variance.
};

// The last `window` estimates (0 = all) placed in the base frame with the scale `lambda` (map
// units per metre; 0 = each with its own), fused by the per-axis weighted median with weights
// 1 / sigma^2 when `weighted` or when one of them states a sigma of at most `weigh_below_m`
// (> 0); else all count the same.
FusedPosition FusePositions(const std::vector<FusedEstimate>& estimates, int window, double lambda,
                            bool weighted, double weigh_below_m = 0);

}  // namespace sightline
