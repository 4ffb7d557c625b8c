#include "core/stereo/motion_gate.h"

#include <gtest/gtest.h>

namespace sightline {
namespace {

MotionCandidate Forward(double metres, int inliers = 200, double residual = 0.3) {
  MotionCandidate c;
  c.estimated = true;
  c.current_from_previous.translation() = Eigen::Vector3d(0, 0, -metres);
  c.inliers = inliers;
  c.residual_px = residual;
  return c;
}

TEST(MotionGate, AcceptsPlausibleMotion) {
  MotionGate gate;
  const GateDecision d = gate.Check(Forward(1.0), 0.1);
  EXPECT_TRUE(d.accepted);
  EXPECT_TRUE(d.reason.empty());
}

TEST(MotionGate, HoldsPoseOnAbsurdMotionWithoutHistory) {
  MotionGate gate;
  const GateDecision d = gate.Check(Forward(100.0), 0.1);  // 1000 m/s.
  EXPECT_FALSE(d.accepted);
  EXPECT_NE(d.reason.find("speed"), std::string::npos);
  EXPECT_NE(d.reason.find("pose held"), std::string::npos);
  EXPECT_TRUE(d.current_from_previous.isApprox(Eigen::Isometry3d::Identity()));
}

TEST(MotionGate, FallsBackToConstantMotionThenHolds) {
  MotionGateOptions options;
  options.max_fallback_frames = 2;
  MotionGate gate(options);
  ASSERT_TRUE(gate.Check(Forward(1.0), 0.1).accepted);
  MotionCandidate failed;
  failed.failure = "RANSAC failed";
  GateDecision d = gate.Check(failed, 0.2);  // Twice the time: twice the motion.
  EXPECT_FALSE(d.accepted);
  EXPECT_NEAR(d.current_from_previous.translation().z(), -2.0, 1e-9);
  EXPECT_NE(d.reason.find("constant motion"), std::string::npos);
  d = gate.Check(failed, 0.1);
  EXPECT_NEAR(d.current_from_previous.translation().z(), -1.0, 1e-9);
  d = gate.Check(failed, 0.1);  // Third in a row: held.
  EXPECT_TRUE(d.current_from_previous.isApprox(Eigen::Isometry3d::Identity()));
}

TEST(MotionGate, RejectsAccelerationResidualAndFewInliers) {
  MotionGate gate;
  ASSERT_TRUE(gate.Check(Forward(1.0), 0.1).accepted);
  EXPECT_NE(gate.Check(Forward(2.0), 0.1).reason.find("acceleration"), std::string::npos);
  EXPECT_NE(gate.Check(Forward(1.0, 200, 5.0), 0.1).reason.find("residual"), std::string::npos);
  EXPECT_NE(gate.Check(Forward(1.0, 5), 0.1).reason.find("inliers"), std::string::npos);
}

TEST(MotionGate, HoldFallbackNeverMoves) {
  MotionGateOptions options;
  options.fallback = "hold";
  MotionGate gate(options);
  ASSERT_TRUE(gate.Check(Forward(1.0), 0.1).accepted);
  EXPECT_TRUE(gate.Check(Forward(100.0), 0.1)
                  .current_from_previous.isApprox(Eigen::Isometry3d::Identity()));
}

}  // namespace
}  // namespace sightline
