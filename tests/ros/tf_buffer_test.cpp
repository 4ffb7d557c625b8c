// TfBuffer (core/ros/tf_buffer.h): chains through common ancestors, interpolation between the
// samples bracketing a stamp, static transforms at any time, and the lookups it refuses.
#include "core/ros/tf_buffer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sightline {
namespace {

Eigen::Isometry3d Pose(double x, double y, double z, double yaw_rad) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

double Yaw(const Eigen::Isometry3d& pose) {
  return std::atan2(pose.linear()(1, 0), pose.linear()(0, 0));
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// odom -> base_link moving along x and turning; base_link -> arm_base static; arm_base ->
// end_effector moving; odom -> camera a second branch.
void FillTree(TfBuffer& tf) {
  for (int i = 0; i <= 4; ++i) {
    const double t = 10.0 + 0.2 * i;
    tf.Add("odom", "/base_link", t, Pose(1.0 * i, 0, 0, 0.1 * i), false);
    tf.Add("arm_base", "end_effector", t, Pose(0, 0.5, 0.1 * i, 0), false);
  }
  tf.Add("base_link", "arm_base", 0.0, Pose(0.3, 0, 0.2, M_PI / 2), true);
  tf.Add("odom", "camera", 10.0, Pose(0, 0, 1, 0), true);
}

TEST(TfBuffer, InterpolatesTranslationLinearlyAndRotationBySlerp) {
  TfBuffer tf(0.5);
  FillTree(tf);
  StatusOr<Eigen::Isometry3d> exact = tf.Lookup("odom", "base_link", 10.4);
  ASSERT_TRUE(exact.ok()) << exact.status().ToString();
  EXPECT_NEAR(exact->translation().x(), 2.0, 1e-12);
  EXPECT_NEAR(Yaw(*exact), 0.2, 1e-12);
  // A quarter of the way from the sample at 10.4 s to the one at 10.6 s.
  StatusOr<Eigen::Isometry3d> between = tf.Lookup("/odom", "base_link", 10.45);
  ASSERT_TRUE(between.ok()) << between.status().ToString();
  EXPECT_NEAR(between->translation().x(), 2.25, 1e-9);
  EXPECT_NEAR(Yaw(*between), 0.225, 1e-9);
}

TEST(TfBuffer, ChainsThroughStaticAndDynamicEdgesAndCommonAncestors) {
  TfBuffer tf(0.5);
  FillTree(tf);
  const double t = 10.3;
  const Eigen::Isometry3d odom_from_base = Pose(1.5, 0, 0, 0.15);
  const Eigen::Isometry3d base_from_arm = Pose(0.3, 0, 0.2, M_PI / 2);
  const Eigen::Isometry3d arm_from_ee = Pose(0, 0.5, 0.15, 0);
  StatusOr<Eigen::Isometry3d> down = tf.Lookup("odom", "end_effector", t);
  ASSERT_TRUE(down.ok()) << down.status().ToString();
  EXPECT_TRUE(down->isApprox(odom_from_base * base_from_arm * arm_from_ee, 1e-9));
  // Up the tree: the inverse.
  StatusOr<Eigen::Isometry3d> up = tf.Lookup("end_effector", "odom", t);
  ASSERT_TRUE(up.ok());
  EXPECT_TRUE(up->isApprox(down->inverse(), 1e-9));
  // Across branches through the common ancestor odom: camera -> end_effector.
  StatusOr<Eigen::Isometry3d> across = tf.Lookup("camera", "end_effector", t);
  ASSERT_TRUE(across.ok()) << across.status().ToString();
  EXPECT_TRUE(across->isApprox(Pose(0, 0, 1, 0).inverse() * *down, 1e-9));
  // Static edges hold at any time; a frame to itself is the identity.
  StatusOr<Eigen::Isometry3d> fixed = tf.Lookup("base_link", "arm_base", 1e6);
  ASSERT_TRUE(fixed.ok());
  EXPECT_TRUE(fixed->isApprox(base_from_arm, 1e-12));
  EXPECT_TRUE(tf.Lookup("odom", "odom", 0.0)->isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_TRUE(tf.HasFrame("/arm_base"));
  EXPECT_FALSE(tf.HasFrame("map"));
}

TEST(TfBuffer, RefusesStampsOutsideTheSamplesOrInAGapNamingFramesAndStamp) {
  TfBuffer tf(0.5);
  tf.Add("odom", "base_link", 10.0, Pose(0, 0, 0, 0), false);
  tf.Add("odom", "base_link", 10.4, Pose(1, 0, 0, 0), false);
  tf.Add("odom", "base_link", 11.0, Pose(2, 0, 0, 0), false);  // 0.6 s after the last.
  tf.Add("base_link", "end_effector", 0, Pose(0, 0, 1, 0), true);
  EXPECT_TRUE(tf.Lookup("odom", "end_effector", 10.2).ok());
  StatusOr<Eigen::Isometry3d> gap = tf.Lookup("odom", "end_effector", 10.7);
  ASSERT_FALSE(gap.ok());
  EXPECT_EQ(gap.status().code(), StatusCode::kOutOfRange);
  const std::string& g = gap.status().message();
  EXPECT_TRUE(Contains(g, "tf odom -> end_effector at 10.700 s")) << g;
  EXPECT_TRUE(Contains(g, "odom -> base_link")) << g;
  EXPECT_TRUE(Contains(g, "0.600 s apart")) << g;
  StatusOr<Eigen::Isometry3d> late = tf.Lookup("odom", "base_link", 11.5);
  ASSERT_FALSE(late.ok());
  EXPECT_EQ(late.status().code(), StatusCode::kOutOfRange);
  EXPECT_TRUE(Contains(late.status().message(), "11.500 s")) << late.status().message();
  EXPECT_TRUE(Contains(late.status().message(), "from 10.000 s to 11.000 s"))
      << late.status().message();
  StatusOr<Eigen::Isometry3d> early = tf.Lookup("odom", "base_link", 9.99);
  EXPECT_EQ(early.status().code(), StatusCode::kOutOfRange);
  // A wider gap allowed: interpolated.
  TfBuffer wide(1.0);
  wide.Add("odom", "base_link", 10.4, Pose(1, 0, 0, 0), false);
  wide.Add("odom", "base_link", 11.0, Pose(2, 0, 0, 0), false);
  StatusOr<Eigen::Isometry3d> in_gap = wide.Lookup("odom", "base_link", 10.7);
  ASSERT_TRUE(in_gap.ok());
  EXPECT_NEAR(in_gap->translation().x(), 1.5, 1e-9);
}

TEST(TfBuffer, UnknownAndUnconnectedFramesAreNamed) {
  TfBuffer tf;
  tf.Add("odom", "base_link", 1.0, Pose(0, 0, 0, 0), false);
  tf.Add("map", "marker", 1.0, Pose(0, 0, 0, 0), true);
  StatusOr<Eigen::Isometry3d> unknown = tf.Lookup("odom", "end_effector", 1.0);
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.status().code(), StatusCode::kNotFound);
  EXPECT_TRUE(Contains(unknown.status().message(), "'end_effector'")) << unknown.status().message();
  StatusOr<Eigen::Isometry3d> apart = tf.Lookup("base_link", "marker", 1.0);
  ASSERT_FALSE(apart.ok());
  EXPECT_TRUE(Contains(apart.status().message(), "not connected")) << apart.status().message();
  EXPECT_EQ(tf.Frames(), (std::vector<std::string>{"base_link", "map", "marker", "odom"}));
}

}  // namespace
}  // namespace sightline
