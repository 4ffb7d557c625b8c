// How the sensors move: a robot driving the scene's route, a handheld camera (along the route or
// circling a point), or an arm approaching a button. Poses are sampled once per frame.
//
// Frames: body frames follow REP-103 (x forward, y left, z up); a robot base sits on the floor
// (z = 0) under its sensors. Cameras use the optical frame (z forward, x right, y down).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/options/option_table.h"
#include "core/sim/scene.h"

namespace sightline::sim {

// The motion of the sensor carrier.
struct MotionOptions {
  std::string kind = "auto";      // "auto" (from the scene), robot, handheld, orbit, arm, static.
  double speed_mps = 0.5;         // Robot / walking speed along the route, m/s.
  double turn_radius_m = 0.6;     // Radius of the route's turns, metres.
  double camera_height_m = 0.8;   // Robot: optical centre above the floor; handheld: mean height.
  double camera_tilt_deg = 10.0;  // Camera pitched down by this angle, degrees.
  double camera_forward_m = 0.1;  // Robot: optical centre ahead of the base centre, metres.
  double shake_m = 0.03;          // Handheld: amplitude of the positional wobble, metres.
  double shake_deg = 2.0;         // Handheld: amplitude of the angular wobble, degrees.
  // Orbit: a handheld camera circling a point on the floor plan at camera_height_m, looking at
  // it, with the handheld wobble. Defaults circle the terrain's step, ramp and rough patch.
  double orbit_center_x_m = 1.9;   // Centre of the circle (map x), metres.
  double orbit_center_y_m = -0.1;  // Centre of the circle (map y), metres.
  double orbit_target_z_m = 0.1;   // Height of the point looked at, metres.
  double orbit_radius_m = 1.5;     // Radius of the circle, metres.
  double orbit_deg_per_s = 15.0;   // Angular speed around the centre (counter-clockwise), deg/s.

  bool IsValid(std::string* error) const;
  static OptionTable<MotionOptions> Describe();
};

// The arm approach (seed 004): first small sideways moves at the start distance (so a
// monocular tracker can initialise), then straight towards the target button.
struct ArmOptions {
  double start_distance_m = 1.0;   // Camera to button at the start, metres.
  double end_distance_m = 0.3;     // Camera to button at the end, metres.
  double sideways_m = 0.08;        // Amplitude of the sideways moves, metres.
  double sideways_fraction = 0.3;  // Part of the recording spent moving sideways.
  double pose_noise_m = 0.0005;    // Gaussian noise of the reported arm positions, metres.
  // Hand-eye: the camera's optical centre in the end-effector frame (x up along the camera's
  // -y, z along the optical axis), metres.
  double camera_offset_x_m = 0.06;
  double camera_offset_z_m = -0.03;

  bool IsValid(std::string* error) const;
  static OptionTable<ArmOptions> Describe();
};

// The sampled motion of one recording.
struct MotionPlan {
  std::string kind;                                // Resolved: robot, handheld, arm, static.
  std::vector<double> times_s;                     // One per frame.
  std::vector<Eigen::Isometry3d> world_from_body;  // One per frame.
  Eigen::Isometry3d body_from_camera = Eigen::Isometry3d::Identity();  // Every camera's mount.
  // Arm: the base in the map frame (body = end effector).
  Eigen::Isometry3d world_from_arm_base = Eigen::Isometry3d::Identity();

  bool is_robot() const { return kind == "robot" || kind == "static"; }
  bool is_arm() const { return kind == "arm"; }
  Eigen::Isometry3d WorldFromCamera(size_t frame) const {
    return world_from_body[frame] * body_from_camera;
  }
};

// The optical frame of a camera looking along the body's x axis, pitched down by `tilt_rad`.
Eigen::Matrix3d BodyFromOptical(double tilt_rad);

// Samples `frames` poses at `rate_hz` from time 0. "auto" picks "arm" for scenes with a target
// button, "robot" for scenes with a route, else "static". InvalidArgument when the kind needs
// what the scene lacks (a route, a target button) or the route's turns do not fit.
StatusOr<MotionPlan> PlanMotion(const Scene& scene, const MotionOptions& motion,
                                const ArmOptions& arm, int frames, double rate_hz, uint64_t seed);

}  // namespace sightline::sim
