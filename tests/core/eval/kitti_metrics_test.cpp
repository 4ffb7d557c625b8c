#include "core/eval/kitti_metrics.h"

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

TEST(KittiMetrics, ParsesSegmentLengths) {
  EXPECT_EQ(*ParseSegmentLengths("5,10,20,40"), (std::vector<double>{5, 10, 20, 40}));
  EXPECT_EQ(*ParseSegmentLengths("2.5 7"), (std::vector<double>{2.5, 7}));
  EXPECT_EQ(*ParseSegmentLengths("kitti"), KittiSegmentLengthsM());
  EXPECT_EQ(KittiSegmentLengthsM().front(), 100);
  EXPECT_EQ(KittiSegmentLengthsM().back(), 800);
  for (const char* bad : {"", "5,x", "5,-1", "0", "nan"}) {
    StatusOr<std::vector<double>> l = ParseSegmentLengths(bad);
    EXPECT_FALSE(l.ok()) << bad;
  }
  EXPECT_NE(ParseSegmentLengths("5,x").status().message().find("'x'"), std::string::npos);
}

TEST(KittiMetrics, ScaleDriftOfOnePercentGivesOnePercent) {
  const PoseList gt = Poses(testing::StraightLine(61));  // 60 m, poses 1 m apart.
  const PoseList est = Poses(testing::Scaled(testing::StraightLine(61), 1.01));
  StatusOr<KittiErrors> k = ComputeKittiErrors(est, gt, {5, 10, 20, 40}, 1);
  ASSERT_TRUE(k.ok()) << k.status().ToString();
  // Segments starting at 0..55, 0..50, 0..40, 0..20.
  EXPECT_EQ(k->segments.size(), 56u + 51u + 41u + 21u);
  ASSERT_EQ(k->per_length.size(), 4u);
  EXPECT_EQ(k->per_length[3].segments, 21u);
  EXPECT_NEAR(k->translation_error_pct, 1.0, 1e-9);
  EXPECT_NEAR(k->rotation_error_deg_per_100m, 0.0, 1e-9);
  for (const SegmentLengthSummary& s : k->per_length) {
    EXPECT_NEAR(s.translation_error_pct, 1.0, 1e-9);
  }
}

TEST(KittiMetrics, RollDriftPerMetreGivesRotationErrorOnly) {
  // Each metre the estimate rolls 0.01 rad more about the direction of travel; positions stay
  // exact, so t_err = 0 and r_err = 0.01 rad/m = 57.2958 deg/100 m.
  const double drift_rad_per_m = 0.01;
  const PoseList gt = Poses(testing::StraightLine(41));
  PoseList est = gt;
  for (size_t i = 0; i < est.size(); ++i) {
    est[i].linear() =
        Eigen::AngleAxisd(drift_rad_per_m * i, Eigen::Vector3d::UnitX()).toRotationMatrix();
  }
  StatusOr<KittiErrors> k = ComputeKittiErrors(est, gt, {5, 10, 20}, 1);
  ASSERT_TRUE(k.ok());
  EXPECT_NEAR(k->translation_error_pct, 0.0, 1e-9);
  EXPECT_NEAR(k->rotation_error_deg_per_100m, drift_rad_per_m * 180 / std::numbers::pi * 100, 1e-9);
}

TEST(KittiMetrics, StepSkipsFirstFramesAsTheDevkitDoes) {
  const PoseList gt = Poses(testing::StraightLine(61));
  StatusOr<KittiErrors> k = ComputeKittiErrors(gt, gt, {5}, 10);
  ASSERT_TRUE(k.ok());
  ASSERT_EQ(k->segments.size(), 6u);  // First frames 0, 10, ..., 50.
  EXPECT_EQ(k->segments[5].first_frame, 50u);
  EXPECT_EQ(k->segments[5].last_frame, 55u);
  EXPECT_EQ(k->translation_error_pct, 0.0);
}

TEST(KittiMetrics, NoSegmentFittingIsAnErrorNamingTheLengths) {
  const PoseList gt = Poses(testing::StraightLine(4));  // 3 m.
  StatusOr<KittiErrors> k = ComputeKittiErrors(gt, gt, {5, 10}, 1);
  ASSERT_FALSE(k.ok());
  EXPECT_NE(k.status().message().find("path is 3 m long"), std::string::npos)
      << k.status().message();
  EXPECT_NE(k.status().message().find("shortest segment length is 5 m"), std::string::npos);
  EXPECT_FALSE(ComputeKittiErrors(gt, gt, {1}, 0).ok());
  EXPECT_FALSE(ComputeKittiErrors(gt, PoseList(3), {1}, 1).ok());
}

}  // namespace
}  // namespace sightline
