// Displacement pairs for the scale estimators: the camera's displacement in the map and the
// same displacement measured in metres (arm forward kinematics with the hand-eye transform, a
// robot's odometry or ground truth) over the same frame intervals, both expressed in the camera
// frame at the start of the interval, so the two need no common world frame.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/mono/scale_estimator.h"

namespace sightline {

// One frame with both poses (either may be missing).
struct DualPose {
  int64_t frame = -1;                                   // Source sequence id.
  std::optional<Eigen::Isometry3d> map_from_camera;     // SLAM estimate [map units].
  std::optional<Eigen::Isometry3d> metric_from_camera;  // Measured [m], any fixed world frame.
};

// Pairs over consecutive intervals of `interval_frames` frames (frame i to i + interval), for
// every interval whose two ends have both poses. `frames` must be sorted by frame.
std::vector<ScalePair> DisplacementPairs(const std::vector<DualPose>& frames, int interval_frames);

}  // namespace sightline
