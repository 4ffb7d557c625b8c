// Dead reckoning: motion increments from any absolute pose source (wheel odometry from a
// dataset, later a visual odometry pipeline), expressed in the robot's previous base frame so
// that mapping can re-apply them with its own, Manhattan-corrected heading.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "core/mapping/pose2d.h"

namespace sightline {

// The motion between two frames as the pose source saw it.
struct OdometryIncrement {
  bool valid = false;  // False for the first frame or when the source had no pose.
  Eigen::Vector2d translation_in_previous_base = Eigen::Vector2d::Zero();  // [m]
  double heading_change_rad = 0;                                           // Wrapped to [-pi, pi).
};

// Turns a stream of absolute poses (world_from_base of the pose source) into increments.
//
//   DeadReckoning odometry;
//   for (...) {
//     OdometryIncrement step = odometry.Update(pose_source_at_frame);  // nullopt if none
//   }
class DeadReckoning {
 public:
  // The increment from the last pose given to this one. A missing pose gives an invalid
  // increment and the next valid pose restarts the chain.
  OdometryIncrement Update(const std::optional<Pose2d>& world_from_base);
  // Forgets the last pose.
  void Reset() { last_.reset(); }

 private:
  std::optional<Pose2d> last_;
};

}  // namespace sightline
