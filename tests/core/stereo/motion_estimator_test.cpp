#include "core/stereo/motion_estimator.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "stereo_test_util.h"

namespace sightline {
namespace {

using testing::RotationErrorDeg;
using testing::TranslationErrorM;

TEST(MotionEstimator, RecoversExactMotionDespiteOutliers) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const Eigen::Isometry3d truth = testing::TestMotion();
  const auto correspondences = testing::SyntheticCorrespondences(camera, truth, 300, 90, 0.0, 1);
  MotionEstimator ransac;
  const MotionHypothesis h = ransac.Estimate(camera, correspondences);
  ASSERT_TRUE(h.ok) << h.failure;
  EXPECT_LT(RotationErrorDeg(h.current_from_previous, truth), 1e-6);
  EXPECT_LT(TranslationErrorM(h.current_from_previous, truth), 1e-6);
  // Every true point is an inlier, no outlier is.
  EXPECT_EQ(h.inliers.size(), 210u);
  EXPECT_TRUE(std::none_of(h.inliers.begin(), h.inliers.end(), [](int i) { return i < 90; }));
  EXPECT_GT(h.rigidity_failures, 0);  // Outliers make samples fail the rigidity test.
}

TEST(MotionEstimator, IsDeterministicForOneSeed) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const auto correspondences =
      testing::SyntheticCorrespondences(camera, testing::TestMotion(), 200, 60, 0.3, 2);
  MotionEstimator ransac;
  const MotionHypothesis a = ransac.Estimate(camera, correspondences);
  const MotionHypothesis b = ransac.Estimate(camera, correspondences);
  ASSERT_TRUE(a.ok);
  EXPECT_EQ(a.inliers, b.inliers);
  EXPECT_TRUE(a.current_from_previous.isApprox(b.current_from_previous, 0));
}

TEST(MotionEstimator, FailsClearlyWithTooFewPointsOrNoRigidSample) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  MotionEstimator ransac;
  const auto few = testing::SyntheticCorrespondences(camera, testing::TestMotion(), 5, 0, 0, 3);
  MotionHypothesis h = ransac.Estimate(camera, few);
  EXPECT_FALSE(h.ok);
  EXPECT_NE(h.failure.find("too few correspondences"), std::string::npos);

  MotionEstimatorOptions options;
  options.max_rigidity_failures = 50;
  const auto garbage =
      testing::SyntheticCorrespondences(camera, testing::TestMotion(), 100, 100, 0, 4);
  h = MotionEstimator(options).Estimate(camera, garbage);
  EXPECT_FALSE(h.ok);
}

TEST(MotionEstimator, RigidityToleranceGrowsWithDepth) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  StereoCorrespondence a, b;
  a.x_previous = a.x_current = Eigen::Vector3d(0, 0, 2);
  b.x_previous = Eigen::Vector3d(1, 0, 2);
  b.x_current = Eigen::Vector3d(1.5, 0, 2);  // 0.5 m longer: not rigid near the camera.
  MotionEstimator ransac;
  EXPECT_FALSE(ransac.Rigid(camera, a, b));
  a.x_previous = a.x_current = Eigen::Vector3d(0, 0, 40);
  b.x_previous = Eigen::Vector3d(1, 0, 40);
  b.x_current = Eigen::Vector3d(1.5, 0, 40);  // Same change is within depth noise at 40 m.
  EXPECT_TRUE(ransac.Rigid(camera, a, b));
}

TEST(AbsoluteOrientation, NeverReturnsAReflection) {
  Eigen::Matrix3Xd from(3, 4), to(3, 4);
  from << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
  to = from;
  to.row(0) *= -1;  // A mirror image: the best rotation, not the reflection.
  const Eigen::Isometry3d t = AbsoluteOrientation(from, to);
  EXPECT_NEAR(t.rotation().determinant(), 1.0, 1e-9);
}

}  // namespace
}  // namespace sightline
