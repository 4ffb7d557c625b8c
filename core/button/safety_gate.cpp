#include "core/button/safety_gate.h"

#include <cmath>
#include <cstdio>

#include "core/button/arm_protocol.h"
#include "core/button/option_check.h"

namespace sightline {

using button_internal::Invalid;

bool SafetyGateOptions::IsValid(std::string* error) const {
  if (!(max_age_ms > 0)) return Invalid(error, "button.gate.max_age_ms must be > 0");
  if (!(min_confidence >= 0 && min_confidence <= 1)) {
    return Invalid(error, "button.gate.min_confidence must lie in [0, 1]");
  }
  if (!(max_uncertainty_m > 0)) return Invalid(error, "button.gate.max_uncertainty_m must be > 0");
  if (!(max_approach_sigma_deg > 0)) {
    return Invalid(error, "button.gate.max_approach_sigma_deg must be > 0");
  }
  if (!(workspace_min_x_m < workspace_max_x_m && workspace_min_y_m < workspace_max_y_m &&
        workspace_min_z_m < workspace_max_z_m)) {
    return Invalid(error, "button.gate.workspace: every min must be below its max");
  }
  if (!(max_hand_eye_deg > 0)) return Invalid(error, "button.gate.max_hand_eye_deg must be > 0");
  return true;
}

OptionTable<SafetyGateOptions> SafetyGateOptions::Describe() {
  using O = SafetyGateOptions;
  return OptionTable<O>("button.gate")
      .Double("max_age_ms", &O::max_age_ms, "ms", 1, 10000, 10, "Older estimates are not sent.")
      .Double("min_confidence", &O::min_confidence, "", 0, 1, 0.05,
              "Weaker tracking confidence: no target.")
      .Double("max_uncertainty_m", &O::max_uncertainty_m, "m", 1e-4, 1, 0.001,
              "Larger 1-sigma position uncertainty: no target.")
      .Double("max_approach_sigma_deg", &O::max_approach_sigma_deg, "deg", 0.1, 90, 0.5,
              "Larger 1-sigma uncertainty of the approach direction (the panel normal): no "
              "target.")
      .Double("workspace_min_x_m", &O::workspace_min_x_m, "m", -10, 10, 0.01,
              "Workspace box, base x min.")
      .Double("workspace_max_x_m", &O::workspace_max_x_m, "m", -10, 10, 0.01,
              "Workspace box, base x max.")
      .Double("workspace_min_y_m", &O::workspace_min_y_m, "m", -10, 10, 0.01,
              "Workspace box, base y min.")
      .Double("workspace_max_y_m", &O::workspace_max_y_m, "m", -10, 10, 0.01,
              "Workspace box, base y max.")
      .Double("workspace_min_z_m", &O::workspace_min_z_m, "m", -10, 10, 0.01,
              "Workspace box, base z min.")
      .Double("workspace_max_z_m", &O::workspace_max_z_m, "m", -10, 10, 0.01,
              "Workspace box, base z max.")
      .Double("max_hand_eye_deg", &O::max_hand_eye_deg, "deg", 0.01, 90, 0.5,
              "The arm's and the SLAM's displacement directions disagree by more than this "
              "(online hand-eye check; a wrong mount rotation): no target.")
      .Bool("require_hand_eye_check", &O::require_hand_eye_check,
            "No target until the online hand-eye check has seen the mount's translation (the "
            "arm must rotate between keyframes); without it that translation is taken on trust.");
}

const char* GateReasonKey(GateReason reason) {
  switch (reason) {
    case GateReason::kSend:
      return "send";
    case GateReason::kStopped:
      return "stopped";
    case GateReason::kNotConfirmed:
      return "not_confirmed";
    case GateReason::kTrackingLost:
      return "tracking_lost";
    case GateReason::kTrackingPoor:
      return "tracking_poor";
    case GateReason::kNoEstimate:
      return "no_estimate";
    case GateReason::kStale:
      return "stale";
    case GateReason::kScaleNotConverged:
      return "scale_not_converged";
    case GateReason::kPlaneUnsound:
      return "plane_unsound";
    case GateReason::kUncertain:
      return "uncertain";
    case GateReason::kApproachUncertain:
      return "approach_uncertain";
    case GateReason::kOutsideWorkspace:
      return "outside_workspace";
  }
  return "unknown";
}

namespace {

GateVerdict Refuse(GateReason reason, const std::string& message) {
  return {false, reason, message};
}

bool Inside(const Eigen::Vector3d& p, const SafetyGateOptions& o) {
  return p.allFinite() && p.x() >= o.workspace_min_x_m && p.x() <= o.workspace_max_x_m &&
         p.y() >= o.workspace_min_y_m && p.y() <= o.workspace_max_y_m &&
         p.z() >= o.workspace_min_z_m && p.z() <= o.workspace_max_z_m;
}

}  // namespace

GateVerdict CheckSafety(const SafetyState& s, const SafetyGateOptions& o) {
  std::string error;
  if (!o.IsValid(&error)) return Refuse(GateReason::kStopped, "invalid gate options: " + error);
  char text[200];
  if (s.stopped) return Refuse(GateReason::kStopped, "stopped by the operator");
  if (!s.operator_confirmed)
    return Refuse(GateReason::kNotConfirmed, "waiting for the operator's confirmation");
  if (!s.tracking) return Refuse(GateReason::kTrackingLost, "button lost");
  if (!(s.tracking_confidence >= o.min_confidence)) {
    std::snprintf(text, sizeof(text), "tracking confidence %.2f below %.2f", s.tracking_confidence,
                  o.min_confidence);
    return Refuse(GateReason::kTrackingPoor, text);
  }
  if (!s.has_estimate) return Refuse(GateReason::kNoEstimate, "no 3D position yet");
  if (!(s.estimate_age_ms >= 0 && s.estimate_age_ms <= o.max_age_ms)) {
    std::snprintf(text, sizeof(text), "estimate %.0f ms old (limit %.0f ms)", s.estimate_age_ms,
                  o.max_age_ms);
    return Refuse(GateReason::kStale, text);
  }
  if (!s.scale_converged)
    return Refuse(GateReason::kScaleNotConverged, "metric scale not converged");
  if (!s.plane_sound) return Refuse(GateReason::kPlaneUnsound, "panel plane fit not sound");
  if (!(s.uncertainty_m <= o.max_uncertainty_m)) {
    std::snprintf(text, sizeof(text), "uncertainty %.1f mm above %.1f mm", s.uncertainty_m * 1e3,
                  o.max_uncertainty_m * 1e3);
    return Refuse(GateReason::kUncertain, text);
  }
  if (!(s.approach_sigma_deg <= o.max_approach_sigma_deg)) {
    std::snprintf(text, sizeof(text), "approach direction uncertain: %.1f deg above %.1f deg",
                  s.approach_sigma_deg, o.max_approach_sigma_deg);
    return Refuse(GateReason::kApproachUncertain, text);
  }
  if (!IsUnitVector(s.approach_in_base)) {
    return Refuse(GateReason::kApproachUncertain, "approach direction not a unit vector");
  }
  if (!(s.hand_eye_deg <= o.max_hand_eye_deg)) {
    std::snprintf(text, sizeof(text),
                  "hand-eye inconsistent: the arm's and the SLAM's motion differ by %.1f deg "
                  "(limit %.1f deg); check hand_eye.yaml",
                  s.hand_eye_deg, o.max_hand_eye_deg);
    return Refuse(GateReason::kUncertain, text);
  }
  if (o.require_hand_eye_check && !s.hand_eye_translation_verified) {
    return Refuse(GateReason::kUncertain,
                  "hand-eye translation not verified online: the arm has not rotated "
                  "(button.gate.require_hand_eye_check)");
  }
  if (!Inside(s.target_in_base, o)) {
    std::snprintf(text, sizeof(text), "target (%.2f, %.2f, %.2f) m outside the workspace",
                  s.target_in_base.x(), s.target_in_base.y(), s.target_in_base.z());
    return Refuse(GateReason::kOutsideWorkspace, text);
  }
  if (!s.hand_eye_translation_verified) {
    return {true, GateReason::kSend,
            "target sent; hand-eye translation not verified online (the arm has not rotated): "
            "taken on trust from hand_eye.yaml"};
  }
  return {true, GateReason::kSend, "target sent"};
}

std::vector<std::string> LooserGateWarnings(const SafetyGateOptions& o) {
  const SafetyGateOptions d;
  std::vector<std::string> out;
  auto check = [&](bool looser, const char* key, double value, double def) {
    if (!looser) return;
    char text[200];
    std::snprintf(text, sizeof(text),
                  "warning: safety gate loosened: button.gate.%s = %g (default %g)", key, value,
                  def);
    out.push_back(text);
  };
  check(o.max_age_ms > d.max_age_ms, "max_age_ms", o.max_age_ms, d.max_age_ms);
  check(o.min_confidence < d.min_confidence, "min_confidence", o.min_confidence, d.min_confidence);
  check(o.max_uncertainty_m > d.max_uncertainty_m, "max_uncertainty_m", o.max_uncertainty_m,
        d.max_uncertainty_m);
  check(o.max_approach_sigma_deg > d.max_approach_sigma_deg, "max_approach_sigma_deg",
        o.max_approach_sigma_deg, d.max_approach_sigma_deg);
  check(o.workspace_min_x_m < d.workspace_min_x_m, "workspace_min_x_m", o.workspace_min_x_m,
        d.workspace_min_x_m);
  check(o.workspace_max_x_m > d.workspace_max_x_m, "workspace_max_x_m", o.workspace_max_x_m,
        d.workspace_max_x_m);
  check(o.workspace_min_y_m < d.workspace_min_y_m, "workspace_min_y_m", o.workspace_min_y_m,
        d.workspace_min_y_m);
  check(o.workspace_max_y_m > d.workspace_max_y_m, "workspace_max_y_m", o.workspace_max_y_m,
        d.workspace_max_y_m);
  check(o.workspace_min_z_m < d.workspace_min_z_m, "workspace_min_z_m", o.workspace_min_z_m,
        d.workspace_min_z_m);
  check(o.workspace_max_z_m > d.workspace_max_z_m, "workspace_max_z_m", o.workspace_max_z_m,
        d.workspace_max_z_m);
  check(o.max_hand_eye_deg > d.max_hand_eye_deg, "max_hand_eye_deg", o.max_hand_eye_deg,
        d.max_hand_eye_deg);
  check(d.require_hand_eye_check && !o.require_hand_eye_check, "require_hand_eye_check", 0, 1);
  return out;
}

}  // namespace sightline
