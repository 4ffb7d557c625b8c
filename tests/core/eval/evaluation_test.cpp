#include "core/eval/evaluation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "core/eval/error_report.h"
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

std::map<std::string, double> Figures(const TrajectoryErrors& errors) {
  std::map<std::string, double> figures;
  for (const auto& [key, value] : AccuracyFigures(errors)) {
    EXPECT_TRUE(std::isfinite(value)) << key;
    figures[key] = value;
  }
  return figures;
}

Eigen::Isometry3d Translation(const Eigen::Vector3d& t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = t;
  return pose;
}

TEST(Evaluation, ConstantOffsetGivesThatAteWithoutAlignmentAndZeroWithSe3) {
  const Trajectory gt = testing::Helix(80);
  const Trajectory est = testing::Transformed(gt, Translation({0.06, 0.0, -0.08}));  // |.| = 0.1
  StatusOr<TrajectoryErrors> none = EvaluateTrajectory(est, gt, Align("none"));
  ASSERT_TRUE(none.ok()) << none.status().ToString();
  EXPECT_NEAR(none->ate.rmse, 0.1, 1e-12);
  EXPECT_NEAR(none->ate.mean, 0.1, 1e-12);
  EXPECT_NEAR(none->ate.median, 0.1, 1e-12);
  EXPECT_NEAR(none->ate.max, 0.1, 1e-12);
  EXPECT_NEAR(none->rpe.translation_m.rmse, 0.0, 1e-12);  // A world offset moves nothing.
  EXPECT_NEAR(none->rpe.rotation_deg.rmse, 0.0, 1e-9);
  EXPECT_NEAR(none->length_error_pct, 0.0, 1e-9);
  EXPECT_NEAR(none->endpoint_error_pct, 100.0 * 0.1 / none->ground_truth_length_m, 1e-9);

  StatusOr<TrajectoryErrors> se3 = EvaluateTrajectory(est, gt, Align("se3"));
  ASSERT_TRUE(se3.ok());
  EXPECT_NEAR(se3->ate.rmse, 0.0, 1e-12);
  EXPECT_NEAR(se3->ate.max, 0.0, 1e-12);
  EXPECT_NEAR(se3->endpoint_error_pct, 0.0, 1e-9);
  EXPECT_TRUE(
      se3->ground_truth_from_estimate.translation.isApprox(Eigen::Vector3d(-0.06, 0, 0.08), 1e-12));
}

TEST(Evaluation, RotationOffsetGivesTheChordOnACircle) {
  // A circle of radius 5 about the z axis, the estimate's world rotated by 10 deg about z: every
  // position is off by the chord 2 r sin(theta / 2).
  const double radius = 5.0;
  const double theta = 10.0 * std::numbers::pi / 180;
  const Trajectory gt = testing::Helix(90, radius, 0.0);
  Eigen::Isometry3d rotation = Eigen::Isometry3d::Identity();
  rotation.linear() = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Trajectory est = testing::Transformed(gt, rotation);
  const double chord = 2 * radius * std::sin(theta / 2);

  StatusOr<TrajectoryErrors> none = EvaluateTrajectory(est, gt, Align("none"));
  ASSERT_TRUE(none.ok()) << none.status().ToString();
  EXPECT_NEAR(none->ate.rmse, chord, 1e-12);
  EXPECT_NEAR(none->ate.min, chord, 1e-12);
  EXPECT_NEAR(none->ate.max, chord, 1e-12);
  EXPECT_NEAR(none->rpe.translation_m.rmse, 0.0, 1e-12);
  EXPECT_NEAR(none->rpe.rotation_deg.max, 0.0, 1e-9);

  StatusOr<TrajectoryErrors> se3 = EvaluateTrajectory(est, gt, Align("se3"));
  ASSERT_TRUE(se3.ok());
  EXPECT_NEAR(se3->ate.rmse, 0.0, 1e-12);
  EXPECT_NEAR(RotationAngleRad(se3->ground_truth_from_estimate.rotation), theta, 1e-12);
}

TEST(Evaluation, Sim3RecoversScaleHalfForAnEstimateTwiceTooLarge) {
  const Trajectory gt = testing::Helix(80);
  Eigen::Isometry3d offset = Translation({1, 2, 3});
  offset.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Trajectory est = testing::Transformed(testing::Scaled(gt, 2.0), offset);

  StatusOr<TrajectoryErrors> sim3 = EvaluateTrajectory(est, gt, Align("sim3"));
  ASSERT_TRUE(sim3.ok()) << sim3.status().ToString();
  EXPECT_NEAR(sim3->ground_truth_from_estimate.scale, 0.5, 1e-12);
  EXPECT_NEAR(sim3->ate.rmse, 0.0, 1e-12);
  EXPECT_NEAR(sim3->rpe.translation_m.rmse, 0.0, 1e-12);
  EXPECT_NEAR(sim3->length_error_pct, 0.0, 1e-9);
  EXPECT_NEAR(Figures(*sim3).at("scale"), 0.5, 1e-12);

  // Without the scale the same estimate is far off, and its path is twice as long.
  StatusOr<TrajectoryErrors> se3 = EvaluateTrajectory(est, gt, Align("se3"));
  ASSERT_TRUE(se3.ok());
  EXPECT_GT(se3->ate.rmse, 1.0);
  EXPECT_NEAR(se3->length_error_pct, 100.0, 1e-9);
  EXPECT_EQ(Figures(*se3).count("scale"), 0u);
}

TEST(Evaluation, ScaleDriftOfOnePercentGivesOnePercentEverywhere) {
  const Trajectory gt = testing::StraightLine(61);  // 60 m.
  const Trajectory est = testing::Scaled(gt, 1.01);
  StatusOr<TrajectoryErrors> e = EvaluateTrajectory(est, gt, Align("none"));
  ASSERT_TRUE(e.ok()) << e.status().ToString();
  const auto f = Figures(*e);
  EXPECT_NEAR(f.at("length_error_pct"), 1.0, 1e-9);
  EXPECT_NEAR(f.at("endpoint_error_pct"), 1.0, 1e-9);  // 0.6 m off after 60 m.
  EXPECT_NEAR(f.at("rpe_trans_pct"), 1.0, 1e-9);
  EXPECT_NEAR(f.at("rpe_trans_m"), 0.01, 1e-12);
  EXPECT_NEAR(f.at("kitti_t_err_pct"), 1.0, 1e-9);
  EXPECT_NEAR(f.at("kitti_r_err_deg_per_100m"), 0.0, 1e-9);
  EXPECT_NEAR(f.at("ate_max_m"), 0.6, 1e-12);
}

TEST(Evaluation, LateralDriftPerMetreSeparatesSegmentAndLengthErrors) {
  // 2 cm sideways per metre travelled: segments see 2 %, the path is only sqrt(1 + 0.02^2) longer.
  const double drift = 0.02;
  const Trajectory gt = testing::StraightLine(41);
  Trajectory est;
  for (const TimedPose& p : gt.poses()) {
    const double x = p.world_from_sensor.translation().x();
    est.Add(p.time_s, Translation({x, drift * x, 0}));
  }
  EvaluationOptions options = Align("none");
  options.rpe_delta_m = 5;
  StatusOr<TrajectoryErrors> e = EvaluateTrajectory(est, gt, options);
  ASSERT_TRUE(e.ok()) << e.status().ToString();
  const auto f = Figures(*e);
  EXPECT_NEAR(f.at("kitti_t_err_pct"), 100 * drift, 1e-9);
  EXPECT_NEAR(f.at("rpe_trans_pct"), 100 * drift, 1e-9);
  ASSERT_TRUE(e->rpe_over_distance.has_value());
  EXPECT_EQ(e->rpe_over_distance->translation_m.count, 36u);  // Pairs (i, i + 5), i = 0..35.
  EXPECT_NEAR(f.at("length_error_pct"), 100 * (std::sqrt(1 + drift * drift) - 1), 1e-9);
  EXPECT_NEAR(f.at("endpoint_error_pct"), 100 * drift, 1e-9);
}

TEST(Evaluation, RpeDeltaFramesSpacesThePairs) {
  const Trajectory gt = testing::StraightLine(21);
  EvaluationOptions options = Align("none");
  options.rpe_delta_frames = 4;
  StatusOr<TrajectoryErrors> e = EvaluateTrajectory(testing::Scaled(gt, 1.1), gt, options);
  ASSERT_TRUE(e.ok());
  EXPECT_EQ(e->rpe.translation_m.count, 17u);
  EXPECT_NEAR(e->rpe.translation_m.rmse, 0.4, 1e-12);  // 10 % of 4 m.
  EXPECT_NEAR(e->rpe.translation_pct, 10.0, 1e-9);
}

TEST(Evaluation, TrajectoryAgainstItselfIsZeroEverywhere) {
  const Trajectory gt = testing::Helix(120);
  for (const char* mode : {"none", "se3", "sim3"}) {
    StatusOr<TrajectoryErrors> e = EvaluateTrajectory(gt, gt, Align(mode));
    ASSERT_TRUE(e.ok()) << mode << ": " << e.status().ToString();
    for (const auto& [key, value] : Figures(*e)) {
      if (key == "pairs") {
        EXPECT_EQ(value, 120) << mode;
      } else if (key == "scale") {
        EXPECT_NEAR(value, 1.0, 1e-12) << mode;
      } else {
        EXPECT_NEAR(value, 0.0, 1e-9) << mode << " " << key;
      }
    }
  }
}

TEST(Evaluation, AccuracyFiguresHaveTheMetricsJsonKeysInOrder) {
  const Trajectory gt = testing::Helix(120);
  StatusOr<TrajectoryErrors> e = EvaluateTrajectory(gt, gt, Align("sim3"));
  ASSERT_TRUE(e.ok());
  std::vector<std::string> keys;
  for (const auto& [key, value] : AccuracyFigures(*e)) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"ate_rmse_m", "ate_mean_m", "ate_median_m", "ate_max_m",
                                            "rpe_trans_pct", "rpe_rot_deg_per_m", "rpe_trans_m",
                                            "rpe_rot_deg", "length_error_pct", "endpoint_error_pct",
                                            "kitti_t_err_pct", "kitti_r_err_deg_per_100m", "scale",
                                            "pairs"}));
  const std::string json = AccuracyToJson(AccuracyFigures(*e));
  EXPECT_NE(json.find("\"pairs\": 120"), std::string::npos) << json;
  EXPECT_NE(json.find("\"scale\": 1"), std::string::npos) << json;
}

TEST(Evaluation, FiguresThatDoNotFitTheClipAreLeftOutWithANote) {
  const Trajectory gt = testing::StraightLine(4);  // 3 m: no 5 m segment, no 10 m RPE pair.
  EvaluationOptions options = Align("se3");
  options.rpe_delta_m = 10;
  StatusOr<TrajectoryErrors> e = EvaluateTrajectory(testing::Scaled(gt, 1.01), gt, options);
  ASSERT_TRUE(e.ok()) << e.status().ToString();
  const auto f = Figures(*e);
  EXPECT_EQ(f.count("kitti_t_err_pct"), 0u);
  EXPECT_EQ(f.count("rpe_trans_pct"), 0u);
  EXPECT_EQ(f.count("ate_rmse_m"), 1u);
  ASSERT_EQ(e->notes.size(), 2u);
  const std::string table = FormatErrorTable(*e);
  EXPECT_NE(table.find("note: KITTI segment errors left out"), std::string::npos) << table;
  EXPECT_NE(table.find("shorter than eval.rpe_delta_m"), std::string::npos) << table;
}

TEST(Evaluation, TimestampAssociationDropsUnmatchedPoses) {
  const Trajectory gt = testing::Helix(100);  // 10 Hz.
  Trajectory est;
  for (size_t i = 0; i < gt.size(); i += 2) {  // 5 Hz, 4 ms late; every 10th pose missing its GT.
    est.Add(gt.poses()[i].time_s + (i % 10 == 0 ? 0.05 : 0.004), gt.poses()[i].world_from_sensor);
  }
  StatusOr<TrajectoryErrors> e = EvaluateTrajectory(est, gt, Align("se3"));
  ASSERT_TRUE(e.ok()) << e.status().ToString();
  EXPECT_EQ(e->pairs, 40u);
  EXPECT_EQ(e->unmatched_estimate, 10u);
  EXPECT_EQ(e->unmatched_ground_truth, 60u);
  EXPECT_NEAR(e->ate.rmse, 0.0, 1e-12);

  EvaluationOptions by_index = Align("se3");
  by_index.associate = "index";
  StatusOr<TrajectoryErrors> failed = EvaluateTrajectory(est, gt, by_index);
  ASSERT_FALSE(failed.ok());
  EXPECT_NE(failed.status().message().find("equal lengths"), std::string::npos);
}

TEST(Evaluation, FewerThanThreePairsIsAnErrorThatShowsBothTimeSpans) {
  const Trajectory gt = testing::StraightLine(10);
  Trajectory est = testing::StraightLine(10);
  for (TimedPose& p : est.mutable_poses()) p.time_s += 100;
  StatusOr<TrajectoryErrors> e = EvaluateTrajectory(est, gt, EvaluationOptions());
  ASSERT_FALSE(e.ok());
  const std::string& m = e.status().message();
  EXPECT_NE(m.find("only 0 poses associate within 0.02 s (need at least 3)"), std::string::npos)
      << m;
  EXPECT_NE(m.find("t=100.000..100.900 s"), std::string::npos) << m;
  EXPECT_NE(m.find("same clock"), std::string::npos) << m;

  EvaluationOptions by_index;
  by_index.associate = "index";
  e = EvaluateTrajectory(testing::StraightLine(2), testing::StraightLine(2), by_index);
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.status().message().find("only 2 poses"), std::string::npos);
}

TEST(Evaluation, NonFinitePosesAreRejectedByIndexAndTime) {
  const Trajectory gt = testing::StraightLine(10);
  Trajectory est = gt;
  est.mutable_poses()[4].world_from_sensor.translation().y() = std::nan("");
  StatusOr<TrajectoryErrors> e = EvaluateTrajectory(est, gt, EvaluationOptions());
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.status().message().find("estimate pose 4 (t=0.400000 s) is not finite"),
            std::string::npos)
      << e.status().message();
  Trajectory bad_gt = gt;
  bad_gt.mutable_poses()[0].world_from_sensor.linear()(0, 0) = INFINITY;
  e = EvaluateTrajectory(gt, bad_gt, EvaluationOptions());
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.status().message().find("ground-truth pose 0"), std::string::npos);
}

TEST(Evaluation, StillGroundTruthIsAnErrorNotNaN) {
  Trajectory still;
  for (int i = 0; i < 10; ++i) still.Add(0.1 * i, Eigen::Isometry3d::Identity());
  StatusOr<TrajectoryErrors> e =
      EvaluateTrajectory(testing::StraightLine(10), still, Align("none"));
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.status().message().find("ground truth does not move"), std::string::npos)
      << e.status().message();
  EXPECT_NE(e.status().message().find("% errors are undefined"), std::string::npos);
}

TEST(Evaluation, StillEstimateCannotBeAligned) {
  Trajectory still;
  for (int i = 0; i < 10; ++i) still.Add(0.1 * i, Eigen::Isometry3d::Identity());
  StatusOr<TrajectoryErrors> e =
      EvaluateTrajectory(still, testing::StraightLine(10), Align("sim3"));
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.status().message().find("coincide"), std::string::npos) << e.status().message();
}

TEST(Evaluation, InvalidOptionsNameTheKey) {
  EvaluationOptions options;
  std::string error;
  EXPECT_TRUE(options.IsValid(&error));
  options.segment_lengths_m = "5,ten";
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("eval.segment_lengths_m"), std::string::npos) << error;
  options = EvaluationOptions();
  options.align = "affine";
  StatusOr<TrajectoryErrors> e =
      EvaluateTrajectory(testing::StraightLine(5), testing::StraightLine(5), options);
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.status().message().find("eval.align"), std::string::npos);
  options = EvaluationOptions();
  options.rpe_delta_frames = 5;
  e = EvaluateTrajectory(testing::StraightLine(5), testing::StraightLine(5), options);
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.status().message().find("lower eval.rpe_delta_frames"), std::string::npos);
}

TEST(Evaluation, DescribeTableCoversEveryOptionWithValidDefaults) {
  const auto specs = EvaluationOptions::Describe().Specs();
  std::vector<std::string> keys;
  for (const OptionSpec& s : specs) {
    keys.push_back(s.key);
    EXPECT_FALSE(s.description.empty()) << s.key;
    EXPECT_TRUE(CheckOptionValue(s, s.default_value).ok()) << s.key;
  }
  EXPECT_EQ(keys,
            (std::vector<std::string>{"eval.align", "eval.associate", "eval.max_time_difference_s",
                                      "eval.rpe_delta_frames", "eval.rpe_delta_m",
                                      "eval.segment_lengths_m", "eval.segment_step_frames"}));
}

TEST(Evaluation, KittiAndTumFilesRoundTripExactly) {
  const std::string dir = testing::TempDir("eval_roundtrip");
  const Trajectory gt = testing::Helix(50);
  ASSERT_TRUE(WriteKittiTrajectory(gt, dir + "/poses.txt").ok());
  ASSERT_TRUE(WriteTumTrajectory(gt, dir + "/traj.txt").ok());
  StatusOr<Trajectory> kitti = ReadTrajectoryFile(dir + "/poses.txt");
  StatusOr<Trajectory> tum = ReadTrajectoryFile(dir + "/traj.txt");
  ASSERT_TRUE(kitti.ok() && tum.ok());
  EvaluationOptions by_index = Align("none");
  by_index.associate = "index";  // KITTI files carry no timestamps.
  for (const Trajectory* read : {&*kitti, &*tum}) {
    StatusOr<TrajectoryErrors> e = EvaluateTrajectory(*read, gt, by_index);
    ASSERT_TRUE(e.ok()) << e.status().ToString();
    EXPECT_LT(e->ate.max, 1e-8);
    EXPECT_LT(e->rpe.rotation_deg.max, 1e-6);
    EXPECT_EQ(e->pairs, 50u);
  }
  // Writing what was read gives the same text: the KITTI round trip is exact.
  ASSERT_TRUE(WriteKittiTrajectory(*kitti, dir + "/again.txt").ok());
  StatusOr<Trajectory> again = ReadTrajectoryFile(dir + "/again.txt");
  ASSERT_TRUE(again.ok());
  for (size_t i = 0; i < again->size(); ++i) {
    EXPECT_EQ(again->poses()[i].world_from_sensor.matrix(),
              kitti->poses()[i].world_from_sensor.matrix());
  }
}

}  // namespace
}  // namespace sightline
