// Synthetic trajectories with known geometry for the evaluation tests.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "core/common/trajectory.h"

namespace sightline::testing {

// n poses 1 m apart along +x with identity orientation, at 10 Hz.
inline Trajectory StraightLine(int n, double step_m = 1.0) {
  Trajectory t;
  for (int i = 0; i < n; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(step_m * i, 0, 0);
    t.Add(0.1 * i, pose);
  }
  return t;
}

// n poses on a circle of `radius` about the origin in the x-y plane, facing along the tangent,
// plus a small climb in z, so that positions span 3D and orientations vary.
inline Trajectory Helix(int n, double radius = 5.0, double climb_per_pose = 0.02) {
  Trajectory t;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = (Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(0.1 * std::sin(3 * a), Eigen::Vector3d::UnitX()))
                        .toRotationMatrix();
    pose.translation() =
        Eigen::Vector3d(radius * std::cos(a), radius * std::sin(a), climb_per_pose * i);
    t.Add(100.0 + 0.1 * i, pose);
  }
  return t;
}

// Every pose moved into another world frame: other_from_world * pose.
inline Trajectory Transformed(const Trajectory& t, const Eigen::Isometry3d& other_from_world) {
  Trajectory out;
  for (const TimedPose& p : t.poses()) out.Add(p.time_s, other_from_world * p.world_from_sensor);
  return out;
}

// Positions multiplied by `factor` about the world origin; orientations kept.
inline Trajectory Scaled(const Trajectory& t, double factor) {
  Trajectory out;
  for (const TimedPose& p : t.poses()) {
    Eigen::Isometry3d pose = p.world_from_sensor;
    pose.translation() *= factor;
    out.Add(p.time_s, pose);
  }
  return out;
}

}  // namespace sightline::testing
