// Metric scale of a monocular map from measured motion (seed 004, section 4.0.5.2).
//
// Convention: lambda is map units per metre, x = lambda * y, where x is a camera displacement in
// map units and y the same displacement in metres over the same interval, both in one
// orientation frame. The metric map is map / lambda. (The seed's s of equation 4.3 is 1 / lambda.)
//
// - Single ratio (seed eq. 4.3): lambda = |x| / |y| of one pair, usually the initial baseline.
// - Maximum likelihood (Engel, Sturm and Cremers 2014; seed eq. 4.6 in its correct form), with
//   x_i ~ N(lambda mu_i, sigma_x^2 I) and y_i ~ N(mu_i, sigma_y^2 I):
//     s_xx = sigma_y^2 sum x.x,  s_yy = sigma_x^2 sum y.y,  s_xy = sigma_y sigma_x sum x.y
//     lambda = (s_xx - s_yy + sign(s_xy) sqrt((s_xx - s_yy)^2 + 4 s_xy^2)) / (2 sigma_y s_xy /
//     sigma_x)
//   Pair i may carry a weight w_i in all three sums (its sigmas scaled by 1 / sqrt(w_i)). With
//   length_exponent e, w_i = |y_i|^-e: e = 1 models a map whose displacement error grows like a
//   random walk with the distance travelled (the drift of monocular SLAM), so one long pair no
//   longer outweighs the many short ones (e = 0: the plain estimator, every pair's noise equal).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/mono/mono_types.h"
#include "core/options/option_table.h"

namespace sightline {

// One displacement pair over one interval.
struct ScalePair {
  Eigen::Vector3d map_displacement = Eigen::Vector3d::Zero();     // x [map units].
  Eigen::Vector3d metric_displacement = Eigen::Vector3d::Zero();  // y [m].
};

// Options of the scale estimators. Keys "mono.scale.*".
struct ScaleEstimatorOptions {
  double sigma_map = 0.002;           // sigma_x: noise of a map displacement [map units].
  double sigma_metric_m = 0.001;      // sigma_y: noise of a measured displacement [m].
  double min_metric_length_m = 0.01;  // Shorter measured displacements are dropped [m].
  double outlier_factor = 5.0;        // Pairs whose own ratio is outside [l/f, l*f] are dropped.
  int min_pairs = 3;                  // The ML estimate is reported from this many pairs on.
  double length_exponent = 1.0;       // Pair weight |y|^-e (variance grows with the interval).

  bool IsValid(std::string* error) const;
  static OptionTable<ScaleEstimatorOptions> Describe();
};

// lambda = |x| / |y|. InvalidArgument when |y| or |x| is zero or not finite.
StatusOr<double> SingleRatioScale(const ScalePair& pair);

// The closed-form ML estimate over `pairs` (all used, no filtering). InvalidArgument when there
// are no pairs, a sigma is not positive, or s_xy <= 0 (the displacements disagree in direction
// on the whole, so no positive scale explains them).
// `length_exponent` weights each pair by |y|^-length_exponent (0 = unweighted).
StatusOr<double> MaxLikelihoodScale(const std::vector<ScalePair>& pairs, double sigma_map,
                                    double sigma_metric_m, double length_exponent = 0);

// Accumulates pairs and keeps both estimates and their history.
//
//   ScaleEstimator scale(options);
//   scale.Add({map_now - map_before, metres_now - metres_before});
//   if (scale.has_estimate()) metric = map_point / scale.max_likelihood();
class ScaleEstimator {
 public:
  explicit ScaleEstimator(ScaleEstimatorOptions options = {}) : options_(options) {}

  // Offers a pair; returns false when it is dropped as too short or not finite.
  bool Add(const ScalePair& pair);
  void Reset();

  bool has_estimate() const { return max_likelihood_ > 0; }
  double max_likelihood() const { return max_likelihood_; }  // 0 until min_pairs pairs.
  double single_ratio() const { return single_ratio_; }      // 0 until one pair.
  const std::vector<ScaleSample>& history() const { return history_; }
  const std::vector<ScalePair>& pairs() const { return pairs_; }
  // Pairs kept by the last outlier rejection.
  int pairs_used() const { return pairs_used_; }

 private:
  void Update();

  ScaleEstimatorOptions options_;
  std::vector<ScalePair> pairs_;  // Accepted (long enough) pairs.
  std::vector<ScaleSample> history_;
  double single_ratio_ = 0;
  double max_likelihood_ = 0;
  int pairs_used_ = 0;
};

}  // namespace sightline
