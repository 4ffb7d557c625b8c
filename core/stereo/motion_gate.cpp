#include "core/stereo/motion_gate.h"

#include <cmath>
#include <cstdio>

#include "core/stereo/option_check.h"

namespace sightline {

using stereo_internal::Invalid;

bool MotionGateOptions::IsValid(std::string* error) const {
  if (!(max_speed_mps > 0)) return Invalid(error, "stereo.gate.max_speed_mps must be > 0");
  if (!(max_angular_speed_deg_s > 0)) {
    return Invalid(error, "stereo.gate.max_angular_speed_deg_s must be > 0");
  }
  if (!(max_acceleration_mps2 >= 0))
    return Invalid(error, "stereo.gate.max_acceleration_mps2 must be >= 0");
  if (!(max_residual_px > 0)) return Invalid(error, "stereo.gate.max_residual_px must be > 0");
  if (min_inliers < 3) return Invalid(error, "stereo.gate.min_inliers must be >= 3");
  if (fallback != "constant_motion" && fallback != "hold") {
    return Invalid(error, "stereo.gate.fallback must be constant_motion or hold");
  }
  if (max_fallback_frames < 0)
    return Invalid(error, "stereo.gate.max_fallback_frames must be >= 0");
  return true;
}

OptionTable<MotionGateOptions> MotionGateOptions::Describe() {
  using O = MotionGateOptions;
  return OptionTable<O>("stereo.gate")
      .Double("max_speed_mps", &O::max_speed_mps, "m/s", 0.01, 500, 0.5,
              "Faster estimated translation is rejected.")
      .Double("max_angular_speed_deg_s", &O::max_angular_speed_deg_s, "deg/s", 0.1, 5000, 1,
              "Faster estimated rotation is rejected.")
      .Double("max_acceleration_mps2", &O::max_acceleration_mps2, "m/s^2", 0, 1000, 0.5,
              "Larger change of velocity from the last accepted motion is rejected; 0 = no check.")
      .Double("max_residual_px", &O::max_residual_px, "px", 0.01, 100, 0.1,
              "Refined RMS reprojection error above this is rejected.")
      .Int("min_inliers", &O::min_inliers, "points", 3, 10000, 1,
           "Fewer inliers after refinement is rejected.")
      .Choice("fallback", &O::fallback, {"constant_motion", "hold"},
              "What replaces a rejected motion: the last accepted one, or none.")
      .Int("max_fallback_frames", &O::max_fallback_frames, "frames", 0, 1000, 1,
           "Consecutive frames of constant-motion fallback before the pose is held.");
}

namespace {

double AngleDeg(const Eigen::Isometry3d& t) {
  return Eigen::AngleAxisd(t.rotation()).angle() * 180.0 / M_PI;
}

}  // namespace

void MotionGate::Reset() {
  last_motion_.reset();
  last_dt_s_ = 0;
  fallback_frames_ = 0;
}

Eigen::Isometry3d MotionGate::Fallback(double dt_s) const {
  if (!last_motion_ || options_.fallback == "hold" ||
      fallback_frames_ > options_.max_fallback_frames) {
    return Eigen::Isometry3d::Identity();
  }
  const double scale = (dt_s > 0 && last_dt_s_ > 0) ? dt_s / last_dt_s_ : 1.0;
  const Eigen::AngleAxisd aa(last_motion_->rotation());
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = Eigen::AngleAxisd(aa.angle() * scale, aa.axis()).toRotationMatrix();
  m.translation() = last_motion_->translation() * scale;
  return m;
}

GateDecision MotionGate::Check(const MotionCandidate& candidate, double dt_s) {
  GateDecision d;
  char reason[200] = "";
  if (!candidate.estimated) {
    std::snprintf(reason, sizeof(reason), "%s", candidate.failure.c_str());
  } else if (!candidate.current_from_previous.matrix().allFinite()) {
    std::snprintf(reason, sizeof(reason), "motion not finite");
  } else if (candidate.inliers < options_.min_inliers) {
    std::snprintf(reason, sizeof(reason), "%d inliers < %d", candidate.inliers,
                  options_.min_inliers);
  } else if (candidate.residual_px > options_.max_residual_px) {
    std::snprintf(reason, sizeof(reason), "residual %.2f px > %.2f px", candidate.residual_px,
                  options_.max_residual_px);
  } else if (dt_s > 0) {
    const Eigen::Vector3d v = candidate.current_from_previous.translation() / dt_s;
    const double w = AngleDeg(candidate.current_from_previous) / dt_s;
    if (v.norm() > options_.max_speed_mps) {
      std::snprintf(reason, sizeof(reason), "speed %.2f m/s > %.2f m/s", v.norm(),
                    options_.max_speed_mps);
    } else if (w > options_.max_angular_speed_deg_s) {
      std::snprintf(reason, sizeof(reason), "angular speed %.1f deg/s > %.1f deg/s", w,
                    options_.max_angular_speed_deg_s);
    } else if (options_.max_acceleration_mps2 > 0 && last_motion_ && last_dt_s_ > 0 &&
               fallback_frames_ == 0) {
      const Eigen::Vector3d v_last = last_motion_->translation() / last_dt_s_;
      const double a = (v - v_last).norm() / dt_s;
      if (a > options_.max_acceleration_mps2) {
        std::snprintf(reason, sizeof(reason), "acceleration %.1f m/s^2 > %.1f m/s^2", a,
                      options_.max_acceleration_mps2);
      }
    }
  }
  if (reason[0] == '\0') {
    d.accepted = true;
    d.current_from_previous = candidate.current_from_previous;
    last_motion_ = candidate.current_from_previous;
    last_dt_s_ = dt_s;
    fallback_frames_ = 0;
    return d;
  }
  ++fallback_frames_;
  d.current_from_previous = Fallback(dt_s);
  const bool held = d.current_from_previous.isApprox(Eigen::Isometry3d::Identity());
  d.reason = std::string(reason) + (held ? "; pose held" : "; constant motion assumed");
  return d;
}

}  // namespace sightline
