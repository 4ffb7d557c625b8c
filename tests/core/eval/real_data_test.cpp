// The evaluation on the real ground truth of kitti_clip1 (camera frames, 59.86 m) and
// tum_fr1_desk (motion capture, z up).
#include <gtest/gtest.h>

#include "core/common/text_file.h"
#include "core/eval/evaluation.h"
#include "core/eval/subsample_sweep.h"
#include "core/eval/trajectory_file.h"
#include "tests/core/eval/eval_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

EvaluationOptions Align(const std::string& mode) {
  EvaluationOptions options;
  options.align = mode;
  return options;
}

TEST(EvalRealData, KittiClipAgainstItselfIsZero) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  StatusOr<Trajectory> gt = ReadTrajectoryFile(JoinPath(dir, "poses.txt"));
  ASSERT_TRUE(gt.ok()) << gt.status().ToString();
  StatusOr<TrajectoryErrors> e = EvaluateTrajectory(*gt, *gt, EvaluationOptions());
  ASSERT_TRUE(e.ok()) << e.status().ToString();
  EXPECT_NEAR(e->ground_truth_length_m, 59.86, 0.01);
  EXPECT_EQ(e->pairs, gt->size());
  for (const auto& [key, value] : AccuracyFigures(*e)) {
    if (key != "pairs") EXPECT_NEAR(value, 0.0, 1e-9) << key;
  }
}

TEST(EvalRealData, KittiClipWithOnePercentScaleDrift) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  StatusOr<Trajectory> gt = ReadTrajectoryFile(JoinPath(dir, "poses.txt"));
  ASSERT_TRUE(gt.ok());
  // Through a file, as `sightline-cli eval` would read an estimate.
  const std::string estimate_path = testing::TempDir("eval_real") + "/drift.txt";
  ASSERT_TRUE(WriteKittiTrajectory(testing::Scaled(*gt, 1.01), estimate_path).ok());
  StatusOr<Trajectory> est = ReadTrajectoryFile(estimate_path);
  ASSERT_TRUE(est.ok());

  StatusOr<TrajectoryErrors> none = EvaluateTrajectory(*est, *gt, Align("none"));
  ASSERT_TRUE(none.ok()) << none.status().ToString();
  EXPECT_NEAR(none->length_error_pct, 1.0, 1e-6);
  // The clip is nearly straight and starts at the origin, so the end is ~1 % of the path off.
  EXPECT_NEAR(none->endpoint_error_pct, 1.0, 0.05);
  // A segment ends at the first pose at least L along the path (~1.2 m apart here), so its
  // displacement, and with it the error, is up to a step more than 1 % of L.
  ASSERT_TRUE(none->kitti.has_value());
  EXPECT_GE(none->kitti->translation_error_pct, 1.0 - 1e-6);
  EXPECT_LT(none->kitti->translation_error_pct, 1.25);
  EXPECT_LT(none->kitti->rotation_error_deg_per_100m, 1e-3);
  EXPECT_NEAR(none->rpe.translation_pct, 1.0, 0.01);

  StatusOr<TrajectoryErrors> sim3 = EvaluateTrajectory(*est, *gt, Align("sim3"));
  ASSERT_TRUE(sim3.ok());
  EXPECT_NEAR(sim3->ground_truth_from_estimate.scale, 1 / 1.01, 1e-7);
  EXPECT_LT(sim3->ate.rmse, 1e-6);
}

TEST(EvalRealData, TumDeskGroundTruthSurvivesARigidMoveAndAClockOffset) {
  SIGHTLINE_REQUIRE_DATA(dir, "tum_fr1_desk");
  StatusOr<Trajectory> gt = ReadTrajectoryFile(JoinPath(dir, "groundtruth.txt"));
  ASSERT_TRUE(gt.ok()) << gt.status().ToString();
  StatusOr<TrajectoryErrors> self = EvaluateTrajectory(*gt, *gt, EvaluationOptions());
  ASSERT_TRUE(self.ok()) << self.status().ToString();
  EXPECT_LT(self->ate.rmse, 1e-9);
  EXPECT_EQ(self->pairs, gt->size());

  Eigen::Isometry3d moved = Eigen::Isometry3d::Identity();
  moved.linear() =
      Eigen::AngleAxisd(1.0, Eigen::Vector3d(0.2, 0.3, 1).normalized()).toRotationMatrix();
  moved.translation() = Eigen::Vector3d(-3, 4, 0.5);
  Trajectory est = SubsampleTrajectory(testing::Transformed(*gt, moved), 3);
  for (TimedPose& p : est.mutable_poses()) p.time_s += 0.001;  // GT poses are >= 5.8 ms apart.
  StatusOr<TrajectoryErrors> e = EvaluateTrajectory(est, *gt, EvaluationOptions());
  ASSERT_TRUE(e.ok()) << e.status().ToString();
  EXPECT_EQ(e->pairs, est.size());
  EXPECT_LT(e->ate.rmse, 1e-9);
  EXPECT_LT(e->rpe.translation_m.max, 1e-9);
  StatusOr<TrajectoryErrors> unaligned = EvaluateTrajectory(est, *gt, Align("none"));
  ASSERT_TRUE(unaligned.ok());
  EXPECT_GT(unaligned->ate.rmse, 1.0);
}

}  // namespace
}  // namespace sightline
