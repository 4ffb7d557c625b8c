#include "core/sim/motion.h"

#include <cmath>

#include "core/sim/random.h"

namespace sightline::sim {
namespace {

constexpr double kDeg = M_PI / 180;

Eigen::Isometry3d PlanarPose(const PathPose& p, double z = 0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(p.heading_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(p.position.x(), p.position.y(), z);
  return pose;
}

// A smooth random wobble in [-1, 1]: three sinusoids of random frequency and phase.
struct Wobble {
  double frequency[3], phase[3];
  explicit Wobble(std::mt19937& engine) {
    for (int k = 0; k < 3; ++k) {
      frequency[k] = Uniform(engine, 0.15, 1.2) * (k + 1);
      phase[k] = Uniform(engine, 0, 2 * M_PI);
    }
  }
  double At(double t) const {
    double sum = 0;
    for (int k = 0; k < 3; ++k) sum += std::sin(2 * M_PI * frequency[k] * t + phase[k]) / (k + 1);
    return sum / 1.8333;
  }
};

StatusOr<PlanarPath> RouteOf(const Scene& scene, const MotionOptions& motion) {
  if (scene.hints.route.size() < 2) {
    return InvalidArgument("scene '" + scene.name() +
                           "' has no route for a robot or handheld "
                           "motion (MotionHints::route)");
  }
  auto path = PlanarPath::Through(
      scene.hints.route, motion.turn_radius_m,
      scene.hints.route_loops ? PlanarPath::End::kLoop : PlanarPath::End::kStop);
  if (!path.ok()) return path.status().WithContext("sim.motion.turn_radius_m");
  return path;
}

Eigen::Isometry3d EndEffectorFromCamera(const ArmOptions& arm) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  // Columns: the camera's x (right), y (down), z (optical axis) in the end-effector frame.
  t.linear() << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  t.translation() = Eigen::Vector3d(arm.camera_offset_x_m, 0, arm.camera_offset_z_m);
  return t;
}

// The handheld camera circling motion.orbit_center_*, looking at its target point, wobbling.
void PlanOrbit(const MotionOptions& motion, uint64_t seed, MotionPlan* plan) {
  std::mt19937 engine = MakeEngine(DeriveSeed(seed, 0x0B17));
  Wobble x(engine), y(engine), z(engine), yaw(engine), pitch(engine), roll(engine);
  plan->body_from_camera.linear() = BodyFromOptical(0);
  const Eigen::Vector3d target(motion.orbit_center_x_m, motion.orbit_center_y_m,
                               motion.orbit_target_z_m);
  const double a = motion.shake_m, r = motion.shake_deg * kDeg;
  for (double t : plan->times_s) {
    const double angle = motion.orbit_deg_per_s * kDeg * t;
    const Eigen::Vector3d centre =
        Eigen::Vector3d(target.x() + motion.orbit_radius_m * std::cos(angle),
                        target.y() + motion.orbit_radius_m * std::sin(angle),
                        motion.camera_height_m) +
        a * Eigen::Vector3d(x.At(t), y.At(t), z.At(t));
    // Body x towards the target, z as close to up as that allows (REP-103).
    const Eigen::Vector3d forward = (target - centre).normalized();
    const Eigen::Vector3d left = Eigen::Vector3d::UnitZ().cross(forward).normalized();
    Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
    body.linear().col(0) = forward;
    body.linear().col(1) = left;
    body.linear().col(2) = forward.cross(left);
    body.translation() = centre;
    body.rotate(Eigen::AngleAxisd(r * yaw.At(t), Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(r * pitch.At(t), Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(r * roll.At(t), Eigen::Vector3d::UnitX()));
    plan->world_from_body.push_back(body);
  }
}

}  // namespace

bool MotionOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "sim.motion." + m;
    return false;
  };
  if (kind != "auto" && kind != "robot" && kind != "handheld" && kind != "orbit" && kind != "arm" &&
      kind != "static") {
    return fail("kind = '" + kind + "': must be auto, robot, handheld, orbit, arm or static");
  }
  if (!(speed_mps >= 0 && speed_mps <= 5)) return fail("speed_mps must lie in [0, 5] m/s");
  if (!(turn_radius_m >= 0 && turn_radius_m <= 5))
    return fail("turn_radius_m must lie in [0, 5] m");
  if (!(camera_height_m >= 0.05 && camera_height_m <= 3)) {
    return fail("camera_height_m must lie in [0.05, 3] m");
  }
  if (!(camera_tilt_deg >= -60 && camera_tilt_deg <= 89)) {
    return fail("camera_tilt_deg must lie in [-60, 89] deg");
  }
  if (!(std::abs(camera_forward_m) <= 1)) return fail("camera_forward_m must lie in [-1, 1] m");
  if (!(shake_m >= 0 && shake_m <= 0.5)) return fail("shake_m must lie in [0, 0.5] m");
  if (!(shake_deg >= 0 && shake_deg <= 30)) return fail("shake_deg must lie in [0, 30] deg");
  if (!(std::abs(orbit_center_x_m) <= 100 && std::abs(orbit_center_y_m) <= 100)) {
    return fail("orbit_center_x_m and orbit_center_y_m must lie in [-100, 100] m");
  }
  if (!(orbit_target_z_m >= -1 && orbit_target_z_m <= 3)) {
    return fail("orbit_target_z_m must lie in [-1, 3] m");
  }
  if (!(orbit_radius_m >= 0.2 && orbit_radius_m <= 20)) {
    return fail("orbit_radius_m must lie in [0.2, 20] m");
  }
  if (!(std::abs(orbit_deg_per_s) <= 180)) return fail("orbit_deg_per_s must lie in [-180, 180]");
  return true;
}

OptionTable<MotionOptions> MotionOptions::Describe() {
  using O = MotionOptions;
  return OptionTable<O>("motion")
      .Choice("kind", &O::kind, {"auto", "robot", "handheld", "orbit", "arm", "static"},
              "Sensor carrier: auto picks arm for the panel, robot for routes; orbit circles "
              "a point with a handheld camera.")
      .Double("speed_mps", &O::speed_mps, "m/s", 0, 5, 0.05, "Speed along the route.")
      .Double("turn_radius_m", &O::turn_radius_m, "m", 0, 5, 0.05,
              "Radius of the route's 90 deg turns (0 = turn on the spot is not allowed; use a "
              "small radius).")
      .Double("camera_height_m", &O::camera_height_m, "m", 0.05, 3, 0.05,
              "Optical centre above the floor (robot) or mean height (handheld).")
      .Double("camera_tilt_deg", &O::camera_tilt_deg, "deg", -60, 89, 1,
              "Camera pitched down by this angle.")
      .Double("camera_forward_m", &O::camera_forward_m, "m", -1, 1, 0.01,
              "Robot: optical centre ahead of the base centre.")
      .Double("shake_m", &O::shake_m, "m", 0, 0.5, 0.005, "Handheld: positional wobble.")
      .Double("shake_deg", &O::shake_deg, "deg", 0, 30, 0.5, "Handheld: angular wobble.")
      .Double("orbit_center_x_m", &O::orbit_center_x_m, "m", -100, 100, 0.1,
              "Orbit: map x of the centre of the circle.")
      .Double("orbit_center_y_m", &O::orbit_center_y_m, "m", -100, 100, 0.1,
              "Orbit: map y of the centre of the circle.")
      .Double("orbit_target_z_m", &O::orbit_target_z_m, "m", -1, 3, 0.05,
              "Orbit: height of the point the camera looks at (above the centre).")
      .Double("orbit_radius_m", &O::orbit_radius_m, "m", 0.2, 20, 0.1,
              "Orbit: radius of the circle (the camera at camera_height_m).")
      .Double("orbit_deg_per_s", &O::orbit_deg_per_s, "deg/s", -180, 180, 1,
              "Orbit: angular speed around the centre; 15 deg/s at 2 fps is 7.5 deg per frame.");
}

bool ArmOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "sim.arm." + m;
    return false;
  };
  if (!(end_distance_m >= 0.05 && end_distance_m <= start_distance_m)) {
    return fail("end_distance_m must lie in [0.05, start_distance_m]");
  }
  if (!(start_distance_m <= 5)) return fail("start_distance_m must be <= 5 m");
  if (!(sideways_m >= 0 && sideways_m <= 0.5)) return fail("sideways_m must lie in [0, 0.5] m");
  if (!(sideways_fraction >= 0 && sideways_fraction < 1)) {
    return fail("sideways_fraction must lie in [0, 1)");
  }
  if (!(pose_noise_m >= 0 && pose_noise_m <= 0.05)) {
    return fail("pose_noise_m must lie in [0, 0.05] m");
  }
  if (!(std::abs(camera_offset_x_m) <= 0.5 && std::abs(camera_offset_z_m) <= 0.5)) {
    return fail("camera_offset_x_m and camera_offset_z_m must lie in [-0.5, 0.5] m");
  }
  return true;
}

OptionTable<ArmOptions> ArmOptions::Describe() {
  using O = ArmOptions;
  return OptionTable<O>("arm")
      .Double("start_distance_m", &O::start_distance_m, "m", 0.05, 5, 0.05,
              "Camera to target button at the start.")
      .Double("end_distance_m", &O::end_distance_m, "m", 0.05, 5, 0.05,
              "Camera to target button at the end.")
      .Double("sideways_m", &O::sideways_m, "m", 0, 0.5, 0.01,
              "Amplitude of the initial sideways moves (monocular initialisation).")
      .Double("sideways_fraction", &O::sideways_fraction, "", 0, 0.99, 0.05,
              "Part of the recording spent moving sideways before the approach.")
      .Double("pose_noise_m", &O::pose_noise_m, "m", 0, 0.05, 0.0001,
              "Gaussian noise of the arm positions written to arm_poses.txt.")
      .Double("camera_offset_x_m", &O::camera_offset_x_m, "m", -0.5, 0.5, 0.005,
              "Hand-eye: camera centre along the end effector's x axis.")
      .Double("camera_offset_z_m", &O::camera_offset_z_m, "m", -0.5, 0.5, 0.005,
              "Hand-eye: camera centre along the end effector's z (tool) axis.");
}

Eigen::Matrix3d BodyFromOptical(double tilt) {
  Eigen::Matrix3d r;
  // Columns: optical x (right), y (down), z (forward) in the body frame (x fwd, y left, z up).
  r.col(0) = Eigen::Vector3d(0, -1, 0);
  r.col(2) = Eigen::Vector3d(std::cos(tilt), 0, -std::sin(tilt));
  r.col(1) = r.col(2).cross(r.col(0));
  return r;
}

StatusOr<MotionPlan> PlanMotion(const Scene& scene, const MotionOptions& motion,
                                const ArmOptions& arm, int frames, double rate_hz, uint64_t seed) {
  std::string error;
  if (!motion.IsValid(&error) || !arm.IsValid(&error)) return InvalidArgument(error);
  if (frames < 1) return InvalidArgument("sim.frames must be at least 1");
  if (!(rate_hz > 0)) return InvalidArgument("sim.rate_hz must be positive");
  MotionPlan plan;
  plan.kind = motion.kind;
  if (plan.kind == "auto") {
    plan.kind = scene.hints.target_button >= 0  ? "arm"
                : scene.hints.route.size() >= 2 ? "robot"
                                                : "static";
  }
  for (int i = 0; i < frames; ++i) plan.times_s.push_back(i / rate_hz);
  const double tilt = motion.camera_tilt_deg * kDeg;

  if (plan.kind == "robot" || (plan.kind == "static" && scene.hints.route.size() >= 2)) {
    auto path = RouteOf(scene, motion);
    if (!path.ok()) return path.status();
    plan.body_from_camera.linear() = BodyFromOptical(tilt);
    plan.body_from_camera.translation() =
        Eigen::Vector3d(motion.camera_forward_m, 0, motion.camera_height_m);
    const double speed = plan.kind == "static" ? 0.0 : motion.speed_mps;
    for (double t : plan.times_s) plan.world_from_body.push_back(PlanarPose(path->At(speed * t)));
    return plan;
  }
  if (plan.kind == "static") {  // No route: at the origin, looking along x.
    plan.body_from_camera.linear() = BodyFromOptical(tilt);
    plan.body_from_camera.translation() = Eigen::Vector3d(0, 0, motion.camera_height_m);
    plan.world_from_body.assign(frames, Eigen::Isometry3d::Identity());
    return plan;
  }
  if (plan.kind == "orbit") {
    PlanOrbit(motion, seed, &plan);
    return plan;
  }
  if (plan.kind == "handheld") {
    auto path = RouteOf(scene, motion);
    if (!path.ok()) return path.status();
    std::mt19937 engine = MakeEngine(DeriveSeed(seed, 0x4A4D));
    Wobble x(engine), y(engine), z(engine), yaw(engine), pitch(engine), roll(engine);
    plan.body_from_camera.linear() = BodyFromOptical(tilt);
    const double a = motion.shake_m, r = motion.shake_deg * kDeg;
    for (double t : plan.times_s) {
      Eigen::Isometry3d body = PlanarPose(path->At(motion.speed_mps * t), motion.camera_height_m);
      body.translate(Eigen::Vector3d(a * x.At(t), a * y.At(t), a * z.At(t)));
      body.rotate(Eigen::AngleAxisd(r * yaw.At(t), Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(r * pitch.At(t), Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(r * roll.At(t), Eigen::Vector3d::UnitX()));
      plan.world_from_body.push_back(body);
    }
    return plan;
  }
  if (plan.kind != "arm") return InvalidArgument("sim.motion.kind '" + plan.kind + "' unknown");
  const int target = scene.hints.target_button;
  if (target < 0 || target >= static_cast<int>(scene.buttons.size())) {
    return InvalidArgument("scene '" + scene.name() +
                           "' has no target button for an arm "
                           "motion (MotionHints::target_button)");
  }
  const ButtonSpec& button = scene.buttons[target];
  plan.world_from_arm_base = scene.hints.world_from_arm_base;
  const Eigen::Isometry3d ee_from_camera = EndEffectorFromCamera(arm);
  plan.body_from_camera = ee_from_camera;
  // The camera looks into the panel (along -normal) with the map's z up in the image.
  Eigen::Matrix3d world_from_optical;
  world_from_optical.col(2) = -button.normal.normalized();
  world_from_optical.col(0) =
      world_from_optical.col(2).cross(Eigen::Vector3d::UnitZ()).normalized();
  world_from_optical.col(1) = world_from_optical.col(2).cross(world_from_optical.col(0));
  const double duration = frames > 1 ? plan.times_s.back() : 1.0;
  for (double t : plan.times_s) {
    const double tau = t / duration;
    double distance = arm.start_distance_m, lateral = 0;
    if (tau < arm.sideways_fraction) {
      lateral = arm.sideways_m * std::sin(2 * M_PI * tau / arm.sideways_fraction);
    } else {
      const double u = (tau - arm.sideways_fraction) / (1 - arm.sideways_fraction);
      const double smooth = u * u * (3 - 2 * u);
      distance = arm.start_distance_m + smooth * (arm.end_distance_m - arm.start_distance_m);
    }
    Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
    world_from_camera.linear() = world_from_optical;
    world_from_camera.translation() =
        button.center + distance * button.normal + lateral * world_from_optical.col(0);
    plan.world_from_body.push_back(world_from_camera * ee_from_camera.inverse());
  }
  return plan;
}

}  // namespace sightline::sim
