// Simulated wheel odometry for dead reckoning (seed 000): the robot base's true planar motion
// integrated with a distance scale error, a heading drift proportional to the distance driven,
// and random walk noise.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/trajectory.h"
#include "core/options/option_table.h"

namespace sightline::sim {

// Odometry error model. With all noise at zero, after driving L metres the heading error is
// exactly heading_drift_deg_per_m * L and every distance is scaled by (1 + scale_error).
struct OdometryOptions {
  double heading_drift_deg_per_m = 0.5;  // Systematic heading drift, deg per metre driven.
  double scale_error = 0.01;             // Systematic distance error (0.01 = 1 % long).
  double distance_noise = 0.01;          // Distance noise, m per sqrt(m) driven.
  double heading_noise_deg = 0.2;        // Heading noise, deg per sqrt(m) driven.

  bool IsValid(std::string* error) const;
  static OptionTable<OdometryOptions> Describe();
};

// Dead reckoning of the base poses `world_from_base` (on the floor, z up) sampled at `times_s`.
// The odometry frame coincides with the map frame at the first pose. Per frame, the true
// planar increment (distance ds along direction alpha in the previous base frame, heading
// change dtheta) becomes ds' = ds (1 + scale) + N(0, sigma_d^2 ds) and
// dtheta' = dtheta + drift ds + N(0, sigma_h^2 ds), integrated from the odometry's own pose.
Trajectory SimulateWheelOdometry(const std::vector<double>& times_s,
                                 const std::vector<Eigen::Isometry3d>& world_from_base,
                                 const OdometryOptions& options, uint64_t seed);

}  // namespace sightline::sim
