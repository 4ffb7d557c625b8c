// The arm-target protocol (version 2): JSON lines over TCP, documented in
// core/button/PROTOCOL.md. Serialisation of the three message types, parsing of the one line a
// client may send (the token handshake) and the token check.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sightline {

inline constexpr int kArmProtocolVersion = 2;

// A button target for the arm controller.
struct ArmTarget {
  double stamp_s = 0;                 // Time of the image the estimate comes from [s].
  std::string frame_id = "arm_base";  // Frame of position and approach.
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // Button centre [m].
  Eigen::Vector3d approach = Eigen::Vector3d::UnitX();   // Unit push direction.
  double uncertainty_m = 0;                              // 1-sigma position uncertainty [m].
  double approach_sigma_deg = 0;                         // 1-sigma of `approach` [deg].
  std::vector<int64_t> source_frames;                    // Frame ids the estimate used.
};

// True for a finite vector of unit length (to 1e-6): the only `approach` a target may carry.
inline bool IsUnitVector(const Eigen::Vector3d& v) {
  return v.allFinite() && std::abs(v.norm() - 1) < 1e-6;
}

// One JSON line (with the trailing '\n') per message; `seq` counts all messages of a server.
// `stamp` and `frame_stamp` are written with six decimals (microseconds).
std::string TargetLine(int64_t seq, double now_s, const ArmTarget& target);
std::string HeartbeatLine(int64_t seq, double now_s, bool targets_enabled);
std::string StopLine(int64_t seq, double now_s, const std::string& reason);

// The token of a handshake line `{"token": "..."}`; nullopt for anything else (malformed JSON,
// other keys only, non-string token). Accepts a flat object of string, number, bool or null
// members.
std::optional<std::string> ParseTokenLine(const std::string& line);

// True when `presented` equals `expected`. The time taken depends only on the length of
// `expected`, not on where the two differ (no timing oracle for guessing the token).
bool TokensMatch(const std::string& presented, const std::string& expected);

}  // namespace sightline
