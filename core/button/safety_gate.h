// The safety gate between the button estimate and the arm: a target goes out only when the
// operator confirmed, STOP is not active, tracking is good, the estimate is fresh, the metric
// scale has converged, the plane fit is sound, position and approach direction are certain
// enough and the point lies inside the workspace box.
// A pure function of its inputs, so every rule is testable on its own.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "core/options/option_table.h"

namespace sightline {

// Gate options. Keys "button.gate.*". The workspace box is in the arm base frame.
struct SafetyGateOptions {
  double max_age_ms = 200;            // Older estimates are not sent [ms].
  double min_confidence = 0.3;        // Weaker tracking confidence is "tracking poor".
  double max_uncertainty_m = 0.02;    // Larger 1-sigma position uncertainty is not sent [m].
  double max_approach_sigma_deg = 5;  // Larger 1-sigma approach uncertainty is not sent [deg].
  double workspace_min_x_m = 0.1, workspace_max_x_m = 1.3;  // Base frame box [m].
  double workspace_min_y_m = -0.6, workspace_max_y_m = 0.6;
  double workspace_min_z_m = -0.5, workspace_max_z_m = 0.9;
  // The online hand-eye check (SafetyState::hand_eye_deg): the arm's and the SLAM's displacement
  // directions disagree by more than this: the mount is wrong, no target [deg].
  double max_hand_eye_deg = 3;
  // No target while the check could not see the mount's translation (the arm did not rotate).
  bool require_hand_eye_check = false;

  bool IsValid(std::string* error) const;
  static OptionTable<SafetyGateOptions> Describe();
};

// Everything the gate looks at, gathered by the caller for one estimate.
struct SafetyState {
  bool stopped = false;             // STOP pressed and not yet released by a new start.
  bool operator_confirmed = false;  // "Press this button?" answered Yes.
  bool tracking = false;            // The tracker found the button in the estimate's frame.
  double tracking_confidence = 0;   // ButtonTrack::confidence.
  bool has_estimate = false;        // A 3D position exists.
  double estimate_age_ms = 0;       // Now minus the estimate's frame time.
  bool scale_converged = false;     // The SLAM's metric scale estimate has converged.
  bool plane_sound = false;         // ButtonLocation::plane_sound.
  double uncertainty_m = 0;         // ButtonLocation::uncertainty_m.
  // 1-sigma angular uncertainty of the approach direction (the panel normal) [deg]; infinite
  // when no normal is known.
  double approach_sigma_deg = std::numeric_limits<double>::infinity();
  // The approach direction sent with the target: a finite unit vector, or no target.
  Eigen::Vector3d approach_in_base = Eigen::Vector3d::Constant(std::nan(""));
  Eigen::Vector3d target_in_base = Eigen::Vector3d::Zero();
  double hand_eye_deg = 0;                    // Mount rotation error the online check sees.
  bool hand_eye_translation_verified = true;  // The check saw the mount's translation.
};

// Why a target was (not) sent. kSend is the only value that lets a target out.
enum class GateReason {
  kSend,
  kStopped,
  kNotConfirmed,
  kTrackingLost,
  kTrackingPoor,
  kNoEstimate,
  kStale,
  kScaleNotConverged,
  kPlaneUnsound,
  kUncertain,
  kApproachUncertain,
  kOutsideWorkspace,
};

struct GateVerdict {
  bool send = false;
  GateReason reason = GateReason::kNotConfirmed;
  std::string message;  // For the operator's banner and logs, e.g. "estimate 340 ms old".
};

// The first rule that fails, in the order of the enum (STOP first); invalid options never send.
GateVerdict CheckSafety(const SafetyState& state, const SafetyGateOptions& options);

// One line per option of `options` set looser than its default (a later deadline, a weaker
// confidence, a larger uncertainty or workspace, ...), naming the key, its value and the
// default, for the run's log and notes; empty when none is.
std::vector<std::string> LooserGateWarnings(const SafetyGateOptions& options);

// Stable key of a reason ("send", "stopped", "stale", ...) for CSV files and the protocol.
const char* GateReasonKey(GateReason reason);

}  // namespace sightline
