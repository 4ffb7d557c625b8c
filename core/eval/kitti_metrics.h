// KITTI odometry segment errors (Geiger et al. 2012, the devkit's evaluate_odometry.cpp), with
// configurable segment lengths so that short clips can be evaluated too.
//
// For every first frame i (every `step_frames`-th; the devkit uses 10) and every length L, the
// segment ends at the first frame j whose ground-truth path distance from i is at least L
// (segments running past the end are skipped; the devkit asks for more than L, which differs
// only on exact ties). With Q ground truth and P estimate:
//   E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j),  t_err = |t(E)| / L,  r_err = angle(E) / L
// and the reported figures are the plain means over all segments of all lengths, in % and in
// deg/100 m (the units of the KITTI leaderboard).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/eval/trajectory_metrics.h"

namespace sightline {

// The devkit's segment lengths, 100 .. 800 m.
std::vector<double> KittiSegmentLengthsM();

// Parses "5,10,20,40" (commas and/or spaces) into positive lengths in metres, or the word "kitti"
// into KittiSegmentLengthsM(). Errors name the bad field.
StatusOr<std::vector<double>> ParseSegmentLengths(const std::string& text);

// The error of one segment.
struct SegmentError {
  size_t first_frame = 0;
  size_t last_frame = 0;
  double length_m = 0;                     // The nominal length L [m].
  double translation_error_pct = 0;        // 100 * t_err [%].
  double rotation_error_deg_per_100m = 0;  // r_err in deg per 100 m.
};

// Mean errors of all segments of one length.
struct SegmentLengthSummary {
  double length_m = 0;
  size_t segments = 0;
  double translation_error_pct = 0;
  double rotation_error_deg_per_100m = 0;
};

// All segment errors and their means.
struct KittiErrors {
  std::vector<SegmentError> segments;
  std::vector<SegmentLengthSummary> per_length;  // Only lengths with at least one segment.
  double translation_error_pct = 0;              // Mean over all segments [%].
  double rotation_error_deg_per_100m = 0;        // Mean over all segments [deg/100 m].
};

// Segment errors of associated poses (equal-length lists; alignment does not change them except
// for a Sim(3) scale). Fails when a length is not positive, when step_frames < 1, or when no
// segment fits (the message gives the ground-truth path length and the shortest length asked).
StatusOr<KittiErrors> ComputeKittiErrors(const PoseList& estimate, const PoseList& ground_truth,
                                         const std::vector<double>& lengths_m, int step_frames);

}  // namespace sightline
