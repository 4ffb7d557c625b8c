// The client side of the arm-target protocol (PROTOCOL.md): a strict parser of the lines the
// server sends (target, heartbeat, stop). Used by the simulated arm (arm_simulator.h); a line it
// cannot read is an error naming what is wrong, never a crash. (The arm's own `arm_pose` line is
// ArmPoseLine in arm_pose_stream.h.)
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <string>

#include "core/button/arm_protocol.h"
#include "core/common/status.h"

namespace sightline {

// One server line.
struct ServerLine {
  enum class Type { kTarget, kHeartbeat, kStop };
  Type type = Type::kHeartbeat;
  int version = 0;
  int64_t seq = -1;
  double stamp_s = 0;
  ArmTarget target;              // kTarget.
  bool targets_enabled = false;  // kHeartbeat.
  std::string reason;            // kStop.
};

// Parses one line (without '\n'). InvalidArgument naming the member otherwise: not one flat
// JSON object, an unknown `type`, a missing member, a non-finite number, a zero `approach`, a
// `version` other than 2 (members it does not know are ignored, as the protocol asks).
StatusOr<ServerLine> ParseServerLine(const std::string& line);

}  // namespace sightline
