#include "core/eval/trajectory_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace sightline {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
// Below this a ground-truth path counts as not moving [m].
constexpr double kMinPathLengthM = 1e-9;

std::string FormatMetres(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g m", value);
  return text;
}

}  // namespace

ErrorStats SummarizeErrors(std::vector<double> errors) {
  ErrorStats stats;
  stats.count = errors.size();
  if (errors.empty()) return stats;
  double sum = 0;
  double sum_squares = 0;
  for (double e : errors) {
    sum += e;
    sum_squares += e * e;
  }
  const double n = static_cast<double>(errors.size());
  stats.mean = sum / n;
  stats.rmse = std::sqrt(sum_squares / n);
  stats.std_dev = std::sqrt(std::max(0.0, sum_squares / n - stats.mean * stats.mean));
  std::sort(errors.begin(), errors.end());
  stats.min = errors.front();
  stats.max = errors.back();
  const size_t mid = errors.size() / 2;
  stats.median = errors.size() % 2 == 1 ? errors[mid] : 0.5 * (errors[mid - 1] + errors[mid]);
  return stats;
}

double RotationAngleRad(const Eigen::Matrix3d& rotation) {
  const Eigen::Vector3d axis_times_sin(rotation(2, 1) - rotation(1, 2),
                                       rotation(0, 2) - rotation(2, 0),
                                       rotation(1, 0) - rotation(0, 1));
  const double cos_angle = 0.5 * (rotation.trace() - 1.0);
  return std::atan2(0.5 * axis_times_sin.norm(), cos_angle);
}

std::vector<double> PathDistances(const PoseList& poses) {
  std::vector<double> distances(poses.size(), 0.0);
  for (size_t i = 1; i < poses.size(); ++i) {
    distances[i] = distances[i - 1] + (poses[i].translation() - poses[i - 1].translation()).norm();
  }
  return distances;
}

double PathLength(const PoseList& poses) {
  const std::vector<double> d = PathDistances(poses);
  return d.empty() ? 0.0 : d.back();
}

std::vector<double> AbsoluteTranslationErrors(const PoseList& estimate,
                                              const PoseList& ground_truth) {
  std::vector<double> errors;
  const size_t n = std::min(estimate.size(), ground_truth.size());
  errors.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    errors.push_back((ground_truth[i].translation() - estimate[i].translation()).norm());
  }
  return errors;
}

RelativeError RelativePoseError(const PoseList& estimate, const PoseList& ground_truth,
                                const std::vector<double>& gt_distances, size_t i, size_t j) {
  const Eigen::Isometry3d gt_motion = ground_truth[i].inverse(Eigen::Isometry) * ground_truth[j];
  const Eigen::Isometry3d est_motion = estimate[i].inverse(Eigen::Isometry) * estimate[j];
  const Eigen::Isometry3d error = gt_motion.inverse(Eigen::Isometry) * est_motion;
  RelativeError e;
  e.first = i;
  e.last = j;
  e.gt_distance_m = gt_distances[j] - gt_distances[i];
  e.translation_m = error.translation().norm();
  e.rotation_deg = RotationAngleRad(error.linear()) * kDegPerRad;
  return e;
}

std::vector<RelativeError> RelativeErrorsOverFrames(const PoseList& estimate,
                                                    const PoseList& ground_truth,
                                                    int delta_frames) {
  std::vector<RelativeError> errors;
  const size_t n = std::min(estimate.size(), ground_truth.size());
  if (delta_frames < 1 || n <= static_cast<size_t>(delta_frames)) return errors;
  const std::vector<double> d = PathDistances(ground_truth);
  const size_t delta = static_cast<size_t>(delta_frames);
  for (size_t i = 0; i + delta < n; ++i) {
    errors.push_back(RelativePoseError(estimate, ground_truth, d, i, i + delta));
  }
  return errors;
}

std::vector<RelativeError> RelativeErrorsOverDistance(const PoseList& estimate,
                                                      const PoseList& ground_truth,
                                                      double delta_m) {
  std::vector<RelativeError> errors;
  const size_t n = std::min(estimate.size(), ground_truth.size());
  if (!(delta_m > 0)) return errors;
  const std::vector<double> d = PathDistances(ground_truth);
  size_t j = 0;
  for (size_t i = 0; i < n; ++i) {
    // d is non-decreasing, so the first j reaching d[i] + delta_m only moves forward.
    j = std::max(j, i + 1);
    while (j < n && d[j] - d[i] < delta_m) ++j;
    if (j >= n) break;
    errors.push_back(RelativePoseError(estimate, ground_truth, d, i, j));
  }
  return errors;
}

StatusOr<RelativeErrorSummary> SummarizeRelativeErrors(const std::vector<RelativeError>& errors) {
  if (errors.empty()) return InvalidArgument("no relative-pose pairs to evaluate");
  RelativeErrorSummary summary;
  std::vector<double> translations;
  std::vector<double> rotations;
  double translation_sum = 0;
  double rotation_sum = 0;
  for (const RelativeError& e : errors) {
    translations.push_back(e.translation_m);
    rotations.push_back(e.rotation_deg);
    translation_sum += e.translation_m;
    rotation_sum += e.rotation_deg;
    summary.gt_distance_m += e.gt_distance_m;
  }
  if (!(summary.gt_distance_m > kMinPathLengthM)) {
    return InvalidArgument(
        "relative errors per distance are undefined: the ground truth does not "
        "move over the " +
        std::to_string(errors.size()) + " RPE pairs");
  }
  summary.translation_m = SummarizeErrors(std::move(translations));
  summary.rotation_deg = SummarizeErrors(std::move(rotations));
  summary.translation_pct = 100.0 * translation_sum / summary.gt_distance_m;
  summary.rotation_deg_per_m = rotation_sum / summary.gt_distance_m;
  return summary;
}

StatusOr<double> LengthErrorPct(const PoseList& estimate, const PoseList& ground_truth) {
  const double gt_length = PathLength(ground_truth);
  if (!(gt_length > kMinPathLengthM)) {
    return InvalidArgument("length error in % is undefined: the ground-truth path has length " +
                           FormatMetres(gt_length));
  }
  return 100.0 * std::abs(PathLength(estimate) - gt_length) / gt_length;
}

StatusOr<double> EndpointErrorPct(const PoseList& estimate, const PoseList& ground_truth) {
  if (estimate.empty() || ground_truth.empty()) {
    return InvalidArgument("end-point error needs at least one pose in each trajectory");
  }
  const double gt_length = PathLength(ground_truth);
  if (!(gt_length > kMinPathLengthM)) {
    return InvalidArgument("end-point error in % is undefined: the ground-truth path has length " +
                           FormatMetres(gt_length));
  }
  return 100.0 * (ground_truth.back().translation() - estimate.back().translation()).norm() /
         gt_length;
}

}  // namespace sightline
