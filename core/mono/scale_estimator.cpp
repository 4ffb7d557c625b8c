#include "core/mono/scale_estimator.h"

#include <algorithm>
#include <cmath>

#include "core/mono/option_check.h"

namespace sightline {

using mono_internal::Invalid;

bool ScaleEstimatorOptions::IsValid(std::string* error) const {
  if (!(sigma_map > 0)) return Invalid(error, "mono.scale.sigma_map must be > 0");
  if (!(sigma_metric_m > 0)) return Invalid(error, "mono.scale.sigma_metric_m must be > 0");
  if (!(min_metric_length_m >= 0)) {
    return Invalid(error, "mono.scale.min_metric_length_m must be >= 0");
  }
  if (!(outlier_factor > 1)) return Invalid(error, "mono.scale.outlier_factor must be > 1");
  if (min_pairs < 1) return Invalid(error, "mono.scale.min_pairs must be >= 1");
  if (!(length_exponent >= 0 && length_exponent <= 4)) {
    return Invalid(error, "mono.scale.length_exponent must lie in [0, 4]");
  }
  return true;
}

OptionTable<ScaleEstimatorOptions> ScaleEstimatorOptions::Describe() {
  using O = ScaleEstimatorOptions;
  return OptionTable<O>("scale")  // Nested under "mono" by MonoSlamOptions.
      .Double("sigma_map", &O::sigma_map, "map units", 1e-6, 10, 0.001,
              "Noise of a camera displacement measured in the map (sigma_x of the ML estimator).")
      .Double("sigma_metric_m", &O::sigma_metric_m, "m", 1e-6, 10, 0.0005,
              "Noise of a displacement measured by the arm or robot (sigma_y).")
      .Double("min_metric_length_m", &O::min_metric_length_m, "m", 0, 10, 0.005,
              "Measured displacements shorter than this are dropped.")
      .Double("outlier_factor", &O::outlier_factor, "", 1.01, 100, 0.5,
              "Pairs whose own ratio lies outside a factor of this from the estimate are dropped.")
      .Int("min_pairs", &O::min_pairs, "pairs", 1, 10000, 1,
           "The maximum-likelihood estimate is reported from this many pairs on.")
      .Double("length_exponent", &O::length_exponent, "", 0, 4, 0.5,
              "Pairs weigh |measured displacement|^-e in the ML estimate: 1 = the map's error "
              "grows with the distance travelled, 0 = every pair equally noisy.");
}

StatusOr<double> SingleRatioScale(const ScalePair& pair) {
  const double x = pair.map_displacement.norm();
  const double y = pair.metric_displacement.norm();
  if (!std::isfinite(x) || !std::isfinite(y) || y <= 0 || x <= 0) {
    return InvalidArgument("single-ratio scale: a displacement is zero or not finite");
  }
  return x / y;
}

StatusOr<double> MaxLikelihoodScale(const std::vector<ScalePair>& pairs, double sigma_map,
                                    double sigma_metric_m, double length_exponent) {
  if (pairs.empty()) return InvalidArgument("maximum-likelihood scale: no pairs");
  if (!(sigma_map > 0) || !(sigma_metric_m > 0)) {
    return InvalidArgument("maximum-likelihood scale: the sigmas must be > 0");
  }
  double xx = 0, yy = 0, xy = 0;
  for (const ScalePair& p : pairs) {
    const double length = p.metric_displacement.norm();
    const double w = length_exponent == 0 ? 1.0
                     : length > 0         ? std::pow(length, -length_exponent)
                                          : 0.0;
    xx += w * p.map_displacement.squaredNorm();
    yy += w * p.metric_displacement.squaredNorm();
    xy += w * p.map_displacement.dot(p.metric_displacement);
  }
  const double sx = sigma_map, sy = sigma_metric_m;
  const double s_xx = sy * sy * xx;
  const double s_yy = sx * sx * yy;
  const double s_xy = sy * sx * xy;
  if (!std::isfinite(s_xx + s_yy + s_xy)) {
    return InvalidArgument("maximum-likelihood scale: a displacement is not finite");
  }
  if (s_xy <= 0) {
    return InvalidArgument(
        "maximum-likelihood scale: s_xy <= 0 (map and measured displacements "
        "do not point the same way; check the hand-eye transform)");
  }
  const double d = s_xx - s_yy;
  // s_xy > 0 here, so sign(s_xy) = +1.
  return (d + std::sqrt(d * d + 4 * s_xy * s_xy)) / (2 * (sy / sx) * s_xy);
}

bool ScaleEstimator::Add(const ScalePair& pair) {
  ScaleSample sample;
  sample.index = static_cast<int>(history_.size()) + 1;
  const bool finite = pair.map_displacement.allFinite() && pair.metric_displacement.allFinite();
  const bool accepted = finite && pair.metric_displacement.norm() >= options_.min_metric_length_m &&
                        pair.metric_displacement.norm() > 0 && pair.map_displacement.norm() > 0;
  if (accepted) {
    pairs_.push_back(pair);
    sample.pair_ratio = pair.map_displacement.norm() / pair.metric_displacement.norm();
    if (single_ratio_ == 0) single_ratio_ = sample.pair_ratio;
    Update();
  }
  sample.single_ratio = single_ratio_;
  sample.max_likelihood = max_likelihood_;
  sample.pairs_used = pairs_used_;
  history_.push_back(sample);
  return accepted;
}

void ScaleEstimator::Reset() {
  pairs_.clear();
  history_.clear();
  single_ratio_ = max_likelihood_ = 0;
  pairs_used_ = 0;
}

void ScaleEstimator::Update() {
  if (static_cast<int>(pairs_.size()) < options_.min_pairs) return;
  // First estimate over every pair, robustly started from the median ratio; then keep the pairs
  // whose own ratio lies within outlier_factor of it, and estimate again.
  std::vector<double> ratios;
  for (const ScalePair& p : pairs_) {
    ratios.push_back(p.map_displacement.norm() / p.metric_displacement.norm());
  }
  std::vector<double> sorted = ratios;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  double reference = sorted[sorted.size() / 2];
  std::vector<ScalePair> kept;
  for (int round = 0; round < 2; ++round) {
    kept.clear();
    for (size_t i = 0; i < pairs_.size(); ++i) {
      if (ratios[i] <= reference * options_.outlier_factor &&
          ratios[i] >= reference / options_.outlier_factor) {
        kept.push_back(pairs_[i]);
      }
    }
    StatusOr<double> ml = MaxLikelihoodScale(kept, options_.sigma_map, options_.sigma_metric_m,
                                             options_.length_exponent);
    if (!ml.ok()) return;
    reference = *ml;
  }
  max_likelihood_ = reference;
  pairs_used_ = static_cast<int>(kept.size());
}

}  // namespace sightline
