// Least-squares alignment of an estimated trajectory to ground truth (Umeyama 1991): rigid SE(3),
// similarity Sim(3) for monocular estimates whose scale is unknown, or none.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// How an estimate is brought into the ground-truth frame before errors are measured.
enum class AlignmentMode {
  kNone,  // Compare as given: both must already share a world frame (e.g. both start at identity).
  kSe3,   // Best rotation and translation (stereo, RGB-D, anything with metric scale).
  kSim3,  // Best rotation, translation and scale (monocular).
};

// "none", "se3", "sim3".
const char* AlignmentModeName(AlignmentMode mode);
// Parses "none", "se3" or "sim3"; the error lists the choices.
StatusOr<AlignmentMode> ParseAlignmentMode(const std::string& text);

// x_in_ground_truth = scale * rotation * x_in_estimate + translation.
//
// `scale` is the factor that corrects the estimate: an estimate twice as large as the ground
// truth gives scale 0.5 (the convention of the TUM benchmark scripts and evo).
struct Similarity3 {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double scale = 1.0;

  // Maps a point of the estimate's world frame into the ground-truth world frame.
  Eigen::Vector3d Apply(const Eigen::Vector3d& x_in_estimate) const {
    return scale * (rotation * x_in_estimate) + translation;
  }
  // Maps a pose world_from_sensor of the estimate into the ground-truth world frame. The
  // orientation is rotated; the position is rotated, scaled and shifted (the sensor frame itself
  // keeps metric units, so relative motions come out scaled by `scale`).
  Eigen::Isometry3d Apply(const Eigen::Isometry3d& world_from_sensor) const;
};

// The Similarity3 minimising sum |gt_i - T(estimate_i)|^2 over corresponding positions.
// kNone returns the identity. kSe3 keeps scale 1. Reflections are excluded (det R = +1).
// Fails when the counts differ, when there are fewer than 3 points, or when the estimate's
// points all coincide (no rotation or scale is defined); collinear points leave the rotation
// about the line undetermined and are accepted (the result is one of the minimisers).
StatusOr<Similarity3> AlignUmeyama(const std::vector<Eigen::Vector3d>& estimate_positions,
                                   const std::vector<Eigen::Vector3d>& ground_truth_positions,
                                   AlignmentMode mode);

}  // namespace sightline
