#include "core/button/panel_normal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/button/option_check.h"
#include "core/button/plane_fit.h"

namespace sightline {

using button_internal::Invalid;

bool PanelNormalOptions::IsValid(std::string* error) const {
  if (!(radius_m > 0)) return Invalid(error, "button.normal.radius_m must be > 0");
  if (min_points < 3) return Invalid(error, "button.normal.min_points must be >= 3");
  if (ransac_iterations < 1) return Invalid(error, "button.normal.ransac_iterations must be >= 1");
  if (!(ransac_threshold_m > 0)) {
    return Invalid(error, "button.normal.ransac_threshold_m must be > 0");
  }
  if (!(max_button_offset_m > 0)) {
    return Invalid(error, "button.normal.max_button_offset_m must be > 0");
  }
  if (!(min_sigma_deg > 0)) return Invalid(error, "button.normal.min_sigma_deg must be > 0");
  if (!(stated_min_sigma_deg > 0)) {
    return Invalid(error, "button.normal.stated_min_sigma_deg must be > 0");
  }
  if (!(smoothing_s >= 0)) return Invalid(error, "button.normal.smoothing_s must be >= 0");
  if (!(outlier_sigmas > 0)) return Invalid(error, "button.normal.outlier_sigmas must be > 0");
  if (!(arm_min_parallax_deg > 0 && arm_min_parallax_deg < 90)) {
    return Invalid(error, "button.normal.arm_min_parallax_deg must lie in (0, 90)");
  }
  if (arm_max_corners < min_points) {
    return Invalid(error, "button.normal.arm_max_corners must be >= button.normal.min_points");
  }
  if (!(arm_inlier_px > 0)) return Invalid(error, "button.normal.arm_inlier_px must be > 0");
  return true;
}

OptionTable<PanelNormalOptions> PanelNormalOptions::Describe() {
  using O = PanelNormalOptions;
  return OptionTable<O>("button.normal")
      .Double("radius_m", &O::radius_m, "m", 0.02, 2, 0.01,
              "The approach direction is the normal of a plane through the map points within "
              "this distance of the located button (the panel around it).")
      .Int("min_points", &O::min_points, "", 3, 100000, 1,
           "Fewer map points or plane inliers: no normal in this frame.")
      .Int("ransac_iterations", &O::ransac_iterations, "", 1, 100000, 10,
           "Plane RANSAC hypotheses of the panel normal.")
      .Double("ransac_threshold_m", &O::ransac_threshold_m, "m", 1e-4, 0.1, 0.0005,
              "Inlier distance of the panel plane.")
      .Double("max_button_offset_m", &O::max_button_offset_m, "m", 1e-4, 1, 0.001,
              "The panel plane passes at most this far from the located button: of the "
              "surfaces around it (a side wall, a door frame) only the one holding the button "
              "gives the push direction.")
      .Double("min_sigma_deg", &O::min_sigma_deg, "deg", 0.01, 45, 0.1,
              "Smallest 1-sigma stated for one frame's normal (the map points' errors are "
              "correlated, so the fit's own figure is optimistic).")
      .Double("stated_min_sigma_deg", &O::stated_min_sigma_deg, "deg", 0.01, 45, 0.1,
              "Smallest approach_sigma_deg a target states: the average of frames that share one "
              "map does not beat the map's own bias (on the simulated approach with the SLAM's "
              "map, up to 4.3 deg against per-frame fits of 0.5 deg).")
      .Double("smoothing_s", &O::smoothing_s, "s", 0, 600, 0.1,
              "Older frames' normals fade with exp(-age / this) in the average (data time); "
              "0 = this frame's normal only.")
      .Double("outlier_sigmas", &O::outlier_sigmas, "", 0.5, 100, 0.5,
              "A frame's normal this many sigmas off the average is skipped.")
      .Bool("arm_motion", &O::arm_motion,
            "Take the approach from the plane that the arm's own motion shows (corners around "
            "the button tracked from an anchor frame, the views' poses from the arm) rather than "
            "from the SLAM's map, whenever that plane is found.")
      .Double("arm_min_parallax_deg", &O::arm_min_parallax_deg, "deg", 0.1, 45, 0.5,
              "The arm's motion since the anchor frame, as an angle seen from the panel, before "
              "its plane is used.")
      .Int("arm_max_corners", &O::arm_max_corners, "", 3, 5000, 10,
           "Corners tracked around the button for the plane from the arm's motion.")
      .Double("arm_inlier_px", &O::arm_inlier_px, "px", 0.1, 20, 0.1,
              "A tracked corner within this of where the plane's homography puts it is on the "
              "panel.");
}

namespace {

// The points within the threshold of the best 3-point plane, scored by truncated squared
// distances (MSAC): of two parallel surfaces a few millimetres apart (a plate on its wall) it
// keeps one, where counting inliers may prefer a plane tilted through both.
std::vector<Eigen::Vector3d> RansacInliers(const std::vector<Eigen::Vector3d>& points,
                                           const Eigen::Vector3d& button,
                                           const PanelNormalOptions& o) {
  std::mt19937_64 rng(o.seed);
  std::uniform_int_distribution<size_t> pick(0, points.size() - 1);
  const double t2 = o.ransac_threshold_m * o.ransac_threshold_m;
  Eigen::Vector3d best_n = Eigen::Vector3d::Zero();
  double best_d = 0, best_cost = std::numeric_limits<double>::infinity();
  for (int it = 0; it < o.ransac_iterations; ++it) {
    const size_t i = pick(rng), j = pick(rng), k = pick(rng);
    const Eigen::Vector3d& a = points[i];
    const Eigen::Vector3d n = (points[j] - a).cross(points[k] - a);
    if (n.norm() < 1e-12) continue;
    const Eigen::Vector3d unit = n.normalized();
    const double d = -unit.dot(a);
    if (std::abs(unit.dot(button) + d) > o.max_button_offset_m) continue;  // Not the panel.
    double cost = 0;
    for (const auto& p : points) cost += std::min(t2, std::pow(unit.dot(p) + d, 2));
    if (cost < best_cost) best_cost = cost, best_n = unit, best_d = d;
  }
  std::vector<Eigen::Vector3d> in;
  if (!std::isfinite(best_cost)) return in;
  for (int round = 0; round < 3; ++round) {  // Least squares on the inliers, inliers again.
    in.clear();
    for (const auto& p : points) {
      if (std::abs(best_n.dot(p) + best_d) <= o.ransac_threshold_m) in.push_back(p);
    }
    if (in.size() < 3) break;
    const LeastSquaresPlane refit = FitLeastSquaresPlane(in);
    best_n = refit.normal;
    best_d = refit.offset();
  }
  return in;
}

}  // namespace

StatusOr<PanelNormal> EstimatePanelNormal(const std::vector<Eigen::Vector3d>& points_in_camera,
                                          const Eigen::Vector3d& button_in_camera,
                                          const PanelNormalOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  if (!button_in_camera.allFinite()) return InvalidArgument("panel normal: button not finite");
  PanelNormal out;
  std::vector<Eigen::Vector3d> near;
  for (const auto& p : points_in_camera) {
    if (p.allFinite() && (p - button_in_camera).norm() <= options.radius_m) near.push_back(p);
  }
  out.points = int(near.size());
  if (out.points < options.min_points) {
    return NotFound("panel normal: " + std::to_string(out.points) + " map points within " +
                    std::to_string(options.radius_m) + " m of the button (needs " +
                    std::to_string(options.min_points) + ")");
  }
  const std::vector<Eigen::Vector3d> inliers = RansacInliers(near, button_in_camera, options);
  out.inliers = int(inliers.size());
  if (out.inliers < options.min_points) {
    return NotFound("panel normal: " + std::to_string(out.inliers) + " plane inliers of " +
                    std::to_string(out.points) + " points");
  }
  const LeastSquaresPlane plane = FitLeastSquaresPlane(inliers);
  out.normal_in_camera = plane.normal.dot(button_in_camera) < 0 ? plane.normal : -plane.normal;
  // Residual with the three fitted degrees of freedom taken out.
  out.rms_m = std::sqrt(plane.eigenvalues[0] * out.inliers / std::max(1, out.inliers - 3));
  // A tilt about the narrower in-plane axis: residual over the lever arm of n points.
  const double lever = std::sqrt(std::max(plane.eigenvalues[1], 1e-12) * out.inliers);
  const double min_sigma = options.min_sigma_deg * M_PI / 180.0;
  out.sigma_rad = std::max(min_sigma, std::atan(out.rms_m / lever));
  return out;
}

void NormalAverage::Reset() {
  frames_ = 0;
  skipped_ = 0;
  sum_normal_.setZero();
  sum_weight_ = sum_weight_sigma_ = sum_weight_dev2_ = 0;
}

void NormalAverage::Decay(double stamp_s) {
  if (frames_ == 0) return;
  if (stamp_s < last_stamp_s_) return Reset();  // Data time went back: a new run.
  const double k = options_.smoothing_s > 0
                       ? std::exp(-(stamp_s - last_stamp_s_) / options_.smoothing_s)
                       : (stamp_s > last_stamp_s_ ? 0.0 : 1.0);
  // The sums now hold the average at `stamp_s`: a skipped frame does not fade them twice.
  last_stamp_s_ = stamp_s;
  sum_normal_ *= k;
  sum_weight_ *= k;
  sum_weight_sigma_ *= k;
  sum_weight_dev2_ *= k;
  // Faded to nothing (a long gap): the old frames no longer say anything about the direction.
  const double floor_w = 1.0 / std::pow(options_.min_sigma_deg * M_PI / 180.0, 2);
  if (!(sum_weight_ > kFadedFraction * floor_w) || !(sum_normal_.norm() > 1e-6 * sum_weight_)) {
    Reset();
  }
}

bool NormalAverage::Add(double stamp_s, const Eigen::Vector3d& normal, double sigma_rad) {
  if (!normal.allFinite() || !(sigma_rad > 0) || normal.norm() < 1e-9) return false;
  const Eigen::Vector3d n = normal.normalized();
  Decay(stamp_s);
  double dev = 0;
  if (frames_ > 0) {
    dev = std::acos(std::clamp(n.dot(this->normal()), -1.0, 1.0));
    const double allowed = options_.outlier_sigmas * std::hypot(sigma_rad, sigma_rad_inner());
    if (frames_ >= 3 && !(dev <= allowed)) {
      // Skipped frames that go on for longer than the smoothing time are no longer outliers:
      // the average was wrong (it started on a poor map), and starts again from this frame.
      if (skipped_ == 0) first_skipped_s_ = stamp_s;
      ++skipped_;
      if (skipped_ < kMinSkippedToRestart || stamp_s - first_skipped_s_ < options_.smoothing_s) {
        return false;
      }
      Reset();
      dev = 0;
    }
  }
  skipped_ = 0;
  const double w = 1.0 / (sigma_rad * sigma_rad);
  sum_normal_ += w * n;
  sum_weight_ += w;
  sum_weight_sigma_ += w * sigma_rad;
  sum_weight_dev2_ += w * dev * dev;
  last_stamp_s_ = stamp_s;
  ++frames_;
  return true;
}

Eigen::Vector3d NormalAverage::normal() const {
  const double norm = sum_normal_.norm();
  if (frames_ == 0 || !(norm > 0)) return Eigen::Vector3d::Constant(std::nan(""));
  return sum_normal_ / norm;
}

double NormalAverage::sigma_rad() const {
  if (frames_ == 0 || !(sum_weight_ > 0)) return std::numeric_limits<double>::infinity();
  return std::max(sigma_rad_inner(), std::sqrt(sum_weight_dev2_ / sum_weight_));
}

double NormalAverage::sigma_rad_inner() const { return sum_weight_sigma_ / sum_weight_; }

}  // namespace sightline
