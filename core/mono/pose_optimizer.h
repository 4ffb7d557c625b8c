// Robust camera pose from 3D-2D matches (PTAM's tracking objective, seed eq. 4.1): Gauss-Newton
// on SE(3) minimising Huber-weighted reprojection errors, in rounds that re-classify outliers.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "core/common/camera.h"

namespace sightline {

// One match of a map point with a keypoint.
struct PoseObservation {
  Eigen::Vector3d x_in_map = Eigen::Vector3d::Zero();
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  // Undistorted keypoint [px].
  double level_scale = 1;                           // Keypoint's pyramid scale (px sigma).
};

// What the optimisation found.
struct PoseEstimate {
  Eigen::Isometry3d camera_from_map = Eigen::Isometry3d::Identity();
  std::vector<bool> inliers;  // Per observation.
  int inlier_count = 0;
  double rms_px = 0;  // Over the inliers.
};

// Refines `initial` over `observations`. Residuals are divided by each level_scale; weights
// follow Huber with threshold huber_px; observations beyond outlier_px after a round are left
// out of the next (and may come back). Never fails: with too few points the pose stays put and
// inlier_count says so.
PoseEstimate OptimizePose(const PinholeCamera& camera, const Eigen::Isometry3d& initial,
                          const std::vector<PoseObservation>& observations, double huber_px,
                          double outlier_px, int rounds = 4, int iterations = 10);

}  // namespace sightline
