#include "core/mono/scale_estimator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace sightline {
namespace {

// Random true displacements mu_i of length in [min_m, max_m] and pairs x = lambda mu + n_x,
// y = mu + n_y.
std::vector<ScalePair> MakePairs(int n, double lambda, double sigma_x, double sigma_y, double min_m,
                                 double max_m, std::mt19937* rng) {
  std::normal_distribution<double> gauss(0, 1);
  std::uniform_real_distribution<double> length(min_m, max_m);
  std::vector<ScalePair> pairs;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d mu =
        Eigen::Vector3d(gauss(*rng), gauss(*rng), gauss(*rng)).normalized() * length(*rng);
    ScalePair p;
    p.map_displacement =
        lambda * mu + sigma_x * Eigen::Vector3d(gauss(*rng), gauss(*rng), gauss(*rng));
    p.metric_displacement = mu + sigma_y * Eigen::Vector3d(gauss(*rng), gauss(*rng), gauss(*rng));
    pairs.push_back(p);
  }
  return pairs;
}

TEST(ScaleEstimator, RecoversTheScaleExactlyFromNoiselessPairs) {
  std::mt19937 rng(1);
  for (double lambda : {0.1, 1.0, 7.5}) {
    const std::vector<ScalePair> pairs = MakePairs(10, lambda, 0, 0, 0.01, 0.2, &rng);
    StatusOr<double> ml = MaxLikelihoodScale(pairs, 0.01, 0.002);
    ASSERT_TRUE(ml.ok()) << ml.status().message();
    EXPECT_NEAR(*ml, lambda, 1e-9 * lambda);
    StatusOr<double> weighted = MaxLikelihoodScale(pairs, 0.01, 0.002, 1.0);  // By length.
    ASSERT_TRUE(weighted.ok());
    EXPECT_NEAR(*weighted, lambda, 1e-9 * lambda);
    StatusOr<double> single = SingleRatioScale(pairs[0]);
    ASSERT_TRUE(single.ok());
    EXPECT_NEAR(*single, lambda, 1e-9 * lambda);
  }
}

TEST(ScaleEstimator, MaxLikelihoodIsUnbiasedAndSingleRatioIsNotUnderNoise) {
  // Short, noisy displacements (noise 10-40 % of their length): the ML estimate's mean error over
  // 1000 trials stays below 0.5 %; the single ratio of one pair is biased upwards (|x| and 1/|y|
  // are both inflated by noise).
  std::mt19937 rng(7);
  const double lambda = 2.5, sigma_y = 0.01, sigma_x = lambda * 0.01;
  double ml_sum = 0, single_sum = 0;
  const int trials = 1000;
  for (int t = 0; t < trials; ++t) {
    const std::vector<ScalePair> pairs = MakePairs(60, lambda, sigma_x, sigma_y, 0.03, 0.1, &rng);
    StatusOr<double> ml = MaxLikelihoodScale(pairs, sigma_x, sigma_y);
    ASSERT_TRUE(ml.ok());
    ml_sum += *ml;
    single_sum += *SingleRatioScale(pairs[0]);
  }
  const double ml_error_pct = 100 * std::abs(ml_sum / trials - lambda) / lambda;
  const double single_error_pct = 100 * (single_sum / trials - lambda) / lambda;
  EXPECT_LT(ml_error_pct, 0.5);
  EXPECT_GT(single_error_pct, 3.0);
}

TEST(ScaleEstimator, GuardsAgainstOppositeDirections) {
  ScalePair p;
  p.map_displacement = Eigen::Vector3d(1, 0, 0);
  p.metric_displacement = Eigen::Vector3d(-0.5, 0, 0);
  StatusOr<double> ml = MaxLikelihoodScale({p}, 0.01, 0.01);
  EXPECT_FALSE(ml.ok());
  EXPECT_NE(ml.status().message().find("s_xy"), std::string::npos);
  p.metric_displacement = Eigen::Vector3d(0, 0.5, 0);  // Perpendicular: s_xy = 0.
  EXPECT_FALSE(MaxLikelihoodScale({p}, 0.01, 0.01).ok());
  EXPECT_FALSE(MaxLikelihoodScale({}, 0.01, 0.01).ok());
  EXPECT_FALSE(SingleRatioScale(ScalePair{}).ok());
}

TEST(ScaleEstimator, DoesNotDependOnTheOrderOfPairs) {
  std::mt19937 rng(3);
  std::vector<ScalePair> pairs = MakePairs(30, 1.7, 0.02, 0.01, 0.02, 0.2, &rng);
  ScaleEstimatorOptions options;
  options.sigma_map = 0.02;
  options.sigma_metric_m = 0.01;
  ScaleEstimator forward(options), backward(options);
  for (const ScalePair& p : pairs) forward.Add(p);
  std::reverse(pairs.begin(), pairs.end());
  for (const ScalePair& p : pairs) backward.Add(p);
  ASSERT_TRUE(forward.has_estimate());
  EXPECT_NEAR(forward.max_likelihood(), backward.max_likelihood(), 1e-12);
  EXPECT_NEAR(*MaxLikelihoodScale(pairs, 0.02, 0.01, options.length_exponent),
              forward.max_likelihood(), 1e-12);
}

TEST(ScaleEstimator, DropsShortPairsAndOutliersAndKeepsItsHistory) {
  std::mt19937 rng(5);
  const double lambda = 0.8;
  std::vector<ScalePair> pairs = MakePairs(20, lambda, 0.001, 0.001, 0.05, 0.1, &rng);
  ScaleEstimatorOptions options;
  options.min_metric_length_m = 0.02;
  ScaleEstimator scale(options);
  for (const ScalePair& p : pairs) EXPECT_TRUE(scale.Add(p));
  ScalePair tiny;
  tiny.map_displacement = Eigen::Vector3d(0.001, 0, 0);
  tiny.metric_displacement = Eigen::Vector3d(0.001, 0, 0);
  EXPECT_FALSE(scale.Add(tiny));
  ScalePair wild;  // A tracking failure: 20 times the true scale.
  wild.map_displacement = Eigen::Vector3d(20 * lambda * 0.1, 0, 0);
  wild.metric_displacement = Eigen::Vector3d(0.1, 0, 0);
  EXPECT_TRUE(scale.Add(wild));
  EXPECT_EQ(scale.pairs_used(), 20);
  EXPECT_NEAR(scale.max_likelihood(), lambda, 0.01 * lambda);
  ASSERT_EQ(scale.history().size(), 22u);
  EXPECT_EQ(scale.history()[0].max_likelihood, 0);  // Fewer than min_pairs.
  EXPECT_GT(scale.history()[5].max_likelihood, 0);
  EXPECT_EQ(scale.history()[20].pair_ratio, 0);  // The dropped pair.
}

TEST(ScaleEstimator, OptionsAreChecked) {
  ScaleEstimatorOptions o;
  std::string error;
  EXPECT_TRUE(o.IsValid(&error));
  o.sigma_map = 0;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("mono.scale.sigma_map"), std::string::npos);
  o = {};
  o.length_exponent = -1;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("mono.scale.length_exponent"), std::string::npos);
  EXPECT_EQ(ScaleEstimatorOptions::Describe().Specs().size(), 6u);
}

}  // namespace
}  // namespace sightline
