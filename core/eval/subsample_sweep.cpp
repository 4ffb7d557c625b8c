#include "core/eval/subsample_sweep.h"

#include <cmath>
#include <cstdio>

#include "core/eval/association.h"
#include "core/eval/trajectory_metrics.h"

namespace sightline {

Trajectory SubsampleTrajectory(const Trajectory& trajectory, int every_k) {
  if (every_k <= 1) return trajectory;
  Trajectory result;
  for (size_t i = 0; i < trajectory.size(); i += static_cast<size_t>(every_k)) {
    result.mutable_poses().push_back(trajectory.poses()[i]);
  }
  return result;
}

StatusOr<std::vector<SubsampleRow>> EvaluateSubsampleSweep(
    const std::vector<SubsampleEstimate>& estimates, const Trajectory& ground_truth,
    double tolerance_s) {
  std::vector<SubsampleRow> rows;
  for (const SubsampleEstimate& run : estimates) {
    const std::string which = "subsampling factor " + std::to_string(run.factor);
    if (run.factor < 1) return InvalidArgument(which + ": the factor must be at least 1");
    StatusOr<AssociatedPoses> associated =
        AssociateByTimestamp(run.estimate, ground_truth, tolerance_s);
    if (!associated.ok()) return associated.status().WithContext(which);
    if (associated->size() < 2) {
      return InvalidArgument(which + ": only " + std::to_string(associated->size()) +
                             " estimated poses have ground truth (need at least 2)");
    }
    PoseList est;
    PoseList gt;
    for (size_t i = 0; i < associated->size(); ++i) {
      if (!associated->estimate[i].world_from_sensor.matrix().allFinite() ||
          !associated->ground_truth[i].world_from_sensor.matrix().allFinite()) {
        return InvalidArgument(which + ": associated pose " + std::to_string(i) +
                               " is not finite (NaN or infinity)");
      }
      est.push_back(associated->estimate[i].world_from_sensor);
      gt.push_back(associated->ground_truth[i].world_from_sensor);
    }
    StatusOr<double> error = LengthErrorPct(est, gt);
    if (!error.ok()) return error.status().WithContext(which);
    const double duration =
        associated->estimate.back().time_s - associated->estimate.front().time_s;
    if (!(duration > 0)) return InvalidArgument(which + ": the estimate spans no time");

    SubsampleRow row;
    row.factor = run.factor;
    row.equivalent_fps = static_cast<double>(associated->size() - 1) / duration;
    row.gt_length_m = PathLength(gt);
    row.estimate_length_m = PathLength(est);
    row.length_error_pct = *error;
    row.pairs = associated->size();
    rows.push_back(row);
  }
  return rows;
}

std::string FormatSubsampleTable(const std::vector<SubsampleRow>& rows) {
  std::string out;
  char line[160];
  std::snprintf(line, sizeof(line), "%6s %9s %11s %12s %10s %6s\n", "factor", "fps_equiv",
                "gt_length_m", "est_length_m", "error_pct", "pairs");
  out += line;
  for (const SubsampleRow& r : rows) {
    std::snprintf(line, sizeof(line), "%6d %9.3g %11.2f %12.2f %10.2f %6zu\n", r.factor,
                  r.equivalent_fps, r.gt_length_m, r.estimate_length_m, r.length_error_pct,
                  r.pairs);
    out += line;
  }
  return out;
}

}  // namespace sightline
