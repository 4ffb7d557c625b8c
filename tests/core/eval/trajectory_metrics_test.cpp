#include "core/eval/trajectory_metrics.h"

#include <gtest/gtest.h>

#include <numbers>

#include "tests/core/eval/eval_test_util.h"

namespace sightline {
namespace {

PoseList Poses(const Trajectory& t) {
  PoseList poses;
  for (const TimedPose& p : t.poses()) poses.push_back(p.world_from_sensor);
  return poses;
}

TEST(TrajectoryMetrics, SummarizeErrorsOfAKnownSet) {
  const ErrorStats s = SummarizeErrors({4, 3, 0, 1});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.0);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(26.0 / 4));
  EXPECT_DOUBLE_EQ(s.median, 2.0);
  EXPECT_DOUBLE_EQ(s.min, 0.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(s.std_dev, std::sqrt(26.0 / 4 - 4.0));
  EXPECT_EQ(SummarizeErrors({}).count, 0u);
  EXPECT_EQ(SummarizeErrors({}).rmse, 0.0);
  EXPECT_DOUBLE_EQ(SummarizeErrors({5, 1, 3}).median, 3.0);
}

TEST(TrajectoryMetrics, RotationAngleIsExactNearZeroAndUpToPi) {
  EXPECT_EQ(RotationAngleRad(Eigen::Matrix3d::Identity()), 0.0);
  for (double angle : {1e-9, 1e-4, 0.5, 2.0, std::numbers::pi - 1e-6}) {
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(angle, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
    EXPECT_NEAR(RotationAngleRad(r), angle, 1e-12 + 1e-9 * angle) << angle;
  }
}

TEST(TrajectoryMetrics, PathDistancesAccumulate) {
  const std::vector<double> d = PathDistances(Poses(testing::StraightLine(4, 0.5)));
  ASSERT_EQ(d.size(), 4u);
  EXPECT_DOUBLE_EQ(d[3], 1.5);
  EXPECT_DOUBLE_EQ(PathLength(Poses(testing::StraightLine(4, 0.5))), 1.5);
}

TEST(TrajectoryMetrics, RelativeErrorsOfAPerfectEstimateAreZero) {
  const PoseList gt = Poses(testing::Helix(50));
  for (int delta : {1, 5}) {
    const std::vector<RelativeError> errors = RelativeErrorsOverFrames(gt, gt, delta);
    ASSERT_EQ(errors.size(), 50u - delta);
    for (const RelativeError& e : errors) {
      EXPECT_LT(e.translation_m, 1e-12);
      EXPECT_LT(e.rotation_deg, 1e-9);
    }
  }
  EXPECT_TRUE(RelativeErrorsOverFrames(gt, gt, 50).empty());
  EXPECT_TRUE(RelativeErrorsOverFrames(gt, gt, 0).empty());
}

TEST(TrajectoryMetrics, RelativeErrorsOverDistanceEndWhereTheGroundTruthHasMovedFarEnough) {
  const PoseList gt = Poses(testing::StraightLine(11, 0.5));  // 5 m.
  const std::vector<RelativeError> errors = RelativeErrorsOverDistance(gt, gt, 2.0);
  ASSERT_EQ(errors.size(), 7u);  // i = 0..6, j = i + 4.
  EXPECT_EQ(errors.front().last, 4u);
  EXPECT_DOUBLE_EQ(errors.front().gt_distance_m, 2.0);
  EXPECT_TRUE(RelativeErrorsOverDistance(gt, gt, 6.0).empty());
}

TEST(TrajectoryMetrics, DriftRatiosUseSumsOverPairs) {
  std::vector<RelativeError> errors(2);
  errors[0].gt_distance_m = 1.0;
  errors[0].translation_m = 0.01;
  errors[0].rotation_deg = 0.5;
  errors[1].gt_distance_m = 3.0;
  errors[1].translation_m = 0.07;
  errors[1].rotation_deg = 1.5;
  StatusOr<RelativeErrorSummary> s = SummarizeRelativeErrors(errors);
  ASSERT_TRUE(s.ok());
  EXPECT_DOUBLE_EQ(s->translation_pct, 100.0 * 0.08 / 4.0);
  EXPECT_DOUBLE_EQ(s->rotation_deg_per_m, 2.0 / 4.0);
  EXPECT_DOUBLE_EQ(s->translation_m.rmse, std::sqrt((0.01 * 0.01 + 0.07 * 0.07) / 2));

  EXPECT_FALSE(SummarizeRelativeErrors({}).ok());
  std::vector<RelativeError> still(3);
  StatusOr<RelativeErrorSummary> undefined = SummarizeRelativeErrors(still);
  ASSERT_FALSE(undefined.ok());
  EXPECT_NE(undefined.status().message().find("does not move"), std::string::npos);
}

TEST(TrajectoryMetrics, LengthAndEndpointErrorsNeedAMovingGroundTruth) {
  const PoseList gt = Poses(testing::StraightLine(11));  // 10 m.
  const PoseList est = Poses(testing::Scaled(testing::StraightLine(11), 1.05));
  EXPECT_NEAR(*LengthErrorPct(est, gt), 5.0, 1e-12);
  EXPECT_NEAR(*EndpointErrorPct(est, gt), 5.0, 1e-12);  // 0.5 m off after 10 m.

  const PoseList still(4, Eigen::Isometry3d::Identity());
  StatusOr<double> length = LengthErrorPct(est, still);
  ASSERT_FALSE(length.ok());
  EXPECT_NE(length.status().message().find("ground-truth path has length 0 m"), std::string::npos)
      << length.status().message();
  EXPECT_FALSE(EndpointErrorPct(est, still).ok());
  EXPECT_FALSE(EndpointErrorPct({}, {}).ok());
}

}  // namespace
}  // namespace sightline
