// The subsampling sweep of the stereo seed's Table 1: the same recording processed with every
// k-th frame (k = 1..N), each estimate's path length compared with the ground truth's.
//
//   std::vector<SubsampleEstimate> runs;
//   for (int k : {1, 2, 3, 4, 5, 10, 20, 40}) {
//     runs.push_back({k, RunOdometry(SubsampleTrajectory(frames, k))});
//   }
//   StatusOr<std::vector<SubsampleRow>> table = EvaluateSubsampleSweep(runs, ground_truth, 0.02);
//   if (table.ok()) std::cout << FormatSubsampleTable(*table);
#pragma once

#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/common/trajectory.h"

namespace sightline {

// Every k-th pose, starting with the first (k >= 1; k <= 1 returns a copy).
Trajectory SubsampleTrajectory(const Trajectory& trajectory, int every_k);

// The estimate obtained when processing every `factor`-th frame.
struct SubsampleEstimate {
  int factor = 1;       // k: every k-th frame was processed.
  Trajectory estimate;  // Poses at the processed frames' timestamps.
};

// One row of the table, as in the seed: factor, equivalent frame rate, true and estimated path
// length and the length error.
struct SubsampleRow {
  int factor = 1;
  double equivalent_fps = 0;  // (poses - 1) / duration of the estimate [1/s].
  double gt_length_m = 0;     // Path through the ground-truth poses paired with the estimate [m].
  double estimate_length_m = 0;  // Path through the estimate's paired poses [m].
  double length_error_pct = 0;   // 100 |estimate - gt| / gt [%].
  size_t pairs = 0;              // Associated poses.
};

// One row per estimate, in the order given. Poses associate by timestamp within tolerance_s, so
// the ground-truth length is measured through the same (subsampled) instants as the estimate, as
// the seed's "Distancia" column is. Path length is unchanged by a rigid alignment, so none is
// applied. Fails, naming the factor, when a factor is < 1, an estimate has fewer than 2 poses
// paired with ground truth, spans no time, or its ground-truth path has zero length.
StatusOr<std::vector<SubsampleRow>> EvaluateSubsampleSweep(
    const std::vector<SubsampleEstimate>& estimates, const Trajectory& ground_truth,
    double tolerance_s);

// The table as text: "factor  fps  gt_m  estimate_m  error_pct", one line per row.
std::string FormatSubsampleTable(const std::vector<SubsampleRow>& rows);

}  // namespace sightline
