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
                            bool weighted, double weigh_below_m) {
  FusedPosition out;
  const size_t n = window > 0 ? std::min(estimates.size(), size_t(window)) : estimates.size();
  if (n == 0) return out;
  std::vector<Eigen::Vector3d> positions;
  std::vector<double> sigmas;
  for (size_t i = estimates.size() - n; i < estimates.size(); ++i) {
    const FusedEstimate& e = estimates[i];
    const double l = lambda > 0 ? lambda : e.lambda;
    positions.push_back(e.base_from_camera * (e.in_camera_map / l));
    sigmas.push_back(e.sigma_m * e.lambda / l);
  }
  // Weighing pays once the arm has come close enough that its estimates are sure to a few
  // millimetres: far ones, each placed again with the newest scale, then carry that scale's error
  // times their distance and a map refined since. Before, the near estimates are hardly better
  // than the rest and the plain median of all is the safer guide.
  const bool weigh = weighted || (weigh_below_m > 0 &&
                                  std::any_of(sigmas.begin(), sigmas.end(), [&](double sigma) {
                                    return sigma > 0 && sigma <= weigh_below_m;
                                  }));
  std::vector<double> weights;
  for (double sigma : sigmas) weights.push_back(weigh && sigma > 0 ? 1.0 / (sigma * sigma) : 1.0);
  out.weighted = weigh;
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
