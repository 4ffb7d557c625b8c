// One call that evaluates an estimated trajectory against ground truth: association, alignment,
// ATE, RPE, KITTI segment errors, length and end-point errors, as `sightline-cli eval` prints
// them and as `sightline-cli run` adds them to the `accuracy` block of metrics.json.
//
//   StatusOr<TrajectoryErrors> errors = EvaluateTrajectory(estimate, ground_truth, options);
//   if (!errors.ok()) return errors.status();
//   metrics.accuracy = AccuracyFigures(*errors);
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/status.h"
#include "core/common/trajectory.h"
#include "core/eval/alignment.h"
#include "core/eval/kitti_metrics.h"
#include "core/eval/trajectory_metrics.h"
#include "core/options/option_table.h"

namespace sightline {

// How to evaluate. Keys under "eval." in option sets, profiles and `--set`.
struct EvaluationOptions {
  std::string align = "se3";            // se3, sim3 (monocular) or none.
  std::string associate = "time";       // time (nearest timestamp) or index (i-th with i-th).
  double max_time_difference_s = 0.02;  // Timestamp association tolerance [s].
  int rpe_delta_frames = 1;             // RPE pair spacing for rpe_trans_m / rpe_rot_deg.
  double rpe_delta_m = 0;               // RPE pair spacing for the % and deg/m figures [m];
                                        // 0 uses the rpe_delta_frames pairs instead.
  std::string segment_lengths_m = "5,10,20,40";  // KITTI segment lengths [m], or "kitti".
  int segment_step_frames = 1;                   // First-frame step of KITTI segments (devkit: 10).

  bool IsValid(std::string* error) const;
  static OptionTable<EvaluationOptions> Describe();
};

// Everything measured, per pose and summarised. Positions are in the ground-truth world frame,
// the estimate after alignment.
struct TrajectoryErrors {
  AlignmentMode alignment = AlignmentMode::kSe3;
  Similarity3 ground_truth_from_estimate;  // The alignment applied (identity for none).
  size_t pairs = 0;                        // Associated poses.
  size_t unmatched_estimate = 0;           // Estimated poses without ground truth (dropped).
  size_t unmatched_ground_truth = 0;       // Ground-truth poses not paired.

  std::vector<double> times_s;                          // Estimate time of each pair [s].
  std::vector<Eigen::Vector3d> estimate_positions;      // Aligned estimate [m].
  std::vector<Eigen::Vector3d> ground_truth_positions;  // [m].
  std::vector<double> ate_m;                            // ATE of each pair [m].

  ErrorStats ate;            // Absolute trajectory error [m].
  RelativeErrorSummary rpe;  // Over rpe_delta_frames pairs.
  // Over rpe_delta_m pairs; absent when rpe_delta_m is 0 or the path is shorter than it.
  std::optional<RelativeErrorSummary> rpe_over_distance;
  int rpe_delta_frames = 1;
  double rpe_delta_m = 0;
  double ground_truth_length_m = 0;  // Path length through the associated poses [m].
  double estimate_length_m = 0;      // Same for the aligned estimate [m].
  double length_error_pct = 0;       // 100 |len_est - len_gt| / len_gt [%].
  double endpoint_error_pct = 0;     // 100 |p_est_last - p_gt_last| / len_gt [%].
  std::optional<KittiErrors> kitti;  // Absent when no segment length fits the path.
  std::vector<std::string> notes;    // Why an optional figure is absent, for people.

  // The drift ratios reported as rpe_trans_pct / rpe_rot_deg_per_m: over distance when asked
  // for and available, else over frames; nullptr when distance pairs were asked for but none fit.
  const RelativeErrorSummary* RpeForRatios() const;
};

// Associates, aligns and measures. Fails with a message saying what to change when an input pose
// is not finite, when fewer than 3 poses associate, when too few poses remain for the RPE delta,
// when the ground truth does not move (the % figures would be undefined), or when the options
// are invalid. Never puts NaN in the result.
StatusOr<TrajectoryErrors> EvaluateTrajectory(const Trajectory& estimate,
                                              const Trajectory& ground_truth,
                                              const EvaluationOptions& options);

// The `accuracy` block of metrics.json, in this order: ate_rmse_m, ate_mean_m, ate_median_m,
// ate_max_m, rpe_trans_pct, rpe_rot_deg_per_m, rpe_trans_m, rpe_rot_deg, length_error_pct,
// endpoint_error_pct, kitti_t_err_pct, kitti_r_err_deg_per_100m, scale (Sim(3) only; the factor
// applied to the estimate), pairs. Figures that are absent in `errors` are left out.
std::vector<std::pair<std::string, double>> AccuracyFigures(const TrajectoryErrors& errors);

}  // namespace sightline
