#include "core/eval/subsample_sweep.h"

#include <gtest/gtest.h>

#include "tests/core/eval/eval_test_util.h"

namespace sightline {
namespace {

TEST(SubsampleSweep, SubsampleKeepsEveryKthPoseFromTheFirst) {
  const Trajectory t = testing::StraightLine(10);
  const Trajectory every3 = SubsampleTrajectory(t, 3);
  ASSERT_EQ(every3.size(), 4u);  // 0, 3, 6, 9.
  EXPECT_DOUBLE_EQ(every3.poses()[3].world_from_sensor.translation().x(), 9.0);
  EXPECT_EQ(SubsampleTrajectory(t, 1).size(), 10u);
  EXPECT_EQ(SubsampleTrajectory(t, 20).size(), 1u);
}

TEST(SubsampleSweep, TableHasTheSeedsColumns) {
  // On a circle the ground-truth path through every k-th pose shortens with k (chords), as the
  // seed's "Distancia" column does; an estimate 5 % too long gives 5 % at every factor.
  const Trajectory gt = testing::Helix(120, 5.0, 0.0);  // 10 Hz.
  std::vector<SubsampleEstimate> runs;
  for (int k : {1, 2, 5, 10})
    runs.push_back({k, testing::Scaled(SubsampleTrajectory(gt, k), 1.05)});
  StatusOr<std::vector<SubsampleRow>> rows = EvaluateSubsampleSweep(runs, gt, 0.02);
  ASSERT_TRUE(rows.ok()) << rows.status().ToString();
  ASSERT_EQ(rows->size(), 4u);
  for (size_t i = 0; i < rows->size(); ++i) {
    const SubsampleRow& r = (*rows)[i];
    EXPECT_NEAR(r.equivalent_fps, 10.0 / r.factor, 1e-6) << r.factor;
    EXPECT_NEAR(r.length_error_pct, 5.0, 1e-9) << r.factor;
    EXPECT_NEAR(r.estimate_length_m, 1.05 * r.gt_length_m, 1e-9);
    if (i > 0) EXPECT_LT(r.gt_length_m, (*rows)[i - 1].gt_length_m);
  }
  EXPECT_EQ((*rows)[3].pairs, 12u);
  const std::string table = FormatSubsampleTable(*rows);
  EXPECT_NE(table.find("factor"), std::string::npos);
  EXPECT_NE(table.find("error_pct"), std::string::npos);
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 5);
}

TEST(SubsampleSweep, FailsNamingTheFactor) {
  const Trajectory gt = testing::StraightLine(10);
  StatusOr<std::vector<SubsampleRow>> rows =
      EvaluateSubsampleSweep({{1, gt}, {40, SubsampleTrajectory(gt, 40)}}, gt, 0.02);
  ASSERT_FALSE(rows.ok());
  EXPECT_NE(rows.status().message().find("subsampling factor 40: only 1"), std::string::npos)
      << rows.status().message();
  rows = EvaluateSubsampleSweep({{0, gt}}, gt, 0.02);
  ASSERT_FALSE(rows.ok());
  EXPECT_NE(rows.status().message().find("factor 0"), std::string::npos);
}

}  // namespace
}  // namespace sightline
