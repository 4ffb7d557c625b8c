// The arm's streamed pose: the parser takes well-formed arm_pose lines and refuses everything
// else naming the member; the buffer drops poses above the rate limit or out of order and
// interpolates the pose at a camera stamp through the clock offset.
#include "core/button/arm_pose_stream.h"

#include <gtest/gtest.h>

namespace sightline {
namespace {

const char* kGood =
    R"({"type":"arm_pose","stamp":12.5,"position_m":[0.4,-0.1,0.3],)"
    R"("quaternion_xyzw":[0,0,0.7071068,0.7071068],"joints":[0.1,0.2],"note":"x","ok":true})";

TEST(ArmPoseStream, AWellFormedLineGivesThePose) {
  StatusOr<ArmPoseMessage> m = ParseArmPoseLine(kGood);
  ASSERT_TRUE(m.ok()) << m.status().ToString();
  EXPECT_DOUBLE_EQ(m->stamp_s, 12.5);
  EXPECT_TRUE(m->base_from_end_effector.translation().isApprox(Eigen::Vector3d(0.4, -0.1, 0.3)));
  const Eigen::Vector3d x = m->base_from_end_effector.linear() * Eigen::Vector3d::UnitX();
  EXPECT_TRUE(x.isApprox(Eigen::Vector3d::UnitY(), 1e-6)) << x.transpose();  // 90 deg about z.
  EXPECT_EQ(m->joints.size(), 2u);
}

TEST(ArmPoseStream, HostileOrBrokenLinesAreRefusedNamingTheMember) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "one JSON object"},
      {"[1,2]", "one JSON object"},
      {R"({"type":"target","stamp":1,"position_m":[0,0,0],"quaternion_xyzw":[0,0,0,1]})", "type"},
      {R"({"type":"arm_pose","position_m":[0,0,0],"quaternion_xyzw":[0,0,0,1]})", "stamp"},
      {R"({"type":"arm_pose","stamp":-1,"position_m":[0,0,0],"quaternion_xyzw":[0,0,0,1]})",
       "stamp"},
      {R"({"type":"arm_pose","stamp":1,"position_m":[0,0],"quaternion_xyzw":[0,0,0,1]})",
       "position_m"},
      {R"({"type":"arm_pose","stamp":1,"position_m":[0,0,1e400],"quaternion_xyzw":[0,0,0,1]})",
       "position_m"},
      {R"({"type":"arm_pose","stamp":1,"position_m":[0,0,0x10],"quaternion_xyzw":[0,0,0,1]})",
       "position_m"},
      {R"({"type":"arm_pose","stamp":1,"position_m":[0,0,50],"quaternion_xyzw":[0,0,0,1]})",
       "max_position_m"},
      {R"({"type":"arm_pose","stamp":1,"position_m":[0,0,0],"quaternion_xyzw":[0,0,0,2]})",
       "quaternion"},
      {R"({"type":"arm_pose","stamp":1,"position_m":[0,0,0],"quaternion_xyzw":[0,0,0,1],)"
       R"("joints":[1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17]})",
       "joints"},
      {R"({"type":"arm_pose","stamp":1,"stamp":2,"position_m":[0,0,0],"quaternion_xyzw":[0,0,0,1]})",
       "duplicate"},
      {R"({"type":"arm_pose","stamp":1,"position_m":[0,0,0],"quaternion_xyzw":[0,0,0,1],"o":{}})",
       "\"o\""},
      {R"({"type":"arm_pose","stamp":1,"position_m":[0,0,0],"quaternion_xyzw":[0,0,0,1]} x)",
       "after the object"},
      {R"({"type":"arm_pose","stamp":1,"position_m":[0,0,0],"quaternion_xyzw":[0,0,0,1])", "'}'"},
  };
  for (const auto& [line, named] : cases) {
    StatusOr<ArmPoseMessage> m = ParseArmPoseLine(line);
    ASSERT_FALSE(m.ok()) << line;
    EXPECT_EQ(m.status().code(), StatusCode::kInvalidArgument) << line;
    EXPECT_NE(m.status().message().find(named), std::string::npos)
        << line << " -> " << m.status().message();
  }
}

ArmPoseMessage Pose(double stamp, double x, double yaw) {
  ArmPoseMessage m;
  m.stamp_s = stamp;
  m.base_from_end_effector =
      Eigen::Translation3d(x, 0, 0) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
  return m;
}

TEST(ArmPoseStream, TheBufferLimitsTheRateAndInterpolatesThroughTheClockOffset) {
  ArmPoseStreamOptions o;
  o.max_rate_hz = 100;
  o.clock_offset_s = 100;  // The arm's clock is 100 s ahead of the camera's.
  ArmPoseBuffer buffer(o);
  EXPECT_TRUE(buffer.Add(Pose(100.00, 0.0, 0.0)));
  EXPECT_FALSE(buffer.Add(Pose(100.005, 0.5, 0.0)));  // Faster than 100 Hz: dropped.
  EXPECT_FALSE(buffer.Add(Pose(99.0, 0.5, 0.0)));     // Older: dropped.
  EXPECT_TRUE(buffer.Add(Pose(100.02, 0.2, 0.2)));
  EXPECT_EQ(buffer.dropped(), 2);
  const std::optional<Eigen::Isometry3d> mid = buffer.At(0.005);  // Camera time.
  ASSERT_TRUE(mid.has_value());
  EXPECT_NEAR(mid->translation().x(), 0.05, 1e-9);
  EXPECT_NEAR(Eigen::AngleAxisd(mid->linear()).angle(), 0.05, 1e-9);
  EXPECT_FALSE(buffer.At(-0.001).has_value());  // Before the first pose: no extrapolation.
  EXPECT_FALSE(buffer.At(0.021).has_value());   // After the last.
  // A stamp within a microsecond of the span's end (rounding of the stamps) gets the end pose.
  ASSERT_TRUE(buffer.At(0.0200004).has_value());
  EXPECT_NEAR(buffer.At(0.0200004)->translation().x(), 0.2, 1e-9);
  EXPECT_TRUE(buffer.Add(Pose(100.2, 0.3, 0.2)));
  EXPECT_FALSE(buffer.At(0.1).has_value());  // Across a 180 ms gap (max_gap_s 50 ms).
}

TEST(ArmPoseStream, AnArmAtExactlyTheRateLimitLosesNoPoseAndItsLinesReadBack) {
  ArmPoseStreamOptions o;
  o.max_rate_hz = 200;
  ArmPoseBuffer buffer(o);
  for (int k = 0; k < 1000; ++k) {
    // Through the line an arm client sends: stamps rounded to microseconds.
    StatusOr<ArmPoseMessage> m = ParseArmPoseLine(ArmPoseLine(Pose(12.3 + 0.005 * k, 0.1, 0.2)));
    ASSERT_TRUE(m.ok()) << m.status().ToString();
    EXPECT_TRUE(buffer.Add(*m)) << k;
  }
  EXPECT_EQ(buffer.dropped(), 0);
  EXPECT_FALSE(KeepsRate(1.0, 1.004, 200));
  EXPECT_TRUE(KeepsRate(1.0, 1.005, 200));
}

}  // namespace
}  // namespace sightline
