#include "core/eval/association.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace sightline {

const char* AssociationModeName(AssociationMode mode) {
  return mode == AssociationMode::kIndex ? "index" : "time";
}

StatusOr<AssociationMode> ParseAssociationMode(const std::string& text) {
  if (text == "time") return AssociationMode::kTimestamp;
  if (text == "index") return AssociationMode::kIndex;
  return InvalidArgument("unknown association '" + text + "' (expected time or index)");
}

namespace {

Status CheckTimesIncrease(const Trajectory& trajectory, const char* what) {
  const auto& poses = trajectory.poses();
  for (size_t i = 1; i < poses.size(); ++i) {
    if (!(poses[i].time_s >= poses[i - 1].time_s)) {
      return InvalidArgument(std::string(what) + " timestamps must not decrease (pose " +
                             std::to_string(i) + " at t=" + std::to_string(poses[i].time_s) +
                             " s follows t=" + std::to_string(poses[i - 1].time_s) + " s)");
    }
  }
  return Status::Ok();
}

}  // namespace

StatusOr<AssociatedPoses> AssociateByTimestamp(const Trajectory& estimate,
                                               const Trajectory& ground_truth, double tolerance_s) {
  if (!(tolerance_s >= 0) || !std::isfinite(tolerance_s)) {
    return InvalidArgument("association tolerance must be a finite time >= 0 s");
  }
  SIGHTLINE_RETURN_IF_ERROR(CheckTimesIncrease(estimate, "estimate"));
  SIGHTLINE_RETURN_IF_ERROR(CheckTimesIncrease(ground_truth, "ground-truth"));
  const auto& est = estimate.poses();
  const auto& gt = ground_truth.poses();

  // Every candidate pair within tolerance: (|dt|, estimate index, ground-truth index).
  std::vector<std::tuple<double, size_t, size_t>> candidates;
  for (size_t i = 0; i < est.size(); ++i) {
    const double t = est[i].time_s;
    auto it = std::lower_bound(gt.begin(), gt.end(), t - tolerance_s,
                               [](const TimedPose& p, double time) { return p.time_s < time; });
    for (; it != gt.end() && it->time_s <= t + tolerance_s; ++it) {
      candidates.emplace_back(std::abs(it->time_s - t), i, static_cast<size_t>(it - gt.begin()));
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> est_used(est.size(), false);
  std::vector<bool> gt_used(gt.size(), false);
  std::vector<std::pair<size_t, size_t>> pairs;
  for (const auto& [dt, i, j] : candidates) {
    if (est_used[i] || gt_used[j]) continue;
    est_used[i] = true;
    gt_used[j] = true;
    pairs.emplace_back(i, j);
  }
  std::sort(pairs.begin(), pairs.end());

  AssociatedPoses result;
  for (const auto& [i, j] : pairs) {
    result.estimate.push_back(est[i]);
    result.ground_truth.push_back(gt[j]);
  }
  result.unmatched_estimate = est.size() - pairs.size();
  result.unmatched_ground_truth = gt.size() - pairs.size();
  return result;
}

StatusOr<AssociatedPoses> AssociateByIndex(const Trajectory& estimate,
                                           const Trajectory& ground_truth) {
  if (estimate.size() != ground_truth.size()) {
    return InvalidArgument("association by index needs equal lengths, but the estimate has " +
                           std::to_string(estimate.size()) + " poses and the ground truth " +
                           std::to_string(ground_truth.size()));
  }
  AssociatedPoses result;
  result.estimate = estimate.poses();
  result.ground_truth = ground_truth.poses();
  return result;
}

}  // namespace sightline
