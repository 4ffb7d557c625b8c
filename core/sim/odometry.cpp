#include "core/sim/odometry.h"

#include <cmath>

#include "core/sim/random.h"

namespace sightline::sim {
namespace {

constexpr double kDeg = M_PI / 180;

double Yaw(const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d x = pose.linear().col(0);
  return std::atan2(x.y(), x.x());
}

Eigen::Isometry3d Planar(double x, double y, double yaw) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(x, y, 0);
  return pose;
}

}  // namespace

bool OdometryOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "sim.odometry." + m;
    return false;
  };
  if (!(std::abs(heading_drift_deg_per_m) <= 45)) {
    return fail("heading_drift_deg_per_m must lie in [-45, 45] deg/m");
  }
  if (!(std::abs(scale_error) <= 0.5)) return fail("scale_error must lie in [-0.5, 0.5]");
  if (!(distance_noise >= 0 && distance_noise <= 1))
    return fail("distance_noise must lie in [0, 1]");
  if (!(heading_noise_deg >= 0 && heading_noise_deg <= 45)) {
    return fail("heading_noise_deg must lie in [0, 45]");
  }
  return true;
}

OptionTable<OdometryOptions> OdometryOptions::Describe() {
  using O = OdometryOptions;
  return OptionTable<O>("odometry")
      .Double("heading_drift_deg_per_m", &O::heading_drift_deg_per_m, "deg/m", -45, 45, 0.1,
              "Systematic heading drift per metre driven (wheel-radius mismatch).")
      .Double("scale_error", &O::scale_error, "", -0.5, 0.5, 0.005,
              "Systematic distance error: 0.01 reports 1 % more than driven.")
      .Double("distance_noise", &O::distance_noise, "m/sqrt(m)", 0, 1, 0.001,
              "Random walk of the distance.")
      .Double("heading_noise_deg", &O::heading_noise_deg, "deg/sqrt(m)", 0, 45, 0.05,
              "Random walk of the heading.");
}

Trajectory SimulateWheelOdometry(const std::vector<double>& times_s,
                                 const std::vector<Eigen::Isometry3d>& world_from_base,
                                 const OdometryOptions& options, uint64_t seed) {
  Trajectory odometry;
  if (world_from_base.empty()) return odometry;
  std::mt19937 engine = MakeEngine(seed);
  double x = world_from_base[0].translation().x(), y = world_from_base[0].translation().y();
  double yaw = Yaw(world_from_base[0]);
  odometry.Add(times_s[0], Planar(x, y, yaw));
  for (size_t i = 1; i < world_from_base.size(); ++i) {
    const Eigen::Isometry3d step = world_from_base[i - 1].inverse() * world_from_base[i];
    const double dx = step.translation().x(), dy = step.translation().y();
    const double ds = std::hypot(dx, dy);
    const double alpha = ds > 0 ? std::atan2(dy, dx) : 0.0;
    const double dtheta = Yaw(step);
    const double n_d = Normal(engine), n_h = Normal(engine);  // Always drawn: stable streams.
    const double ds_odo =
        ds * (1 + options.scale_error) + options.distance_noise * std::sqrt(ds) * n_d;
    const double dtheta_odo = dtheta + options.heading_drift_deg_per_m * kDeg * ds +
                              options.heading_noise_deg * kDeg * std::sqrt(ds) * n_h;
    x += ds_odo * std::cos(yaw + alpha);
    y += ds_odo * std::sin(yaw + alpha);
    yaw += dtheta_odo;
    odometry.Add(times_s[i], Planar(x, y, yaw));
  }
  return odometry;
}

}  // namespace sightline::sim
