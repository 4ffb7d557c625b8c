#include "core/sim/motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/sim/odometry.h"
#include "core/sim/panel_scene.h"

namespace sightline::sim {
namespace {

Scene StraightRouteScene() {
  Scene scene("straight");
  scene.AddMaterial({});
  scene.hints.route = {{0, 0}, {100, 0}};
  return scene;
}

double Yaw(const Eigen::Isometry3d& pose) {
  return std::atan2(pose.linear()(1, 0), pose.linear()(0, 0));
}

TEST(Motion, RobotDrivesTheRouteWithTheCameraMounted) {
  MotionOptions motion;
  motion.speed_mps = 0.5;
  motion.camera_height_m = 0.8;
  motion.camera_tilt_deg = 10;
  auto plan = PlanMotion(StraightRouteScene(), motion, ArmOptions(), 31, 30, 1);
  ASSERT_TRUE(plan.ok()) << plan.status().ToString();
  EXPECT_EQ(plan->kind, "robot");
  EXPECT_NEAR(plan->world_from_body.back().translation().x(), 0.5, 1e-12);  // 1 s at 0.5 m/s.
  const Eigen::Isometry3d camera = plan->WorldFromCamera(0);
  EXPECT_NEAR(camera.translation().z(), 0.8, 1e-12);
  // Optical axis forward and 10 deg down; image y down.
  const Eigen::Vector3d axis = camera.linear().col(2);
  EXPECT_NEAR(axis.x(), std::cos(10 * M_PI / 180), 1e-12);
  EXPECT_NEAR(axis.z(), -std::sin(10 * M_PI / 180), 1e-12);
  EXPECT_LT(camera.linear().col(1).z(), -0.9);
}

TEST(Motion, HandheldWobblesAroundTheRouteAndIsSeeded) {
  MotionOptions motion;
  motion.kind = "handheld";
  motion.speed_mps = 0.4;
  motion.camera_height_m = 1.4;
  motion.shake_m = 0.03;
  auto a = PlanMotion(StraightRouteScene(), motion, ArmOptions(), 90, 30, 7);
  auto b = PlanMotion(StraightRouteScene(), motion, ArmOptions(), 90, 30, 7);
  auto c = PlanMotion(StraightRouteScene(), motion, ArmOptions(), 90, 30, 8);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  double max_offset = 0;
  for (int i = 0; i < 90; ++i) {
    const Eigen::Vector3d p = a->WorldFromCamera(i).translation();
    const Eigen::Vector3d on_route(0.4 * a->times_s[i], 0, 1.4);
    max_offset = std::max(max_offset, (p - on_route).norm());
    EXPECT_TRUE(a->world_from_body[i].isApprox(b->world_from_body[i]));
  }
  EXPECT_GT(max_offset, 0.002);
  EXPECT_LT(max_offset, 3 * 0.03);
  EXPECT_FALSE(a->world_from_body[45].isApprox(c->world_from_body[45]));
}

TEST(Motion, OrbitCirclesTheCentreLookingAtTheTarget) {
  MotionOptions motion;
  motion.kind = "orbit";
  motion.orbit_center_x_m = 2;
  motion.orbit_center_y_m = -1;
  motion.orbit_target_z_m = 0.2;
  motion.orbit_radius_m = 1.5;
  motion.orbit_deg_per_s = 15;
  motion.camera_height_m = 1.0;
  motion.shake_m = 0;
  motion.shake_deg = 0;
  // 12 s at 2 fps: 180 deg around the centre. The scene needs no route.
  auto plan = PlanMotion(Scene("empty"), motion, ArmOptions(), 25, 2, 1);
  ASSERT_TRUE(plan.ok()) << plan.status().ToString();
  EXPECT_EQ(plan->kind, "orbit");
  const Eigen::Vector3d target(2, -1, 0.2);
  for (int i : {0, 12, 24}) {
    const Eigen::Isometry3d camera = plan->WorldFromCamera(i);
    const Eigen::Vector3d c = camera.translation();
    EXPECT_NEAR(std::hypot(c.x() - 2, c.y() + 1), 1.5, 1e-9);
    EXPECT_NEAR(c.z(), 1.0, 1e-9);
    EXPECT_NEAR(camera.linear().col(2).dot((target - c).normalized()), 1.0, 1e-9);  // Looks at it.
    EXPECT_LT(camera.linear().col(1).z(), 0);  // Image y points down.
  }
  EXPECT_NEAR(plan->WorldFromCamera(0).translation().x(), 3.5, 1e-9);
  EXPECT_NEAR(plan->WorldFromCamera(12).translation().y(), 0.5, 1e-9);  // 90 deg after 6 s.
  EXPECT_NEAR(plan->WorldFromCamera(24).translation().x(), 0.5, 1e-9);  // 180 deg.
  motion.orbit_radius_m = 0.1;
  EXPECT_FALSE(PlanMotion(Scene("empty"), motion, ArmOptions(), 2, 2, 1).ok());
}

TEST(Motion, ArmMovesSidewaysFirstThenApproachesTheTarget) {
  auto scene = BuildPanel(PanelOptions(), 1);
  ASSERT_TRUE(scene.ok());
  ArmOptions arm;
  auto plan = PlanMotion(*scene, MotionOptions(), arm, 101, 30, 1);
  ASSERT_TRUE(plan.ok()) << plan.status().ToString();
  EXPECT_EQ(plan->kind, "arm");
  const ButtonSpec& target = scene->buttons[scene->hints.target_button];
  double max_lateral = 0;
  for (int i = 0; i <= 30; ++i) {  // The first 30 % of the recording.
    const Eigen::Vector3d offset = plan->WorldFromCamera(i).translation() - target.center;
    EXPECT_NEAR(offset.dot(target.normal), arm.start_distance_m, 1e-9) << i;
    max_lateral = std::max(max_lateral, std::abs(offset.y()));
  }
  EXPECT_NEAR(max_lateral, arm.sideways_m, 1e-3);
  const Eigen::Isometry3d last = plan->WorldFromCamera(100);
  EXPECT_NEAR((last.translation() - target.center).dot(target.normal), arm.end_distance_m, 1e-9);
  EXPECT_NEAR(last.linear().col(2).dot(-target.normal), 1, 1e-12);  // Looks into the panel.
}

TEST(Motion, KindsThatTheSceneCannotSupportFailClearly) {
  Scene empty("empty");
  MotionOptions motion;
  motion.kind = "arm";
  auto plan = PlanMotion(empty, motion, ArmOptions(), 10, 30, 1);
  ASSERT_FALSE(plan.ok());
  EXPECT_NE(plan.status().message().find("target button"), std::string::npos);
  motion.kind = "robot";
  EXPECT_FALSE(PlanMotion(empty, motion, ArmOptions(), 10, 30, 1).ok());
  motion.kind = "static";
  EXPECT_TRUE(PlanMotion(empty, motion, ArmOptions(), 10, 30, 1).ok());
}

TEST(Odometry, HeadingDriftGivesTheAnalyticHeadingErrorAfterNMetres) {
  MotionOptions motion;
  motion.speed_mps = 1.0;
  // 10 s at 1 m/s on a straight route: 10 m.
  auto plan = PlanMotion(StraightRouteScene(), motion, ArmOptions(), 301, 30, 1);
  ASSERT_TRUE(plan.ok());
  OdometryOptions options;
  options.heading_drift_deg_per_m = 2.0;
  options.scale_error = 0;
  options.distance_noise = 0;
  options.heading_noise_deg = 0;
  const Trajectory odometry =
      SimulateWheelOdometry(plan->times_s, plan->world_from_body, options, 3);
  ASSERT_EQ(odometry.size(), 301u);
  for (size_t i : {size_t{30}, size_t{150}, size_t{300}}) {
    const double metres = plan->world_from_body[i].translation().x();
    const double error_deg =
        (Yaw(odometry.poses()[i].world_from_sensor) - Yaw(plan->world_from_body[i])) * 180 / M_PI;
    EXPECT_NEAR(error_deg, 2.0 * metres, 1e-9) << metres << " m";
  }
  // Distances are kept: the odometry drives 10 m along a circular arc of curvature = drift,
  // so it ends one chord of that arc, 2 sin(k L / 2) / k, from the start.
  const double k = 2.0 * M_PI / 180;  // rad per metre
  const Eigen::Vector3d end = odometry.poses().back().world_from_sensor.translation();
  EXPECT_NEAR(end.norm(), 2 * std::sin(k * 10 / 2) / k, 1e-3);
}

TEST(Odometry, NoiseIsSeededAndScaleErrorStretchesDistances) {
  auto plan = PlanMotion(StraightRouteScene(), MotionOptions(), ArmOptions(), 61, 30, 1);
  ASSERT_TRUE(plan.ok());
  OdometryOptions options;
  const Trajectory a = SimulateWheelOdometry(plan->times_s, plan->world_from_body, options, 5);
  const Trajectory b = SimulateWheelOdometry(plan->times_s, plan->world_from_body, options, 5);
  const Trajectory c = SimulateWheelOdometry(plan->times_s, plan->world_from_body, options, 6);
  EXPECT_TRUE(a.poses().back().world_from_sensor.isApprox(b.poses().back().world_from_sensor));
  EXPECT_FALSE(a.poses().back().world_from_sensor.isApprox(c.poses().back().world_from_sensor));
  options = OdometryOptions{0, 0.05, 0, 0};
  const Trajectory scaled = SimulateWheelOdometry(plan->times_s, plan->world_from_body, options, 5);
  EXPECT_NEAR(scaled.LengthM(), 1.05 * 1.0, 1e-9);  // 2 s at 0.5 m/s, 5 % long.
}

}  // namespace
}  // namespace sightline::sim
