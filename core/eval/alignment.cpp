#include "core/eval/alignment.h"

#include <Eigen/SVD>
#include <cmath>

namespace sightline {

const char* AlignmentModeName(AlignmentMode mode) {
  switch (mode) {
    case AlignmentMode::kNone:
      return "none";
    case AlignmentMode::kSe3:
      return "se3";
    case AlignmentMode::kSim3:
      return "sim3";
  }
  return "?";
}

StatusOr<AlignmentMode> ParseAlignmentMode(const std::string& text) {
  for (AlignmentMode mode : {AlignmentMode::kNone, AlignmentMode::kSe3, AlignmentMode::kSim3}) {
    if (text == AlignmentModeName(mode)) return mode;
  }
  return InvalidArgument("unknown alignment '" + text + "' (expected se3, sim3 or none)");
}

Eigen::Isometry3d Similarity3::Apply(const Eigen::Isometry3d& world_from_sensor) const {
  Eigen::Isometry3d aligned = Eigen::Isometry3d::Identity();
  aligned.linear() = rotation * world_from_sensor.linear();
  aligned.translation() = Apply(Eigen::Vector3d(world_from_sensor.translation()));
  return aligned;
}

StatusOr<Similarity3> AlignUmeyama(const std::vector<Eigen::Vector3d>& estimate_positions,
                                   const std::vector<Eigen::Vector3d>& ground_truth_positions,
                                   AlignmentMode mode) {
  const size_t n = estimate_positions.size();
  if (n != ground_truth_positions.size()) {
    return InvalidArgument("alignment needs corresponding points: " + std::to_string(n) +
                           " estimated vs " + std::to_string(ground_truth_positions.size()) +
                           " ground-truth positions");
  }
  if (mode == AlignmentMode::kNone) return Similarity3();
  if (n < 3) {
    return InvalidArgument("alignment needs at least 3 corresponding positions, got " +
                           std::to_string(n));
  }
  Eigen::Vector3d mean_est = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_gt = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < n; ++i) {
    mean_est += estimate_positions[i];
    mean_gt += ground_truth_positions[i];
  }
  mean_est /= static_cast<double>(n);
  mean_gt /= static_cast<double>(n);

  // Cross-covariance Sigma = 1/n sum (gt - mean_gt)(est - mean_est)^T and the estimate's variance.
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
  double variance_est = 0;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d e = estimate_positions[i] - mean_est;
    sigma += (ground_truth_positions[i] - mean_gt) * e.transpose();
    variance_est += e.squaredNorm();
  }
  sigma /= static_cast<double>(n);
  variance_est /= static_cast<double>(n);
  if (!(variance_est > 1e-18)) {
    return InvalidArgument("alignment is undefined: all " + std::to_string(n) +
                           " estimated positions coincide");
  }

  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sigma, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d s = Eigen::Matrix3d::Identity();
  // Umeyama's correction: never return a reflection.
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) s(2, 2) = -1;

  Similarity3 result;
  result.rotation = svd.matrixU() * s * svd.matrixV().transpose();
  if (mode == AlignmentMode::kSim3) {
    result.scale = (svd.singularValues().asDiagonal() * s).trace() / variance_est;
    if (!(result.scale > 0) || !std::isfinite(result.scale)) {
      return InvalidArgument(
          "Sim(3) alignment found no positive scale (the ground truth does "
          "not move, or moves unrelated to the estimate)");
    }
  }
  result.translation = mean_gt - result.scale * result.rotation * mean_est;
  return result;
}

}  // namespace sightline
