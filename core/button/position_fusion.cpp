#include "core/button/position_fusion.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sightline {

namespace {

// The weighted median of `values` (pairs of value, weight > 0).
double WeightedMedian(std::vector<std::pair<double, double>> values) {
  std::sort(values.begin(), values.end());
  double total = 0;
  for (const auto& v : values) total += v.second;
  double sum = 0;
  for (const auto& v : values) {
    sum += v.second;
    if (sum >= 0.5 * total) return v.first;
  }
  return values.back().first;
}

}  // namespace

FusedPosition FusePositions(const std::vector<FusedEstimate>& estimates, int window, double lambda,
                            bool weighted) {
  FusedPosition out;
  const size_t n = window > 0 ? std::min(estimates.size(), size_t(window)) : estimates.size();
  if (n == 0) return out;
  std::vector<Eigen::Vector3d> positions;
  std::vector<double> weights;
  for (size_t i = estimates.size() - n; i < estimates.size(); ++i) {
    const FusedEstimate& e = estimates[i];
    const double l = lambda > 0 ? lambda : e.lambda;
    positions.push_back(e.base_from_camera * (e.in_camera_map / l));
    const double sigma = e.sigma_m * e.lambda / l;
    weights.push_back(weighted && sigma > 0 ? 1.0 / (sigma * sigma) : 1.0);
  }
  for (int k = 0; k < 3; ++k) {
    std::vector<std::pair<double, double>> axis;
    for (size_t i = 0; i < n; ++i) axis.emplace_back(positions[i][k], weights[i]);
    out.in_base[k] = WeightedMedian(std::move(axis));
  }
  std::vector<std::pair<double, double>> distances;
  for (size_t i = 0; i < n; ++i) {
    distances.emplace_back((positions[i] - out.in_base).norm(), weights[i]);
  }
  out.spread_m = 1.4826 * WeightedMedian(std::move(distances));
  out.estimates = static_cast<int>(n);
  return out;
}

}  // namespace sightline
