#include "core/mono/pose_optimizer.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/support/test_camera.h"

namespace sightline {
namespace {

TEST(PoseOptimizer, RecoversThePoseDespiteThirtyPercentOutliers) {
  const PinholeCamera camera = testing::VgaCamera();
  Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
  truth.linear() =
      Eigen::AngleAxisd(0.1, Eigen::Vector3d(0.3, 1, 0.2).normalized()).toRotationMatrix();
  truth.translation() = Eigen::Vector3d(0.05, -0.02, 0.1);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), px(0, 600);
  std::normal_distribution<double> noise(0, 0.5);
  std::vector<PoseObservation> observations;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d x(u(rng), u(rng), 3 + u(rng));
    const Eigen::Vector3d p = truth * x;
    PoseObservation o;
    o.x_in_map = x;
    if (i % 10 < 3) {
      o.pixel = Eigen::Vector2d(px(rng), px(rng) * 0.8);  // Wrong match.
    } else {
      o.pixel = Eigen::Vector2d(camera.fx * p.x() / p.z() + camera.cx + noise(rng),
                                camera.fy * p.y() / p.z() + camera.cy + noise(rng));
    }
    observations.push_back(o);
  }
  Eigen::Isometry3d start = truth;
  start.translation() += Eigen::Vector3d(0.03, 0.02, -0.05);
  start.linear() =
      Eigen::AngleAxisd(0.03, Eigen::Vector3d::UnitY()).toRotationMatrix() * start.linear();
  const PoseEstimate estimate = OptimizePose(camera, start, observations, 2.5, 4.0);
  EXPECT_NEAR((estimate.camera_from_map.translation() - truth.translation()).norm(), 0, 0.005);
  EXPECT_NEAR(
      Eigen::AngleAxisd(estimate.camera_from_map.rotation() * truth.rotation().transpose()).angle(),
      0, 0.002);
  EXPECT_GE(estimate.inlier_count, 135);
  EXPECT_LE(estimate.inlier_count, 145);
  EXPECT_LT(estimate.rms_px, 1.0);
}

TEST(PoseOptimizer, TooFewObservationsLeaveThePoseAlone) {
  const Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  const PoseEstimate estimate =
      OptimizePose(testing::VgaCamera(), start, {PoseObservation{}}, 2.5, 4.0);
  EXPECT_EQ(estimate.inlier_count, 0);
  EXPECT_TRUE(estimate.camera_from_map.isApprox(start));
}

}  // namespace
}  // namespace sightline
