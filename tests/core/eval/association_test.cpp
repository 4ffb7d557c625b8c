#include "core/eval/association.h"

#include <gtest/gtest.h>

#include "tests/core/eval/eval_test_util.h"

namespace sightline {
namespace {

TEST(Association, ByTimestampPairsWithinToleranceAndDropsTheRest) {
  const Trajectory gt = testing::StraightLine(20);  // t = 0.0, 0.1, ... 1.9 s.
  Trajectory est;
  est.Add(0.005, Eigen::Isometry3d::Identity());  // -> gt 0
  est.Add(0.31, Eigen::Isometry3d::Identity());   // -> gt 3 (0.01 s off)
  est.Add(0.55, Eigen::Isometry3d::Identity());   // 0.05 s from both neighbours: dropped
  est.Add(1.9, Eigen::Isometry3d::Identity());    // -> gt 19
  est.Add(5.0, Eigen::Isometry3d::Identity());    // after the ground truth: dropped
  StatusOr<AssociatedPoses> a = AssociateByTimestamp(est, gt, 0.02);
  ASSERT_TRUE(a.ok()) << a.status().ToString();
  ASSERT_EQ(a->size(), 3u);
  EXPECT_DOUBLE_EQ(a->ground_truth[0].time_s, 0.0);
  EXPECT_DOUBLE_EQ(a->ground_truth[1].time_s, 0.1 * 3);
  EXPECT_DOUBLE_EQ(a->ground_truth[2].time_s, 0.1 * 19);
  EXPECT_DOUBLE_EQ(a->estimate[1].time_s, 0.31);
  EXPECT_EQ(a->unmatched_estimate, 2u);
  EXPECT_EQ(a->unmatched_ground_truth, 17u);
}

TEST(Association, ByTimestampUsesEachGroundTruthPoseOnce) {
  const Trajectory gt = testing::StraightLine(5);
  Trajectory est;
  est.Add(0.198, Eigen::Isometry3d::Identity());
  est.Add(0.201, Eigen::Isometry3d::Identity());  // Nearer to gt 2: it wins.
  StatusOr<AssociatedPoses> a = AssociateByTimestamp(est, gt, 0.02);
  ASSERT_TRUE(a.ok());
  ASSERT_EQ(a->size(), 1u);
  EXPECT_DOUBLE_EQ(a->estimate[0].time_s, 0.201);
  EXPECT_EQ(a->unmatched_estimate, 1u);
}

TEST(Association, ByTimestampRejectsDecreasingTimes) {
  Trajectory est;
  est.Add(1.0, Eigen::Isometry3d::Identity());
  est.Add(0.5, Eigen::Isometry3d::Identity());
  StatusOr<AssociatedPoses> a = AssociateByTimestamp(est, testing::StraightLine(5), 0.02);
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.status().message().find("estimate timestamps must not decrease"), std::string::npos)
      << a.status().message();
}

TEST(Association, ByIndexRequiresEqualLength) {
  StatusOr<AssociatedPoses> a =
      AssociateByIndex(testing::StraightLine(7), testing::StraightLine(9));
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.status().message().find("estimate has 7 poses and the ground truth 9"),
            std::string::npos)
      << a.status().message();
}

TEST(Association, ByIndexIgnoresTimestamps) {
  const Trajectory gt = testing::StraightLine(4);
  Trajectory est = testing::StraightLine(4);
  for (TimedPose& p : est.mutable_poses()) p.time_s += 1000;
  StatusOr<AssociatedPoses> a = AssociateByIndex(est, gt);
  ASSERT_TRUE(a.ok());
  ASSERT_EQ(a->size(), 4u);
  EXPECT_DOUBLE_EQ(a->estimate[3].time_s, 1000.3);
  EXPECT_DOUBLE_EQ(a->ground_truth[3].time_s, 0.1 * 3);
}

TEST(Association, ParsesModeNames) {
  EXPECT_EQ(*ParseAssociationMode("time"), AssociationMode::kTimestamp);
  EXPECT_EQ(*ParseAssociationMode("index"), AssociationMode::kIndex);
  EXPECT_FALSE(ParseAssociationMode("nearest").ok());
}

}  // namespace
}  // namespace sightline
