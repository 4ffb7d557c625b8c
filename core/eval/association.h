// Pairs the poses of an estimate with ground-truth poses, by timestamp or by index.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/common/trajectory.h"

namespace sightline {

// How estimated and ground-truth poses are paired.
enum class AssociationMode {
  kTimestamp,  // Nearest time within a tolerance, one-to-one (TUM benchmark's associate.py).
  kIndex,      // The i-th pose of each (KITTI poses files, which carry no timestamps).
};

// "time", "index".
const char* AssociationModeName(AssociationMode mode);
// Parses "time" or "index"; the error lists the choices.
StatusOr<AssociationMode> ParseAssociationMode(const std::string& text);

// Corresponding poses, in the estimate's order. estimate[i] and ground_truth[i] belong together.
struct AssociatedPoses {
  std::vector<TimedPose> estimate;
  std::vector<TimedPose> ground_truth;
  size_t unmatched_estimate = 0;      // Estimated poses with no ground truth within tolerance.
  size_t unmatched_ground_truth = 0;  // Ground-truth poses no estimate was paired with.

  // Number of pairs.
  size_t size() const { return estimate.size(); }
};

// Pairs each estimated pose with the ground-truth pose nearest in time if it lies within
// `tolerance_s`. Pairs are chosen greedily by increasing time difference and each pose is used at
// most once; unmatched poses are dropped and counted. Both trajectories must have
// non-decreasing times (the error names which does not). The result may be empty.
StatusOr<AssociatedPoses> AssociateByTimestamp(const Trajectory& estimate,
                                               const Trajectory& ground_truth, double tolerance_s);

// Pairs the i-th poses. Fails, giving both counts, unless the trajectories have equal length.
StatusOr<AssociatedPoses> AssociateByIndex(const Trajectory& estimate,
                                           const Trajectory& ground_truth);

}  // namespace sightline
