// Every rule of the safety gate on its own: a good state sends; each failing condition stops
// it with its own reason.
#include "core/button/safety_gate.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

namespace sightline {
namespace {

SafetyState Good() {
  SafetyState s;
  s.operator_confirmed = true;
  s.tracking = true;
  s.tracking_confidence = 0.9;
  s.has_estimate = true;
  s.estimate_age_ms = 40;
  s.scale_converged = true;
  s.plane_sound = true;
  s.uncertainty_m = 0.003;
  s.approach_sigma_deg = 1.5;
  s.approach_in_base = {1, 0, 0};
  s.target_in_base = {0.5, 0.0, 0.3};
  return s;
}

TEST(SafetyGate, AGoodEstimateIsSent) {
  const GateVerdict v = CheckSafety(Good(), {});
  EXPECT_TRUE(v.send);
  EXPECT_EQ(v.reason, GateReason::kSend);
}

TEST(SafetyGate, EachFailingRuleStopsTheTarget) {
  struct Case {
    const char* name;
    std::function<void(SafetyState&)> spoil;
    GateReason reason;
  };
  const std::vector<Case> cases = {
      {"stop", [](SafetyState& s) { s.stopped = true; }, GateReason::kStopped},
      {"unconfirmed", [](SafetyState& s) { s.operator_confirmed = false; },
       GateReason::kNotConfirmed},
      {"lost", [](SafetyState& s) { s.tracking = false; }, GateReason::kTrackingLost},
      {"weak", [](SafetyState& s) { s.tracking_confidence = 0.1; }, GateReason::kTrackingPoor},
      {"none", [](SafetyState& s) { s.has_estimate = false; }, GateReason::kNoEstimate},
      {"stale", [](SafetyState& s) { s.estimate_age_ms = 201; }, GateReason::kStale},
      {"negative age", [](SafetyState& s) { s.estimate_age_ms = -5; }, GateReason::kStale},
      {"scale", [](SafetyState& s) { s.scale_converged = false; }, GateReason::kScaleNotConverged},
      {"plane", [](SafetyState& s) { s.plane_sound = false; }, GateReason::kPlaneUnsound},
      {"uncertain", [](SafetyState& s) { s.uncertainty_m = 0.05; }, GateReason::kUncertain},
      {"approach uncertain", [](SafetyState& s) { s.approach_sigma_deg = 6; },
       GateReason::kApproachUncertain},
      {"approach unknown",
       [](SafetyState& s) { s.approach_sigma_deg = std::numeric_limits<double>::infinity(); },
       GateReason::kApproachUncertain},
      {"approach zero", [](SafetyState& s) { s.approach_in_base.setZero(); },
       GateReason::kApproachUncertain},
      {"approach tiny",
       [](SafetyState& s) {
         s.approach_in_base = {1e-300, 0, 0};
       },
       GateReason::kApproachUncertain},
      {"approach nan", [](SafetyState& s) { s.approach_in_base.x() = std::nan(""); },
       GateReason::kApproachUncertain},
      {"outside x", [](SafetyState& s) { s.target_in_base.x() = 2.0; },
       GateReason::kOutsideWorkspace},
      {"outside z", [](SafetyState& s) { s.target_in_base.z() = -1.0; },
       GateReason::kOutsideWorkspace},
      {"nan", [](SafetyState& s) { s.target_in_base.y() = std::nan(""); },
       GateReason::kOutsideWorkspace},
      {"hand-eye inconsistent", [](SafetyState& s) { s.hand_eye_deg = 4; }, GateReason::kUncertain},
  };
  for (const Case& c : cases) {
    SafetyState s = Good();
    c.spoil(s);
    const GateVerdict v = CheckSafety(s, {});
    EXPECT_FALSE(v.send) << c.name;
    EXPECT_EQ(v.reason, c.reason) << c.name << ": " << v.message;
    EXPECT_FALSE(v.message.empty()) << c.name;
  }
}

TEST(SafetyGate, AgeLimitIsAnOption) {
  SafetyState s = Good();
  s.estimate_age_ms = 150;
  SafetyGateOptions o;
  EXPECT_TRUE(CheckSafety(s, o).send);
  o.max_age_ms = 100;
  const GateVerdict v = CheckSafety(s, o);
  EXPECT_EQ(v.reason, GateReason::kStale);
  EXPECT_NE(v.message.find("150 ms"), std::string::npos) << v.message;
}

TEST(SafetyGate, StopWinsOverEverything) {
  SafetyState s = Good();
  s.stopped = true;
  s.tracking = false;
  EXPECT_EQ(CheckSafety(s, {}).reason, GateReason::kStopped);
}

TEST(SafetyGate, InvalidOptionsNeverSend) {
  SafetyGateOptions o;
  o.workspace_min_x_m = 2;  // Above max.
  std::string error;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("workspace"), std::string::npos);
  EXPECT_FALSE(CheckSafety(Good(), o).send);
  EXPECT_STREQ(GateReasonKey(GateReason::kStale), "stale");
}

TEST(SafetyGate, AnUnverifiedMountTranslationIsSaidAndRefusedOnRequest) {
  SafetyState s = Good();
  s.hand_eye_translation_verified = false;
  GateVerdict v = CheckSafety(s, {});
  EXPECT_TRUE(v.send);
  EXPECT_NE(v.message.find("not verified"), std::string::npos) << v.message;
  SafetyGateOptions o;
  o.require_hand_eye_check = true;
  v = CheckSafety(s, o);
  EXPECT_FALSE(v.send);
  EXPECT_EQ(v.reason, GateReason::kUncertain);
  EXPECT_NE(v.message.find("require_hand_eye_check"), std::string::npos) << v.message;
  s.hand_eye_translation_verified = true;
  EXPECT_TRUE(CheckSafety(s, o).send);
}

TEST(SafetyGate, EveryLoosenedOptionIsNamedAndTighterOnesAreNot) {
  EXPECT_TRUE(LooserGateWarnings({}).empty());
  SafetyGateOptions o;
  o.max_age_ms = 500;            // Looser.
  o.max_uncertainty_m = 0.05;    // Looser.
  o.workspace_max_z_m = 2;       // Looser.
  o.max_approach_sigma_deg = 2;  // Tighter: no warning.
  o.min_confidence = 0.5;        // Tighter: no warning.
  const std::vector<std::string> w = LooserGateWarnings(o);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_NE(w[0].find("button.gate.max_age_ms = 500"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("button.gate.max_uncertainty_m = 0.05"), std::string::npos) << w[1];
  EXPECT_NE(w[2].find("button.gate.workspace_max_z_m = 2"), std::string::npos) << w[2];
  o = SafetyGateOptions();
  o.min_confidence = 0.1;
  o.max_hand_eye_deg = 10;
  EXPECT_EQ(LooserGateWarnings(o).size(), 2u);
}

}  // namespace
}  // namespace sightline
