#include "core/button/arm_simulator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/button/server_lines.h"
#include "core/sim/motion.h"
#include "core/sim/simulation_options.h"

namespace sightline {
namespace {

constexpr double kDeg = M_PI / 180;

std::string Format(const char* format, double a, double b = 0, double c = 0, double d = 0) {
  char text[160];
  std::snprintf(text, sizeof(text), format, a, b, c, d);
  return text;
}

// Moves `from` toward `to` by at most `step_m` and `step_rad`; true when it got there.
bool StepToward(const Eigen::Isometry3d& to, double step_m, double step_rad,
                Eigen::Isometry3d* from) {
  const Eigen::Vector3d delta = to.translation() - from->translation();
  const double distance = delta.norm();
  const Eigen::Vector3d position =
      distance <= step_m ? to.translation()
                         : Eigen::Vector3d(from->translation() + delta * (step_m / distance));
  const Eigen::Quaterniond q_from(from->linear()), q_to(to.linear());
  const double angle = q_from.angularDistance(q_to);
  const Eigen::Quaterniond q = angle <= step_rad ? q_to : q_from.slerp(step_rad / angle, q_to);
  from->linear() = q.normalized().toRotationMatrix();
  from->translation() = position;
  return distance <= step_m && angle <= step_rad;
}

}  // namespace

bool ArmSimOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "armsim." + m;
    return false;
  };
  if (!(max_speed_mps > 0 && max_speed_mps <= 1)) return fail("max_speed_mps must lie in (0, 1]");
  if (!(max_angular_speed_dps > 0 && max_angular_speed_dps <= 180)) {
    return fail("max_angular_speed_dps must lie in (0, 180]");
  }
  if (!(control_period_s >= 0.001 && control_period_s <= 0.1)) {
    return fail("control_period_s must lie in [0.001, 0.1]");
  }
  if (!(standoff_m >= 0 && standoff_m <= 0.5)) return fail("standoff_m must lie in [0, 0.5]");
  if (!(hold_s >= 0 && plan_s > 0)) return fail("hold_s must be >= 0 and plan_s > 0");
  if (!(approach_end_m >= 0.05 && approach_end_m <= start_distance_m && start_distance_m <= 5)) {
    return fail("approach_end_m must lie in [0.05, start_distance_m <= 5]");
  }
  if (!(sideways_m >= 0 && sideways_m <= 0.5)) return fail("sideways_m must lie in [0, 0.5]");
  if (!(sideways_fraction >= 0 && sideways_fraction < 1)) {
    return fail("sideways_fraction must lie in [0, 1)");
  }
  if (!(heartbeat_s >= 0 && reach_tolerance_m > 0 && settle_s >= 0 && max_time_s > 0)) {
    return fail("heartbeat_s, settle_s must be >= 0; reach_tolerance_m, max_time_s > 0");
  }
  return true;
}

OptionTable<ArmSimOptions> ArmSimOptions::Describe() {
  using O = ArmSimOptions;
  return OptionTable<O>("armsim")
      .Double("max_speed_mps", &O::max_speed_mps, "m/s", 0.001, 1, 0.005,
              "End-effector speed limit while following targets.")
      .Double("max_angular_speed_dps", &O::max_angular_speed_dps, "deg/s", 0.1, 180, 1,
              "End-effector rotation speed limit while following targets.")
      .Double("control_period_s", &O::control_period_s, "s", 0.001, 0.1, 0.001,
              "One control step; an arm_pose line is sent every step.")
      .Double("standoff_m", &O::standoff_m, "m", 0, 0.5, 0.01,
              "Pre-press point: the arm first goes to target - approach x this, then pushes.")
      .Double("hold_s", &O::hold_s, "s", 0, 60, 0.5, "Still at the start pose before the plan.")
      .Double("plan_s", &O::plan_s, "s", 0.1, 600, 1,
              "Duration of the plan's sideways moves and approach.")
      .Double("sideways_m", &O::sideways_m, "m", 0, 0.5, 0.01,
              "Amplitude of the plan's sideways moves (metric scale).")
      .Double("sideways_fraction", &O::sideways_fraction, "", 0, 0.99, 0.05,
              "Part of plan_s spent moving sideways.")
      .Double("start_distance_m", &O::start_distance_m, "m", 0.05, 5, 0.05,
              "Camera to the scene's target button at the start pose.")
      .Double("approach_end_m", &O::approach_end_m, "m", 0.05, 5, 0.05,
              "Camera to the scene's target button at the end of the plan.")
      .Double("heartbeat_s", &O::heartbeat_s, "s", 0, 10, 0.1,
              "The server's heartbeat period; no line for 3 of them holds the arm (0 = never).")
      .Double("reach_tolerance_m", &O::reach_tolerance_m, "m", 1e-6, 0.01, 0.0001,
              "The target counts as reached this close.")
      .Double("settle_s", &O::settle_s, "s", 0, 60, 0.5,
              "The session ends after holding a reached target this long.")
      .Double("max_time_s", &O::max_time_s, "s", 1, 86400, 10,
              "The session ends after this long in any case.");
}

Eigen::Isometry3d ArmSimWorld::PlanPose(double t) const {
  if (plan.empty()) return Eigen::Isometry3d::Identity();
  const double index = std::clamp(t / plan_period_s, 0.0, double(plan.size() - 1));
  return plan[static_cast<size_t>(std::lround(index))];
}

const ArmSimButton* ArmSimWorld::FindButton(int id) const {
  for (const ArmSimButton& b : buttons) {
    if (b.id == id) return &b;
  }
  return nullptr;
}

StatusOr<ArmSimWorld> BuildArmSimWorld(int seed, const ArmSimOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  sim::SimulationOptions sim = sim::SimulationOptions::ForScene("panel");
  sim.seed = seed;
  sim.arm.start_distance_m = options.start_distance_m;
  sim.arm.end_distance_m = options.approach_end_m;
  sim.arm.sideways_m = options.sideways_m;
  sim.arm.sideways_fraction = options.sideways_fraction;
  StatusOr<sim::Scene> scene = sim::BuildPanel(sim.panel, static_cast<uint64_t>(seed));
  if (!scene.ok()) return scene.status();
  const int steps = static_cast<int>(std::lround(options.plan_s / options.control_period_s)) + 1;
  StatusOr<sim::MotionPlan> plan =
      sim::PlanMotion(*scene, sim.motion, sim.arm, steps, 1.0 / options.control_period_s, 0);
  if (!plan.ok()) return plan.status();
  ArmSimWorld world;
  world.seed = seed;
  world.world_from_base = plan->world_from_arm_base;
  world.end_effector_from_camera = plan->body_from_camera;
  world.plan_button = scene->hints.target_button;
  world.plan_period_s = options.control_period_s;
  const Eigen::Isometry3d base_from_world = world.world_from_base.inverse();
  for (const Eigen::Isometry3d& body : plan->world_from_body) {
    world.plan.push_back(base_from_world * body);
  }
  for (const sim::ButtonSpec& b : scene->buttons) {
    world.buttons.push_back(
        {b.id, b.label, base_from_world * b.center, base_from_world.linear() * b.normal});
  }
  return world;
}

const char* ArmSimPhaseName(ArmSimPhase phase) {
  switch (phase) {
    case ArmSimPhase::kHold:
      return "hold";
    case ArmSimPhase::kSideways:
      return "sideways";
    case ArmSimPhase::kApproach:
      return "approach";
    case ArmSimPhase::kWaiting:
      return "waiting for a target";
    case ArmSimPhase::kToStandoff:
      return "moving to the standoff";
    case ArmSimPhase::kPushing:
      return "pushing";
    case ArmSimPhase::kReached:
      return "reached";
  }
  return "?";
}

Eigen::Matrix3d ToolOrientation(const Eigen::Vector3d& approach) {
  const Eigen::Vector3d z = approach.normalized();
  Eigen::Vector3d x = Eigen::Vector3d::UnitZ() - z * z.z();
  if (x.norm() < 1e-6) x = Eigen::Vector3d::UnitX() - z * z.x();  // Straight up or down.
  x.normalize();
  Eigen::Matrix3d r;
  r.col(0) = x;
  r.col(1) = z.cross(x);
  r.col(2) = z;
  return r;
}

ArmSimulator::ArmSimulator(ArmSimOptions options, ArmSimWorld world)
    : options_(options), world_(std::move(world)) {
  pose_ = world_.PlanPose(0);
}

void ArmSimulator::Log(double now_s, const std::string& what) {
  events_.push_back({now_s, what});
  if (sink_) sink_(events_.back());
}

void ArmSimulator::SetPhase(ArmSimPhase phase, double now_s, const std::string& detail) {
  if (phase == phase_ && detail.empty()) return;
  phase_ = phase;
  const bool plan = phase <= ArmSimPhase::kApproach;
  Log(now_s, std::string(plan ? "plan: " : "") + ArmSimPhaseName(phase) + detail);
}

void ArmSimulator::Start(double now_s, const std::string& note) {
  started_ = true;
  last_step_s_ = last_line_s_ = now_s;
  Log(now_s, note);
  phase_ = ArmSimPhase::kHold;
  Log(now_s, Format("plan: hold %.1f s at the start pose, then %.1f s of sideways moves and "
                    "approach",
                    options_.hold_s, options_.plan_s));
}

void ArmSimulator::OnLine(const std::string& line, double now_s) {
  last_line_s_ = now_s;
  ++counts_["lines"];
  StatusOr<ServerLine> parsed = ParseServerLine(line);
  if (parsed.ok() && parsed->type == ServerLine::Type::kTarget &&
      parsed->target.frame_id != "arm_base") {
    parsed = InvalidArgument("server line: \"frame_id\" '" + parsed->target.frame_id +
                             "' is not arm_base");
  }
  if (!parsed.ok()) {
    ++malformed_[parsed.status().message()];
    ++counts_["malformed"];
    Log(now_s, "malformed line ignored: " + parsed.status().message());
    return;
  }
  switch (parsed->type) {
    case ServerLine::Type::kHeartbeat:
      ++counts_["heartbeats"];
      break;
    case ServerLine::Type::kStop:
      ++counts_["stops"];
      last_stop_s_ = now_s;
      if (!stopped_) {
        stopped_ = true;
        const Eigen::Vector3d p = pose_.translation();
        Log(now_s, "stopped (" + parsed->reason + ")" +
                       Format(" at [%.4f, %.4f, %.4f]", p.x(), p.y(), p.z()));
      }
      break;
    case ServerLine::Type::kTarget:
      ++counts_["targets"];
      TakeTarget(parsed->target, now_s);
      break;
  }
}

void ArmSimulator::TakeTarget(const ArmTarget& target, double now_s) {
  if (stopped_) {
    stopped_ = false;
    Log(now_s, "resumed: a target after the stop");
  }
  const bool first = !target_;
  const bool moved =
      first || (target.position_m - target_->position_m).norm() > options_.reach_tolerance_m ||
      target.approach.dot(target_->approach) < std::cos(0.1 * kDeg);
  const bool far = !first && ((target.position_m - target_->position_m).norm() > 0.01 ||
                              target.approach.dot(target_->approach) < std::cos(3 * kDeg));
  target_ = target;
  const Eigen::Vector3d& p = target.position_m;
  if (first || far) {
    Log(now_s, Format("target received: [%.4f, %.4f, %.4f] +-%.1f mm", p.x(), p.y(), p.z(),
                      target.uncertainty_m * 1000));
  }
  if (phase_ < ArmSimPhase::kWaiting) return;  // Followed once the plan is done.
  if (far && phase_ != ArmSimPhase::kToStandoff) {
    SetPhase(ArmSimPhase::kToStandoff, now_s, " (the target moved)");
  } else if (moved && phase_ == ArmSimPhase::kReached) {
    SetPhase(ArmSimPhase::kPushing, now_s, " (the target moved)");
  }
}

void ArmSimulator::PlanStep(double dt, double now_s) {
  plan_time_s_ += dt;
  const double t = plan_time_s_ - options_.hold_s;
  if (t < 0) return;
  const double sideways_s = options_.plan_s * options_.sideways_fraction;
  if (t < sideways_s) {
    SetPhase(ArmSimPhase::kSideways, now_s);
  } else if (t < options_.plan_s) {
    SetPhase(ArmSimPhase::kApproach, now_s);
  } else {
    SetPhase(ArmSimPhase::kWaiting, now_s);
    if (target_) SetPhase(ArmSimPhase::kToStandoff, now_s);
  }
  pose_ = world_.PlanPose(t);
}

void ArmSimulator::FollowStep(double dt, double now_s) {
  if (!target_) return;
  if (phase_ == ArmSimPhase::kWaiting) SetPhase(ArmSimPhase::kToStandoff, now_s);
  Eigen::Isometry3d goal = Eigen::Isometry3d::Identity();
  goal.linear() = ToolOrientation(target_->approach);
  goal.translation() = target_->position_m;
  if (phase_ == ArmSimPhase::kToStandoff) {
    goal.translation() -= options_.standoff_m * target_->approach;
  }
  const bool there = StepToward(goal, options_.max_speed_mps * dt,
                                options_.max_angular_speed_dps * kDeg * dt, &pose_);
  if (!there) return;
  if (phase_ == ArmSimPhase::kToStandoff) {
    SetPhase(ArmSimPhase::kPushing, now_s);
  } else if (phase_ == ArmSimPhase::kPushing) {
    reached_s_ = now_s;
    const Eigen::Vector3d p = pose_.translation();
    SetPhase(ArmSimPhase::kReached, now_s, Format(" at [%.4f, %.4f, %.4f]", p.x(), p.y(), p.z()));
  }
}

const Eigen::Isometry3d& ArmSimulator::Step(double now_s) {
  if (!started_) Start(now_s);
  // A starved process moves at most two periods' worth: slower, never a jump.
  const double dt = std::clamp(now_s - last_step_s_, 0.0, 2 * options_.control_period_s);
  last_step_s_ = now_s;
  const bool silent = options_.heartbeat_s > 0 && now_s - last_line_s_ > 3 * options_.heartbeat_s;
  if (silent != holding_) {
    holding_ = silent;
    Log(now_s, silent ? "holding: no line from the server for 3 heartbeat periods"
                      : "link back: moving on");
  }
  if (!stopped_ && !holding_) {
    if (phase_ < ArmSimPhase::kWaiting) {
      PlanStep(dt, now_s);
    } else {
      FollowStep(dt, now_s);
    }
  }
  steps_.push_back({now_s, pose_.translation()});
  return pose_;
}

bool ArmSimulator::Finished(double now_s) const {
  return phase_ == ArmSimPhase::kReached && !stopped_ && now_s - reached_s_ >= options_.settle_s;
}

ArmSimOutcome ArmSimulator::Outcome() const {
  ArmSimOutcome out;
  out.position = pose_.translation();
  out.tool_axis = pose_.linear().col(2);
  double best = INFINITY;
  for (const ArmSimButton& b : world_.buttons) {
    const double d = (b.center - out.position).norm();
    if (d >= best) continue;
    best = d;
    out.nearest_button = b.id;
    out.distance_mm = d * 1000;
    const Eigen::Vector3d push = -b.normal.normalized();
    out.depth_mm = (out.position - b.center).dot(push) * 1000;
    out.lateral_mm = std::sqrt(std::max(0.0, d * d * 1e6 - out.depth_mm * out.depth_mm));
    const double c = std::clamp(out.tool_axis.dot(-b.normal.normalized()), -1.0, 1.0);
    out.approach_error_deg = std::acos(c) / kDeg;
  }
  return out;
}

}  // namespace sightline
