// The button picker's data for views and writers: its state and what happened in one frame.
// No picker or server classes: the GUI may include this header.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "core/button/arm_protocol.h"
#include "core/button/button_locator.h"
#include "core/button/button_tracker.h"
#include "core/button/safety_gate.h"

namespace sightline {

// The picker's state, as the operator's banner shows it.
enum class PickerState {
  kIdle,
  kConfirm,
  kSearching,
  kTracking,
  kLocating,
  kTargetSent,
  kLost,
  kStopped
};
const char* PickerStateKey(PickerState state);  // "idle", "confirm", ..., "stopped".

// What happened in one frame.
struct PickerFrame {
  int64_t frame_id = -1;
  double stamp_s = 0;
  PickerState state = PickerState::kIdle;
  ButtonTrack track;
  double tracking_ms = 0;                  // Tracker time of this frame.
  std::optional<ButtonLocation> location;  // Camera frame.
  Eigen::Vector3d button_in_base = Eigen::Vector3d::Constant(std::nan(""));  // Fused.
  int fused_estimates = 0;  // Estimates in button_in_base.
  // 1-sigma of button_in_base: the location's own (fit, scale), tracking, hand-eye and the
  // fused positions' spread (ButtonUncertaintyOptions); 0 without a location.
  double uncertainty_m = 0;
  // The push direction: the averaged panel normal, inward (NaN while none is known), and its
  // 1-sigma [deg] (infinite while none is known).
  Eigen::Vector3d approach_in_base = Eigen::Vector3d::Constant(std::nan(""));
  double approach_sigma_deg = std::numeric_limits<double>::infinity();
  // The button triangulated from the arm's poses alone (button.triangulate.*) and its 1-sigma
  // along its worst axis; NaN while the tracked views do not fix it.
  Eigen::Vector3d arm_in_base = Eigen::Vector3d::Constant(std::nan(""));
  double arm_sigma_m = std::nan("");
  GateVerdict verdict;
  std::optional<ArmTarget> target;  // Set when the gate lets it out.
};

}  // namespace sightline
