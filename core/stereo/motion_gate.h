// Gating of frame-to-frame motions (the seed's filtering): an estimate is rejected when it
// implies a speed, angular speed or acceleration the vehicle cannot have, or when its residuals
// or inlier count say it is unreliable. A rejected or failed estimate is replaced by the last
// accepted motion (constant-motion fallback, as the seed does when RANSAC fails) for a few
// frames, then by no motion (the pose is held).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <utility>

#include "core/options/option_table.h"

namespace sightline {

// Gate options. Keys "stereo.gate.*".
struct MotionGateOptions {
  double max_speed_mps = 40.0;             // Fastest plausible translation [m/s].
  double max_angular_speed_deg_s = 120.0;  // Fastest plausible rotation [deg/s].
  double max_acceleration_mps2 = 30.0;     // Largest change of velocity [m/s^2]; 0 = no check.
  double max_residual_px = 1.5;  // Refined RMS reprojection error above this rejects [px].
  int min_inliers = 20;          // Fewer refined inliers rejects.
  std::string fallback = "constant_motion";  // constant_motion or hold.
  int max_fallback_frames = 2;               // Consecutive constant-motion frames, then hold.

  bool IsValid(std::string* error) const;
  static OptionTable<MotionGateOptions> Describe();
};

// An estimate offered to the gate.
struct MotionCandidate {
  bool estimated = false;  // False when RANSAC or matching failed.
  std::string failure;     // Why not, when not estimated.
  Eigen::Isometry3d current_from_previous = Eigen::Isometry3d::Identity();
  double residual_px = 0;  // Refined RMS reprojection error [px].
  int inliers = 0;
};

// What the gate decided.
struct GateDecision {
  bool accepted = false;  // The candidate's motion is used.
  std::string reason;     // Empty when accepted, else why rejected and what was used instead.
  Eigen::Isometry3d current_from_previous = Eigen::Isometry3d::Identity();  // Motion to apply.
};

// Stateful: remembers the last accepted velocity.
//
//   MotionGate gate(options);
//   GateDecision d = gate.Check(candidate, dt_s);
//   world_from_camera = world_from_camera * d.current_from_previous.inverse();
class MotionGate {
 public:
  explicit MotionGate(MotionGateOptions options = {}) : options_(std::move(options)) {}

  // Decides over a candidate spanning dt_s seconds (<= 0: unknown, speed checks skipped).
  GateDecision Check(const MotionCandidate& candidate, double dt_s);
  // Forgets the velocity history.
  void Reset();

 private:
  // The last accepted motion scaled to dt_s, or identity.
  Eigen::Isometry3d Fallback(double dt_s) const;

  MotionGateOptions options_;
  std::optional<Eigen::Isometry3d> last_motion_;  // Last accepted current_from_previous.
  double last_dt_s_ = 0;
  int fallback_frames_ = 0;
};

}  // namespace sightline
