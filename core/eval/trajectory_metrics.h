// Error measures of an estimated trajectory against ground truth, on poses that are already
// associated (estimate[i] belongs to ground_truth[i]) and aligned (one world frame).
//
// Definitions (Sturm et al. 2012, "A Benchmark for the Evaluation of RGB-D SLAM Systems"):
//   ATE_i       = |t(Q_i) - t(P_i)|                                  (Q ground truth, P estimate)
//   E_ij        = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j)                        (relative pose error, RPE)
//   trans_ij    = |t(E_ij)|,  rot_ij = angle(E_ij)
// and the drift ratios of the RPE pairs, with L_ij the ground-truth path length from i to j:
//   rpe_trans_pct      = 100 * sum trans_ij / sum L_ij
//   rpe_rot_deg_per_m  = sum rot_ij[deg] / sum L_ij
// (ratios of sums, so that near-stationary pairs do not dominate as they would in a mean of
// ratios). The stereo seed's own metrics:
//   length_error_pct   = 100 * |len(P) - len(Q)| / len(Q)
//   endpoint_error_pct = 100 * |t(Q_last) - t(P_last)| / len(Q)
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// Poses world_from_sensor, one per associated time.
using PoseList = std::vector<Eigen::Isometry3d>;

// Summary of a set of non-negative errors. All zero when the set is empty.
struct ErrorStats {
  size_t count = 0;
  double rmse = 0;
  double mean = 0;
  double median = 0;   // Middle value, or the mean of the two middle values.
  double std_dev = 0;  // Population standard deviation.
  double min = 0;
  double max = 0;
};

// Count, RMSE, mean, median, standard deviation, minimum and maximum.
ErrorStats SummarizeErrors(std::vector<double> errors);

// The rotation angle of R in radians, in [0, pi]. Stable near 0 (atan2 rather than acos).
double RotationAngleRad(const Eigen::Matrix3d& rotation);

// Cumulative ground-truth path length at each pose: d[0] = 0, d[i] = d[i-1] + |t_i - t_(i-1)|.
std::vector<double> PathDistances(const PoseList& poses);

// Length of the polyline through the positions of `poses` [m].
double PathLength(const PoseList& poses);

// ATE_i in metres for every pose. The lists must have equal length.
std::vector<double> AbsoluteTranslationErrors(const PoseList& estimate,
                                              const PoseList& ground_truth);

// One relative pose error E_ij.
struct RelativeError {
  size_t first = 0;          // i
  size_t last = 0;           // j
  double gt_distance_m = 0;  // L_ij, ground-truth path length from i to j [m].
  double translation_m = 0;  // |t(E_ij)| [m].
  double rotation_deg = 0;   // angle(E_ij) [deg].
};

// E_ij for one pair of indices; `gt_distances` from PathDistances(ground_truth).
RelativeError RelativePoseError(const PoseList& estimate, const PoseList& ground_truth,
                                const std::vector<double>& gt_distances, size_t i, size_t j);

// E_(i, i+delta) for every i. Empty when delta_frames < 1 or there are too few poses.
std::vector<RelativeError> RelativeErrorsOverFrames(const PoseList& estimate,
                                                    const PoseList& ground_truth, int delta_frames);

// E_(i, j) for every i, with j the first pose whose ground-truth path distance from i is at least
// delta_m. Pairs that would run past the end are left out (so a path shorter than delta_m gives
// none).
std::vector<RelativeError> RelativeErrorsOverDistance(const PoseList& estimate,
                                                      const PoseList& ground_truth, double delta_m);

// RPE over a set of pairs: RMSE-style statistics in metres and degrees, and the drift ratios.
struct RelativeErrorSummary {
  ErrorStats translation_m;
  ErrorStats rotation_deg;
  double gt_distance_m = 0;       // sum L_ij [m].
  double translation_pct = 0;     // 100 * sum trans_ij / sum L_ij [%].
  double rotation_deg_per_m = 0;  // sum rot_ij / sum L_ij [deg/m].
};

// Summarises RPE pairs. Fails when there are none, or when their ground-truth path length sums to
// zero (the ratios are undefined for a ground truth that does not move).
StatusOr<RelativeErrorSummary> SummarizeRelativeErrors(const std::vector<RelativeError>& errors);

// 100 * |len(estimate) - len(ground_truth)| / len(ground_truth). Fails for a zero-length ground
// truth.
StatusOr<double> LengthErrorPct(const PoseList& estimate, const PoseList& ground_truth);

// 100 * |final estimated position - final true position| / len(ground_truth). Fails for a
// zero-length ground truth or empty lists.
StatusOr<double> EndpointErrorPct(const PoseList& estimate, const PoseList& ground_truth);

}  // namespace sightline
