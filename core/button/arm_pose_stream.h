// The arm's pose streamed in by an authenticated arm client (PROTOCOL.md, `arm_pose`): a strict
// parser of one message line, and the buffer that keeps the recent poses and interpolates
// base_from_end_effector at a camera frame's stamp (data time, with an explicit clock offset).
// The arm-target server (arm_server.h) parses the lines of the arm client with it; the button
// pipeline buffers the received poses (core/pipeline/arm_pose_feed.h) for the metric scale.
#pragma once

#include <Eigen/Geometry>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// One `arm_pose` message:
//   {"type":"arm_pose","stamp":12.345678,"position_m":[x,y,z],"quaternion_xyzw":[x,y,z,w],
//    "joints":[q1,...]}
// stamp: seconds on the arm's clock; position and quaternion: base_from_end_effector; joints
// optional (radians or metres). Other members (string, number, bool, null or numeric arrays)
// are ignored.
struct ArmPoseMessage {
  double stamp_s = 0;
  Eigen::Isometry3d base_from_end_effector = Eigen::Isometry3d::Identity();
  std::vector<double> joints;
};

// Limits of the stream. Keys "button.arm_pose.*".
struct ArmPoseStreamOptions {
  int max_joints = 16;         // More joint positions: the message is refused.
  double max_position_m = 10;  // A position farther from the base is refused [m].
  double max_rate_hz = 200;    // Poses closer in arm time than 1/this are dropped [Hz].
  double clock_offset_s = 0;   // arm clock = camera clock + this [s].
  double max_gap_s = 0.05;     // No interpolation across a larger gap between poses [s].
  double keep_s = 5;           // Poses older than this behind the newest are dropped [s].
  double wait_s = 0.1;         // A frame past the newest pose waits this long for it [s, host].

  bool IsValid(std::string* error) const;
  static OptionTable<ArmPoseStreamOptions> Describe();
};

// Parses one line (without its '\n'). InvalidArgument naming the member for anything else:
// not one flat JSON object, another `type`, a missing or non-finite member, a quaternion whose
// norm is not within 10 % of 1 (it is normalised otherwise), too many joints, a duplicate key.
StatusOr<ArmPoseMessage> ParseArmPoseLine(const std::string& line,
                                          const ArmPoseStreamOptions& options = {});

// Resolution of the stamps (arm_pose lines carry microseconds) [s].
inline constexpr double kStampResolutionS = 1e-6;

// Whether `stamp_s` keeps to `max_rate_hz` after `previous_s`: at least 1 / max_rate_hz later,
// up to a microsecond (the stamps' resolution), so an arm at exactly the limit loses nothing.
bool KeepsRate(double previous_s, double stamp_s, double max_rate_hz);

// The line an arm client sends for `pose` (without '\n'): stamp with six decimals, position and
// quaternion with nine; ParseArmPoseLine reads it back.
std::string ArmPoseLine(const ArmPoseMessage& pose);

// The recent poses of one arm, in arm time. Not thread-safe.
class ArmPoseBuffer {
 public:
  explicit ArmPoseBuffer(ArmPoseStreamOptions options = {}) : options_(options) {}

  // Adds a pose. False (and counted) when its stamp is not after the newest one by at least
  // 1 / max_rate_hz (KeepsRate).
  bool Add(const ArmPoseMessage& pose);
  // base_from_end_effector at camera time `camera_stamp_s` (shifted by clock_offset_s): the
  // interpolation of the two poses around it (linear position, slerp rotation); nullopt outside
  // the buffered span (a microsecond outside counts as its end) or across a gap above
  // max_gap_s.
  std::optional<Eigen::Isometry3d> At(double camera_stamp_s) const;
  size_t size() const { return poses_.size(); }
  // Stamp of the newest pose (arm clock); nullopt while empty.
  std::optional<double> newest_stamp() const {
    return poses_.empty() ? std::nullopt : std::optional<double>(poses_.back().stamp_s);
  }
  const ArmPoseStreamOptions& options() const { return options_; }
  int64_t dropped() const { return dropped_; }

 private:
  ArmPoseStreamOptions options_;
  std::deque<ArmPoseMessage> poses_;
  int64_t dropped_ = 0;
};

}  // namespace sightline
