#include "core/mapping/manhattan_rotation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/mapping/pose2d.h"

namespace sightline {
namespace {

WallSegment Line(double angle_deg, double length_m = 2.0, int inliers = 60) {
  WallSegment line;
  line.angle_rad = WrapHalfTurn(DegToRad(angle_deg));
  line.length_m = length_m;
  line.inliers = inliers;
  return line;
}

OdometryIncrement Turn(double deg, double forward_m = 0.05) {
  OdometryIncrement step;
  step.valid = true;
  step.heading_change_rad = DegToRad(deg);
  step.translation_in_previous_base = Eigen::Vector2d(forward_m, 0);
  return step;
}

TEST(ManhattanAngle, FourThetaAveragingAcrossTheWrap) {
  const ManhattanRotationOptions options;
  // 44.5 deg and 45.5 deg (= -44.5 deg modulo 90) average to 45 deg, i.e. the wrap, not 0.
  ManhattanMeasurement m = MeasureManhattanAngle({Line(44.5), Line(45.5)}, options);
  ASSERT_TRUE(m.valid);
  EXPECT_NEAR(std::abs(RadToDeg(m.angle_rad)), 45.0, 1e-9);
  // -44.6 (= 45.4), 44.8 and 134.6 (= 44.6) deg: mean 44.93 deg.
  m = MeasureManhattanAngle({Line(-44.6), Line(44.8), Line(134.6)}, options);
  ASSERT_TRUE(m.valid);
  EXPECT_NEAR(std::abs(RadToDeg(m.angle_rad)), 44.9333, 1e-3);
  EXPECT_EQ(m.voting_lines, 3);
  // Perpendicular walls agree: 10 deg and 100 deg give 10 deg.
  m = MeasureManhattanAngle({Line(10), Line(100), Line(-80)}, options);
  ASSERT_TRUE(m.valid);
  EXPECT_NEAR(RadToDeg(m.angle_rad), 10.0, 1e-9);
  EXPECT_NEAR(m.concentration, 1.0, 1e-12);
  EXPECT_EQ(m.voting_lines, 3);
}

TEST(ManhattanAngle, WeightedByLength) {
  const ManhattanRotationOptions options;
  // 2 deg (3 m) and 93 deg (= 3 deg, 1 m): (3 x 2 + 1 x 3) / 4 = 2.25 deg.
  const ManhattanMeasurement m = MeasureManhattanAngle({Line(2, 3.0), Line(93, 1.0)}, options);
  ASSERT_TRUE(m.valid);
  EXPECT_NEAR(RadToDeg(m.angle_rad), 2.25, 0.01);
  EXPECT_NEAR(m.weight_m, 4.0, 1e-12);
}

TEST(ManhattanAngle, MedianAndTrimDropAWallMergedWithADoor) {
  // Two true walls at 0 deg and a 1.3 m line at -5.9 deg (a wall merged with a recessed door):
  // the weighted median is 0 and the tilted line is trimmed.
  const ManhattanRotationOptions options;
  const ManhattanMeasurement m = MeasureManhattanAngle(
      {Line(0.2, 1.0), Line(-0.2, 0.6), Line(89.8, 0.6), Line(-5.9, 1.3)}, options);
  ASSERT_TRUE(m.valid);
  EXPECT_NEAR(RadToDeg(m.angle_rad), 0.0, 0.1);
  EXPECT_EQ(m.voting_lines, 3);
  EXPECT_EQ(m.rejected_lines, 1);
}

TEST(ManhattanAngle, ShortOrSparseLinesDoNotVoteAndDisagreementIsInvalid) {
  const ManhattanRotationOptions options;
  EXPECT_FALSE(MeasureManhattanAngle({}, options).valid);
  EXPECT_FALSE(MeasureManhattanAngle({Line(5, 0.1)}, options).valid);
  EXPECT_FALSE(MeasureManhattanAngle({Line(5, 2.0, 3)}, options).valid);
  // A box face at 30 deg beside a wall at 0 deg: only lines near the best-supported direction
  // (modulo 90) vote, so the diagonal does not pull the mean.
  ManhattanMeasurement m = MeasureManhattanAngle({Line(0, 3.0), Line(30, 1.0)}, options);
  EXPECT_TRUE(m.valid);
  EXPECT_NEAR(RadToDeg(m.angle_rad), 0.0, 1e-9);
  EXPECT_EQ(m.voting_lines, 1);
  EXPECT_EQ(m.rejected_lines, 1);
  // With an expected direction, lines far from it do not vote at all.
  m = MeasureManhattanAngle({Line(30, 3.0)}, options, DegToRad(0));
  EXPECT_FALSE(m.valid);
  EXPECT_EQ(m.rejected_lines, 1);
  // Lines within the gate that spread widely have a low concentration.
  ManhattanRotationOptions strict = options;
  strict.min_concentration = 0.95;
  strict.trim_deg = 45;
  m = MeasureManhattanAngle({Line(0), Line(9), Line(-9)}, strict);
  EXPECT_FALSE(m.valid);
  EXPECT_NEAR(m.concentration, (1 + 2 * std::cos(DegToRad(36))) / 3, 1e-9);
}

// A robot driving through a Manhattan world whose walls run at 12 deg to the world x axis,
// with odometry whose heading drifts by drift_deg per frame.
struct DriveResult {
  double max_error_deg = 0;
  int resets = 0;
};

DriveResult Drive(const ManhattanRotationOptions& options, double drift_deg_per_frame, int frames,
                  bool walls_every_frame) {
  ManhattanRotation rotation(options);
  const double alpha = DegToRad(12);
  rotation.Restart(0.3);
  double truth = 0.3;
  std::mt19937 rng(4);
  std::normal_distribution<double> noise(0.0, DegToRad(0.3));
  DriveResult result;
  for (int k = 0; k < frames; ++k) {
    const double turn = (k % 100 >= 50 && k % 100 < 60) ? DegToRad(9) : 0.0;  // 90 deg turns.
    if (k > 0) truth = WrapAngle(truth + turn);
    std::vector<WallSegment> lines;
    if (walls_every_frame || k % 3 == 0) {
      // A wall along the reference direction and, sometimes, a perpendicular one; seen in the
      // base frame at (wall - heading).
      lines.push_back(Line(RadToDeg(alpha - truth + noise(rng)), 2.5));
      if (k % 2 == 0) lines.push_back(Line(RadToDeg(alpha + M_PI / 2 - truth + noise(rng)), 1.5));
    }
    const OdometryIncrement step =
        k == 0 ? OdometryIncrement() : Turn(RadToDeg(turn) + drift_deg_per_frame);
    const RotationEstimate e = rotation.Update(lines, step);
    result.max_error_deg =
        std::max(result.max_error_deg, std::abs(RadToDeg(WrapAngle(e.heading_rad - truth))));
  }
  result.resets = rotation.resets();
  return result;
}

TEST(ManhattanRotation, CorrectionBoundsHeadingDriftThroughTurns) {
  const ManhattanRotationOptions options;
  const DriveResult corrected = Drive(options, 0.1, 600, true);
  EXPECT_LT(corrected.max_error_deg, 1.0);
  EXPECT_EQ(corrected.resets, 0);
  ManhattanRotationOptions off = options;
  off.enabled = false;
  const DriveResult dead_reckoning = Drive(off, 0.1, 600, true);
  EXPECT_GT(dead_reckoning.max_error_deg, 30.0);  // 0.1 deg x 600 frames drifts 60 deg.
}

TEST(ManhattanRotation, FramesWithoutWallsFallBackToDeadReckoning) {
  const DriveResult sparse = Drive(ManhattanRotationOptions(), 0.1, 600, false);
  EXPECT_LT(sparse.max_error_deg, 1.5);  // Two frames of drift at most between corrections.
  EXPECT_EQ(sparse.resets, 0);
}

TEST(ManhattanRotation, OneWallIsEnough) {
  ManhattanRotation rotation;
  rotation.Restart(0);
  RotationEstimate e = rotation.Update({Line(30)}, OdometryIncrement());
  EXPECT_EQ(e.status, "reference set");
  EXPECT_TRUE(e.reference_set);
  // Odometry says 2 deg left, the single wall says the robot did not turn.
  e = rotation.Update({Line(30)}, Turn(2));
  EXPECT_TRUE(e.corrected);
  EXPECT_NEAR(RadToDeg(e.heading_rad), 0.0, 1e-9);
  EXPECT_NEAR(RadToDeg(e.predicted_heading_rad), 2.0, 1e-9);
  // Turning 90 deg left in 10 deg steps (odometry over-reports 0.3 deg per step) while the
  // same wall stays in view: the wall keeps the heading exact.
  for (int k = 1; k <= 9; ++k) e = rotation.Update({Line(30 - 10 * k)}, Turn(10.3, 0.0));
  EXPECT_TRUE(e.corrected);
  EXPECT_NEAR(RadToDeg(e.heading_rad), 90.0, 1e-6);
}

TEST(ManhattanRotation, NoWallsNeverResets) {
  ManhattanRotation rotation;
  for (int k = 0; k < 500; ++k) {
    const RotationEstimate e = rotation.Update({}, Turn(0.5));
    EXPECT_FALSE(e.reset);
    EXPECT_EQ(e.status, "no walls: dead reckoning");
  }
  EXPECT_EQ(rotation.resets(), 0);
  EXPECT_NEAR(RadToDeg(rotation.heading_rad()), WrapAngle(DegToRad(250)) * 180 / M_PI, 1e-6);
}

TEST(ManhattanRotation, LargeJumpResetsOnceNotAStorm) {
  ManhattanRotationOptions options;
  ManhattanRotation rotation(options);
  rotation.Update({Line(0)}, OdometryIncrement());
  // Odometry jumps 120 deg in one frame: reset with a reason.
  RotationEstimate e = rotation.Update({Line(5)}, Turn(120));
  EXPECT_TRUE(e.reset);
  EXPECT_NE(e.reset_reason.find("turned 120.0 deg"), std::string::npos) << e.reset_reason;
  EXPECT_EQ(e.status, "reference set");
  // More jumps within the cooldown do not reset again.
  for (int k = 0; k < options.reset_cooldown_frames - 2; ++k) {
    e = rotation.Update({Line(5)}, Turn(k % 2 == 0 ? 100 : -100));
    EXPECT_FALSE(e.reset) << k;
  }
  EXPECT_EQ(rotation.resets(), 1);
  // A translation jump after the cooldown resets.
  for (int k = 0; k < 5; ++k) rotation.Update({Line(5)}, Turn(0));
  e = rotation.Update({Line(5)}, Turn(0, 3.0));
  EXPECT_TRUE(e.reset);
  EXPECT_NE(e.reset_reason.find("moved 3.00 m"), std::string::npos) << e.reset_reason;
}

TEST(ManhattanRotation, PersistentDisagreementResetsTheReference) {
  ManhattanRotationOptions options;
  ManhattanRotation rotation(options);
  rotation.Update({Line(0)}, OdometryIncrement());
  // From now on the walls run at 30 deg to the reference: every frame is gated, and after
  // reset_disagreement_frames frames the reference is re-set to the new walls.
  RotationEstimate e;
  int frame_of_reset = -1;
  for (int k = 0; k < 40; ++k) {
    e = rotation.Update({Line(30)}, Turn(0));
    if (e.reset) {
      frame_of_reset = k;
      EXPECT_EQ(e.status, "reference re-set");
      EXPECT_NE(e.reset_reason.find("disagreed"), std::string::npos);
    } else if (frame_of_reset < 0) {
      EXPECT_TRUE(e.gated);
    }
  }
  EXPECT_EQ(frame_of_reset, options.reset_disagreement_frames - 1);
  EXPECT_EQ(rotation.resets(), 1);
  EXPECT_TRUE(e.corrected);  // The new reference agrees with the walls.
}

TEST(ManhattanRotation, ClassifiesLinesAgainstTheReference) {
  ManhattanRotation rotation;
  RotationEstimate e = rotation.Update({Line(10)}, OdometryIncrement());
  std::vector<WallSegment> lines = {Line(10), Line(100), Line(-80), Line(55)};
  rotation.Classify(e, &lines);
  EXPECT_EQ(lines[0].direction_class, 0);
  EXPECT_EQ(lines[1].direction_class, 1);
  EXPECT_EQ(lines[2].direction_class, 1);
  EXPECT_EQ(lines[3].direction_class, -1);
}

TEST(DeadReckoning, IncrementsInThePreviousBaseFrame) {
  DeadReckoning odometry;
  EXPECT_FALSE(odometry.Update(Pose2d{1, 2, M_PI / 2}).valid);
  const OdometryIncrement step = odometry.Update(Pose2d{1, 3, M_PI / 2 + 0.1});
  ASSERT_TRUE(step.valid);
  EXPECT_NEAR(step.translation_in_previous_base.x(), 1.0, 1e-12);  // Forward.
  EXPECT_NEAR(step.translation_in_previous_base.y(), 0.0, 1e-12);
  EXPECT_NEAR(step.heading_change_rad, 0.1, 1e-12);
  EXPECT_FALSE(odometry.Update(std::nullopt).valid);
  EXPECT_FALSE(odometry.Update(Pose2d{0, 0, 0}).valid);  // The chain restarts.
}

}  // namespace
}  // namespace sightline
