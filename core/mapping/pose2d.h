// Planar poses and angle helpers shared by the mapping stages.
//
// Frames: the robot ("base") frame lies on the floor directly below the camera, x forward (the
// camera's optical axis projected onto the floor), y left, z up. The world ("map") frame is the
// frame of the first pose (or of the pose source); headings are counter-clockwise from its x axis.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace sightline {

// Pi without <numbers>: the ROS translation units (C++17) include the mapping results.
inline constexpr double kPose2dPi = 3.14159265358979323846;

// Wraps an angle to [-pi, pi).
inline double WrapAngle(double angle_rad) {
  const double two_pi = 2 * kPose2dPi;
  double a = std::fmod(angle_rad + kPose2dPi, two_pi);
  if (a < 0) a += two_pi;
  return a - kPose2dPi;
}

// Wraps an angle to [-pi/2, pi/2): the direction of an undirected line.
inline double WrapHalfTurn(double angle_rad) { return 0.5 * WrapAngle(2 * angle_rad); }

// Wraps an angle to [-pi/4, pi/4): a direction in a Manhattan world, where walls repeat every
// 90 degrees.
inline double WrapQuarterTurn(double angle_rad) { return 0.25 * WrapAngle(4 * angle_rad); }

inline double DegToRad(double deg) { return deg * kPose2dPi / 180.0; }
inline double RadToDeg(double rad) { return rad * 180.0 / kPose2dPi; }

// A pose on the floor: world_from_base as position and heading.
struct Pose2d {
  double x = 0;            // [m]
  double y = 0;            // [m]
  double heading_rad = 0;  // Counter-clockwise from the world x axis.

  Eigen::Vector2d position() const { return {x, y}; }
  // Maps a point from the base frame into the world frame.
  Eigen::Vector2d Apply(const Eigen::Vector2d& p_in_base) const {
    const double c = std::cos(heading_rad), s = std::sin(heading_rad);
    return {x + c * p_in_base.x() - s * p_in_base.y(), y + s * p_in_base.x() + c * p_in_base.y()};
  }
  // The same pose as a 3D isometry (z = 0, rotation about z).
  Eigen::Isometry3d ToIsometry() const {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::AngleAxisd(heading_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    t.translation() = Eigen::Vector3d(x, y, 0);
    return t;
  }
  // The planar part of a 3D pose: position x, y and the heading of its `forward` axis projected
  // onto the x-y plane (for a camera with z forward pass UnitZ()).
  static Pose2d FromIsometry(const Eigen::Isometry3d& world_from_frame,
                             const Eigen::Vector3d& forward = Eigen::Vector3d::UnitX()) {
    const Eigen::Vector3d f = world_from_frame.linear() * forward;
    return {world_from_frame.translation().x(), world_from_frame.translation().y(),
            std::atan2(f.y(), f.x())};
  }
};

}  // namespace sightline
