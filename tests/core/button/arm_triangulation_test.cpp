// The button's point from the arm's metric camera poses (core/button/arm_triangulation.h) on
// synthetic geometry: the simulated approach's motion (a sideways move at 1 m, then straight at
// the button to 0.3 m), exact poses, the tracked centre and radius with noise.
#include "core/button/arm_triangulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/support/test_camera.h"

namespace sightline {
namespace {

// The button in the arm's base frame, facing the arm (the camera looks along base +x).
const Eigen::Vector3d kButton(1.2, 0.05, 0.2);
constexpr double kRadiusM = 0.018;

// The camera `distance` in front of the button, moved `lateral` sideways, looking at the panel.
Eigen::Isometry3d CameraAt(double distance, double lateral) {
  Eigen::Matrix3d r;
  r.col(2) = Eigen::Vector3d::UnitX();   // Optical z: into the panel.
  r.col(0) = -Eigen::Vector3d::UnitY();  // Image right.
  r.col(1) = r.col(2).cross(r.col(0));   // Image down.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = r;
  pose.translation() = kButton - distance * Eigen::Vector3d::UnitX() + lateral * r.col(0);
  return pose;
}

struct Noise {
  double pixel_px = 0, radius_rel = 0;
  double outlier_fraction = 0;  // Views whose centre is 30 px off.
};

// `sideways` views on one sine period of +-8 cm at 1 m, then `approach` views from 1 m to 0.3 m.
std::vector<ArmView> Approach(int sideways, int approach, const Noise& noise, uint64_t seed) {
  const PinholeCamera camera = testing::VgaCamera();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<ArmView> views;
  auto add = [&](const Eigen::Isometry3d& pose) {
    const Eigen::Vector3d x = pose.inverse() * kButton;
    ArmView v;
    v.base_from_camera = pose;
    v.pixel = camera.Project(x) + noise.pixel_px * Eigen::Vector2d(g(rng), g(rng));
    if (u(rng) < noise.outlier_fraction) v.pixel += Eigen::Vector2d(30, -20);
    v.radius_px = camera.fx * kRadiusM / x.z() * (1 + noise.radius_rel * g(rng));
    views.push_back(v);
  };
  for (int i = 0; i < sideways; ++i) add(CameraAt(1.0, 0.08 * std::sin(2 * M_PI * i / sideways)));
  for (int i = 0; i < approach; ++i) add(CameraAt(1.0 - 0.7 * i / std::max(1, approach - 1), 0));
  return views;
}

TEST(ArmTriangulation, ExactViewsGiveTheExactPointAndSizeConstant) {
  const auto at =
      TriangulateFromArm(Approach(40, 60, {}, 1), testing::VgaCamera(), ArmTriangulationOptions{});
  ASSERT_TRUE(at.ok()) << at.status().ToString();
  EXPECT_LT((at->in_base - kButton).norm(), 1e-6);
  EXPECT_NEAR(at->radius_at_1m_px, 525 * kRadiusM, 1e-4);
  EXPECT_EQ(at->inliers, 100);
  EXPECT_TRUE(at->used_size);
}

TEST(ArmTriangulation, NoisyTrackWithinTwoMillimetresAndItsStatedCovariance) {
  Noise noise;
  noise.pixel_px = 0.5;
  noise.radius_rel = 0.005;
  ArmTriangulationOptions options;
  options.floor_sigma_m = 0;
  int covered = 0;
  const int runs = 40;
  for (int seed = 1; seed <= runs; ++seed) {
    const auto at =
        TriangulateFromArm(Approach(45, 105, noise, seed), testing::VgaCamera(), options);
    ASSERT_TRUE(at.ok()) << at.status().ToString();
    const Eigen::Vector3d e = at->in_base - kButton;
    EXPECT_LT(e.norm(), 0.002) << "seed " << seed;
    // Within the 95 % ellipsoid of its covariance (chi-square, 3 degrees of freedom).
    covered += e.dot(at->covariance.inverse() * e) <= 7.81;
  }
  EXPECT_GE(covered, 0.85 * runs);
}

TEST(ArmTriangulation, LoomingAloneGivesTheDepthAlongTheApproach) {
  Noise noise;
  noise.pixel_px = 0.3;
  noise.radius_rel = 0.003;
  const std::vector<ArmView> views = Approach(0, 60, noise, 7);  // Every ray on the one axis.
  const auto at = TriangulateFromArm(views, testing::VgaCamera(), ArmTriangulationOptions{});
  ASSERT_TRUE(at.ok()) << at.status().ToString();
  EXPECT_LT((at->in_base - kButton).norm(), 0.002);
  // The rays alone cannot tell the depth.
  ArmTriangulationOptions rays_only;
  rays_only.use_size = false;
  EXPECT_EQ(TriangulateFromArm(views, testing::VgaCamera(), rays_only).status().code(),
            StatusCode::kFailedPrecondition);
}

TEST(ArmTriangulation, CrossingRaysAloneGiveThePointFromTheSidewaysMove) {
  Noise noise;
  noise.pixel_px = 0.3;
  ArmTriangulationOptions options;
  options.use_size = false;
  const auto at = TriangulateFromArm(Approach(45, 0, noise, 3), testing::VgaCamera(), options);
  ASSERT_TRUE(at.ok()) << at.status().ToString();
  EXPECT_FALSE(at->used_size);
  // 8 cm at 1 m: the depth is the weak axis (about 1.5 mm per view-averaged 0.3 px).
  EXPECT_LT((at->in_base - kButton).norm(), 0.006);
  EXPECT_LT(std::abs((at->in_base - kButton).y()), 0.001);  // Across the rays: sub-mm.
}

// A tracked centre off by a constant 0.4 px in the image (a detector's sub-pixel convention)
// tilts the approach's rays against the sideways move's: estimated, it leaves the point.
TEST(ArmTriangulation, EstimatesAConstantImageOffsetOfTheTrackedCentre) {
  Noise noise;
  noise.pixel_px = 0.2;
  noise.radius_rel = 0.003;
  std::vector<ArmView> views = Approach(45, 105, noise, 5);
  for (ArmView& v : views) v.pixel += Eigen::Vector2d(0.4, 0.4);
  const auto at = TriangulateFromArm(views, testing::VgaCamera(), {});
  ASSERT_TRUE(at.ok()) << at.status().ToString();
  EXPECT_LT((at->in_base - kButton).norm(), 0.001);
  EXPECT_LT((at->pixel_offset_px - Eigen::Vector2d(0.4, 0.4)).norm(), 0.1);
  ArmTriangulationOptions held;
  held.pixel_offset = false;
  const auto off = TriangulateFromArm(views, testing::VgaCamera(), held);
  ASSERT_TRUE(off.ok()) << off.status().ToString();
  EXPECT_GT((off->in_base - kButton).norm(), (at->in_base - kButton).norm());
}

TEST(ArmTriangulation, RobustToMisTrackedViews) {
  Noise noise;
  noise.pixel_px = 0.5;
  noise.radius_rel = 0.005;
  noise.outlier_fraction = 0.2;
  const auto at = TriangulateFromArm(Approach(45, 105, noise, 11), testing::VgaCamera(), {});
  ASSERT_TRUE(at.ok()) << at.status().ToString();
  EXPECT_LT((at->in_base - kButton).norm(), 0.0015);
  EXPECT_LT(at->inliers, 135);  // The mis-tracked views are recognised.
}

TEST(ArmTriangulation, RefusesTooFewViewsAStillCameraAndInvalidOptions) {
  const PinholeCamera camera = testing::VgaCamera();
  EXPECT_EQ(TriangulateFromArm(Approach(3, 0, {}, 1), camera, {}).status().code(),
            StatusCode::kFailedPrecondition);
  std::vector<ArmView> still(20, Approach(1, 0, {}, 1).front());
  EXPECT_EQ(TriangulateFromArm(still, camera, {}).status().code(), StatusCode::kFailedPrecondition);
  ArmTriangulationOptions bad;
  bad.pixel_sigma_px = 0;
  EXPECT_EQ(TriangulateFromArm(Approach(40, 40, {}, 1), camera, bad).status().code(),
            StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace sightline
