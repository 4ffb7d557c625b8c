// A simulated arm for the operator loop: it knows the panel scene of its seed, flies
// the recorded approach's plan (start pose, a still hold, the sideways moves the metric scale
// needs, an approach towards the panel), then follows the targets Sightline publishes at a
// bounded speed: first to a standoff in front of the target, then pushing along `approach` onto
// it. A stop line freezes it at once; a silent link holds it. The control logic only: lines and
// clock come from the caller (arm_sim_session.h runs it over TCP), so tests can drive it
// deterministically.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/button/arm_protocol.h"
#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// The simulated arm's settings. Keys "armsim.*".
struct ArmSimOptions {
  double max_speed_mps = 0.02;        // End-effector speed limit while following targets [m/s].
  double max_angular_speed_dps = 10;  // Its rotation speed limit [deg/s].
  double control_period_s = 0.01;     // One control step (and one arm_pose line) [s].
  double standoff_m = 0.05;           // Pre-press point: target - approach x this [m].
  double hold_s = 2;                  // Still at the start pose before the plan moves [s].
  double plan_s = 40;                 // Sideways moves plus approach [s].
  double sideways_m = 0.12;           // Amplitude of the sideways moves [m].
  double sideways_fraction = 0.4;     // Part of plan_s spent moving sideways.
  double start_distance_m = 1.0;      // Camera to the seed's target button at the start [m].
  double approach_end_m = 0.4;        // ... at the end of the plan's approach [m].
  double heartbeat_s = 0.5;           // The server's heartbeat period; 3 silent ones = hold [s].
  double reach_tolerance_m = 0.0001;  // Reached when this close to the target [m].
  double settle_s = 2;                // Finished after holding a reached target this long [s].
  double max_time_s = 900;            // The session ends after this long in any case [s].

  bool IsValid(std::string* error) const;
  static OptionTable<ArmSimOptions> Describe();
};

// A true button of the scene, in the arm's base frame.
struct ArmSimButton {
  int id = -1;
  std::string label;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();   // Centre of the front face [m].
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // Out of the panel.
};

// What the arm knows of its world: the panel scene of a seed (the simulator's `panel` with its
// defaults) and the plan it flies first.
struct ArmSimWorld {
  int seed = 4;
  Eigen::Isometry3d world_from_base = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d end_effector_from_camera = Eigen::Isometry3d::Identity();  // Hand-eye.
  std::vector<ArmSimButton> buttons;
  int plan_button = -1;                 // The button the plan approaches.
  std::vector<Eigen::Isometry3d> plan;  // base_from_end_effector every control period.
  double plan_period_s = 0.01;

  // The plan's pose `t` seconds after its start (clamped to its span).
  Eigen::Isometry3d PlanPose(double t) const;
  const ArmSimButton* FindButton(int id) const;
};
// Builds the panel scene of `seed` and samples the plan. InvalidArgument for bad options.
StatusOr<ArmSimWorld> BuildArmSimWorld(int seed, const ArmSimOptions& options = {});

enum class ArmSimPhase {
  kHold,        // Still at the start pose.
  kSideways,    // The plan's sideways moves.
  kApproach,    // The plan's approach.
  kWaiting,     // Plan done, no target yet.
  kToStandoff,  // Moving to target - approach x standoff.
  kPushing,     // Moving along the approach onto the target.
  kReached,     // At the target.
};
const char* ArmSimPhaseName(ArmSimPhase phase);

// One logged event; `time_s` on the caller's clock.
struct ArmSimEvent {
  double time_s = 0;
  std::string what;
};

// Where the arm ended, against the scene's truth.
struct ArmSimOutcome {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();    // End effector in the base frame [m].
  Eigen::Vector3d tool_axis = Eigen::Vector3d::UnitZ();  // Its z axis in the base frame.
  int nearest_button = -1;
  double distance_mm = 0;         // To the nearest true button centre [mm].
  double lateral_mm = 0;          // ... across the panel (off the button's axis) [mm].
  double depth_mm = 0;            // ... along the push: + beyond its front face [mm].
  double approach_error_deg = 0;  // Tool axis against the push direction (-normal) [deg].
};

// Every control step: where the end effector was.
struct ArmSimStep {
  double time_s = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

class ArmSimulator {
 public:
  ArmSimulator(ArmSimOptions options, ArmSimWorld world);

  // Called for every logged event as it happens (besides being kept in events()).
  void set_event_sink(std::function<void(const ArmSimEvent&)> sink) { sink_ = std::move(sink); }
  // Starts the plan's clock (logs "connected" with `note`).
  void Start(double now_s, const std::string& note = "connected");
  // One server line received at `now_s`. Malformed lines are counted by their reason.
  void OnLine(const std::string& line, double now_s);
  // One control period ending at `now_s`: moves (or not) and returns base_from_end_effector.
  const Eigen::Isometry3d& Step(double now_s);
  // Reached, and no newer target moved it for settle_s.
  bool Finished(double now_s) const;

  const Eigen::Isometry3d& pose() const { return pose_; }
  ArmSimPhase phase() const { return phase_; }
  bool stopped() const { return stopped_; }
  bool holding() const { return holding_; }
  const std::optional<ArmTarget>& target() const { return target_; }
  const std::vector<ArmSimEvent>& events() const { return events_; }
  const std::vector<ArmSimStep>& steps() const { return steps_; }
  // Arrival time of the last stop line; nullopt when none came.
  std::optional<double> last_stop_s() const { return last_stop_s_; }
  const std::map<std::string, int64_t>& counts() const { return counts_; }
  // Malformed lines by reason.
  const std::map<std::string, int64_t>& malformed() const { return malformed_; }
  ArmSimOutcome Outcome() const;
  const ArmSimWorld& world() const { return world_; }
  const ArmSimOptions& options() const { return options_; }

 private:
  void Log(double now_s, const std::string& what);
  void SetPhase(ArmSimPhase phase, double now_s, const std::string& detail = "");
  void TakeTarget(const ArmTarget& target, double now_s);
  void PlanStep(double dt, double now_s);
  void FollowStep(double dt, double now_s);

  ArmSimOptions options_;
  ArmSimWorld world_;
  std::function<void(const ArmSimEvent&)> sink_;
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
  ArmSimPhase phase_ = ArmSimPhase::kHold;
  double plan_time_s_ = 0;  // Advances only while the arm may move.
  double last_step_s_ = 0;
  double last_line_s_ = 0;
  double reached_s_ = 0;
  bool started_ = false;
  bool stopped_ = false;
  bool holding_ = false;
  std::optional<ArmTarget> target_;
  std::optional<double> last_stop_s_;
  std::vector<ArmSimEvent> events_;
  std::vector<ArmSimStep> steps_;
  std::map<std::string, int64_t> counts_;
  std::map<std::string, int64_t> malformed_;
};

// base_from_end_effector whose tool (z) axis points along `approach`, x as close to the base's
// up (z) as the approach allows (the plan's camera roll: the map's up is up in the image).
Eigen::Matrix3d ToolOrientation(const Eigen::Vector3d& approach);

}  // namespace sightline
