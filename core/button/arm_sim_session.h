// Runs a simulated arm (arm_simulator.h) against Sightline's arm-target server over TCP: the
// token handshake, an `arm_pose` line every control period (stamped with this machine's wall
// clock), and every server line handed to the arm the moment it arrives, before the next control
// step (so nothing moves after a stop line arrived). Used by `sightline-cli arm-sim` and the
// closed-loop tests.
#pragma once

#include <Eigen/Geometry>
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "core/button/arm_simulator.h"
#include "core/common/status.h"

namespace sightline {

struct ArmSimSessionResult {
  std::string end_reason;  // finished, closed, cancelled, max_time_s.
  int64_t poses_sent = 0;
  ArmSimOutcome outcome;
};

// Seconds since the Unix epoch on this machine's wall clock (the arm's clock).
double WallClockS();

// Connects to HOST:PORT, presents `token` (when not empty) and runs `arm` until it is finished
// (reached and settled), the server closes the connection, armsim.max_time_s passes or `cancel`
// becomes true. `on_pose` sees every pose sent. Unavailable when the server cannot be reached.
StatusOr<ArmSimSessionResult> RunArmSimSession(
    const std::string& host, int port, const std::string& token, ArmSimulator* arm,
    const std::atomic<bool>* cancel = nullptr,
    const std::function<void(double, const Eigen::Isometry3d&)>& on_pose = nullptr);

}  // namespace sightline
