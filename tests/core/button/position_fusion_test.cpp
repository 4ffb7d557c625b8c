// Fusion of the per-frame button positions: the plain per-axis median while every estimate is
// unsure, weighed by the estimates' own variance once the arm has come close.
#include "core/button/position_fusion.h"

#include <gtest/gtest.h>

#include <vector>

namespace sightline {
namespace {

// An approach along x: `far` estimates 3 mm beyond the button (each placed again with a newer
// scale, they carry its error times their distance), then `near` ones 1 mm short of it.
std::vector<FusedEstimate> Approach(int far, int near, double far_sigma, double near_sigma) {
  std::vector<FusedEstimate> estimates;
  for (int i = 0; i < far + near; ++i) {
    FusedEstimate e;
    const bool is_near = i >= far;
    const double depth = is_near ? 0.15 : 0.8;
    e.in_camera_map = Eigen::Vector3d(0, 0, 2.0 * (depth + (is_near ? -0.001 : 0.003)));
    e.lambda = 2.0;  // Map units per metre.
    e.base_from_camera = Eigen::Translation3d(1.0 - depth, 0, 0) *
                         Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY());
    e.sigma_m = is_near ? near_sigma : far_sigma;
    estimates.push_back(e);
  }
  return estimates;
}

TEST(PositionFusion, EveryEstimateCountsTheSameWhileNoneIsSure) {
  const auto estimates = Approach(30, 10, 0.009, 0.004);
  const FusedPosition fused = FusePositions(estimates, 0, 2.0, false, 0.003);
  EXPECT_FALSE(fused.weighted);
  EXPECT_NEAR(fused.in_base.x(), 1.003, 1e-9);  // The far majority's median.
  EXPECT_EQ(fused.estimates, 40);
}

TEST(PositionFusion, OnceOneEstimateIsSureTheNearOnesCountMost) {
  const auto estimates = Approach(30, 10, 0.009, 0.001);
  const FusedPosition fused = FusePositions(estimates, 0, 2.0, false, 0.003);
  EXPECT_TRUE(fused.weighted);
  EXPECT_NEAR(fused.in_base.x(), 0.999, 1e-9);
  // Off (0): the plain median; forced on: weighed even when no estimate is sure.
  EXPECT_NEAR(FusePositions(estimates, 0, 2.0, false, 0).in_base.x(), 1.003, 1e-9);
  const auto unsure = Approach(30, 10, 0.009, 0.004);
  EXPECT_NEAR(FusePositions(unsure, 0, 2.0, true, 0).in_base.x(), 0.999, 1e-9);
}

TEST(PositionFusion, TheNewestScalePlacesEveryEstimateAgain) {
  auto estimates = Approach(1, 0, 0.009, 0.001);
  // Located with 2 map units per metre, 0.8 m + 3 mm away; with 2.02 it lies 1 % nearer.
  const FusedPosition fused = FusePositions(estimates, 0, 2.02, false, 0.003);
  EXPECT_NEAR(fused.in_base.x(), 0.2 + 0.803 / 1.01, 1e-9);
  EXPECT_NEAR(FusePositions(estimates, 0, 0, false, 0.003).in_base.x(), 1.003, 1e-9);
}

}  // namespace
}  // namespace sightline
