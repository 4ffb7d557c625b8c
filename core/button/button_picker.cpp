#include "core/button/button_picker.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/button/option_check.h"

namespace sightline {

bool ButtonFuseOptions::IsValid(std::string* error) const {
  if (window < 0) return button_internal::Invalid(error, "button.fuse.window must be >= 0");
  if (!(weigh_below_m >= 0 && weigh_below_m <= 1)) {
    return button_internal::Invalid(error, "button.fuse.weigh_below_m must lie in [0, 1] m");
  }
  return true;
}

OptionTable<ButtonFuseOptions> ButtonFuseOptions::Describe() {
  using O = ButtonFuseOptions;
  return OptionTable<O>("button.fuse")
      .Int("window", &O::window, "estimates", 0, 100000, 1,
           "The target is the per-axis median of this many recent base-frame positions (sound "
           "plane, converged scale); 0 = every one since the tap, 1 = no fusion.")
      .Bool("rescale", &O::rescale,
            "Place every kept position again with the newest metric scale (kept in map units).")
      .Bool("weighted", &O::weighted,
            "Always weigh each position by 1 / its own variance (plane fit, tracked centre and "
            "scale, growing with the distance): the near frames of the approach count most.")
      .Double("weigh_below_m", &O::weigh_below_m, "m", 0, 1, 0.0005,
              "Weigh them so once one position states a 1-sigma of at most this (the arm has "
              "come close; far positions then carry the newest scale's error times their "
              "distance); 0 = only with weighted (docs/button.md).");
}

bool ButtonUncertaintyOptions::IsValid(std::string* error) const {
  if (!(tracking_sigma_px >= 0 && hand_eye_sigma_m >= 0 && hand_eye_sigma_deg >= 0 &&
        spread_factor >= 0)) {
    return button_internal::Invalid(error, "button.uncertainty.* must be >= 0");
  }
  return true;
}

OptionTable<ButtonUncertaintyOptions> ButtonUncertaintyOptions::Describe() {
  using O = ButtonUncertaintyOptions;
  return OptionTable<O>("button.uncertainty")
      .Double("tracking_sigma_px", &O::tracking_sigma_px, "px", 0, 100, 0.1,
              "1-sigma error of the tracked button centre; moves the point across the viewing "
              "ray (the target's stated uncertainty includes it).")
      .Double("hand_eye_sigma_m", &O::hand_eye_sigma_m, "m", 0, 1, 0.0005,
              "1-sigma translation error of the hand-eye calibration (end effector to camera).")
      .Double("hand_eye_sigma_deg", &O::hand_eye_sigma_deg, "deg", 0, 45, 0.05,
              "1-sigma rotation error of the hand-eye calibration; times the distance to the "
              "button.")
      .Double("spread_factor", &O::spread_factor, "", 0, 10, 0.1,
              "Weight of the fused positions' spread (1.4826 x median absolute deviation from "
              "the fused target) in the stated uncertainty.");
}

bool ButtonPickerOptions::IsValid(std::string* error) const {
  return detect.IsValid(error) && track.IsValid(error) && locate.IsValid(error) &&
         gate.IsValid(error) && fuse.IsValid(error) && normal.IsValid(error) &&
         uncertainty.IsValid(error) && triangulate.IsValid(error);
}

OptionTable<ButtonPickerOptions> ButtonPickerOptions::Describe() {
  using O = ButtonPickerOptions;
  return OptionTable<O>("")  // The nested tables carry "button.detect" etc.
      .Nested(&O::detect, ButtonDetectorOptions::Describe())
      .Nested(&O::track, ButtonTrackerOptions::Describe())
      .Nested(&O::locate, ButtonLocatorOptions::Describe())
      .Nested(&O::gate, SafetyGateOptions::Describe())
      .Nested(&O::fuse, ButtonFuseOptions::Describe())
      .Nested(&O::normal, PanelNormalOptions::Describe())
      .Nested(&O::uncertainty, ButtonUncertaintyOptions::Describe())
      .Nested(&O::triangulate, ArmTriangulationOptions::Describe());
}

const char* PickerStateKey(PickerState state) {
  switch (state) {
    case PickerState::kIdle:
      return "idle";
    case PickerState::kConfirm:
      return "confirm";
    case PickerState::kSearching:
      return "searching";
    case PickerState::kTracking:
      return "tracking";
    case PickerState::kLocating:
      return "locating";
    case PickerState::kTargetSent:
      return "target_sent";
    case PickerState::kLost:
      return "lost";
    case PickerState::kStopped:
      return "stopped";
  }
  return "unknown";
}

Status ButtonPicker::Tap(const cv::Mat& still, cv::Point2d tap, int64_t frame_id) {
  if (stopped_) return FailedPrecondition("stopped: press Start again first");
  auto model = ButtonDetector(options_.detect).Detect(still, tap);
  if (!model.ok()) {
    candidate_.reset();
    state_ = PickerState::kIdle;
    return model.status();
  }
  candidate_ = *model;
  tap_frame_ = frame_id;
  tracker_.reset();
  button_in_world_.reset();
  fused_.clear();
  ResetApproach();
  arm_views_.clear();
  state_ = PickerState::kConfirm;
  return Status::Ok();
}

void ButtonPicker::Confirm() {
  if (stopped_ || !candidate_ || state_ != PickerState::kConfirm) return;
  tracker_ = std::make_unique<ButtonTracker>(candidate_, options_.track);
  state_ = PickerState::kSearching;
}

void ButtonPicker::Cancel() {
  candidate_.reset();
  tracker_.reset();
  button_in_world_.reset();
  fused_.clear();
  ResetApproach();
  arm_views_.clear();
  if (!stopped_) state_ = PickerState::kIdle;
}

void ButtonPicker::Stop() {
  stopped_ = true;
  state_ = PickerState::kStopped;
}

void ButtonPicker::Start() {
  stopped_ = false;
  Cancel();
}

TrackPrediction ButtonPicker::Predict(const SlamView& slam) const {
  TrackPrediction p;
  if (!button_in_world_ || !slam.tracking || last_depth_m_ <= 0) return p;  // Last position.
  const Eigen::Vector3d x = slam.camera_from_world * *button_in_world_;
  if (!(x.z() > 1e-3)) return p;
  const Eigen::Vector2d px = slam.camera.Project(x);
  p.valid = true;
  p.center = {px.x(), px.y()};
  p.scale = last_scale_ * last_depth_m_ / x.z();
  return p;
}

double ButtonPicker::HandEyeSigmaRad(const SlamView& slam) const {
  const double stated = options_.uncertainty.hand_eye_sigma_deg * M_PI / 180.0;
  return std::hypot(stated, slam.hand_eye_deg * M_PI / 180.0);
}

double ButtonPicker::TargetUncertainty(const SlamView& slam, const ButtonLocation& at,
                                       bool fused) const {
  const ButtonUncertaintyOptions& o = options_.uncertainty;
  const double distance = at.button_in_camera.norm();
  const double focal = std::max(1.0, 0.5 * (slam.camera.fx + slam.camera.fy));
  const double tracking = o.tracking_sigma_px / focal * distance / std::max(0.2, at.incidence_cos);
  // The mount: the stated rotation and the one the online check sees, times the distance; the
  // stated translation, or the one the check implies when the arm rotated enough to see it.
  const double hand_eye_rot = HandEyeSigmaRad(slam) * distance;
  const double hand_eye_t = slam.hand_eye_translation_observable
                                ? std::max(o.hand_eye_sigma_m, slam.hand_eye_translation_m)
                                : o.hand_eye_sigma_m;
  const double spread = fused && fused_.size() >= 3 ? o.spread_factor * fused_spread_m_ : 0;
  const double sum2 = at.uncertainty_m * at.uncertainty_m + tracking * tracking +
                      hand_eye_t * hand_eye_t + hand_eye_rot * hand_eye_rot + spread * spread;
  return std::sqrt(sum2);
}

double ButtonPicker::OwnSigma(const SlamView& slam, const ButtonLocation& at) const {
  const double distance = at.button_in_camera.norm();
  const double focal = std::max(1.0, 0.5 * (slam.camera.fx + slam.camera.fy));
  const double tracking =
      options_.uncertainty.tracking_sigma_px / focal * distance / std::max(0.2, at.incidence_cos);
  return std::hypot(at.uncertainty_m, tracking);
}

void ButtonPicker::FuseWith(const SlamView& slam, const ButtonLocation& at,
                            const Eigen::Isometry3d& base_from_camera, PickerFrame* out) {
  FusedEstimate e;
  e.lambda = slam.lambda > 0 ? slam.lambda : 1.0;
  e.in_camera_map = at.button_in_camera * e.lambda;
  e.base_from_camera = base_from_camera;
  e.sigma_m = OwnSigma(slam, at);
  fused_.push_back(e);
  const ButtonFuseOptions& o = options_.fuse;
  const FusedPosition fused =
      FusePositions(fused_, o.window, o.rescale ? slam.lambda : 0.0, o.weighted, o.weigh_below_m);
  out->button_in_base = fused.in_base;
  out->fused_estimates = fused.estimates;
  fused_spread_m_ = fused.spread_m;
}

void ButtonPicker::ResetApproach() {
  panel_normal_.Reset();
  arm_plane_.Reset();
  arm_normal_.Reset();
}

void ButtonPicker::AddArmPlane(const SlamView& slam, const cv::Mat& image,
                               const Eigen::Isometry3d& base_from_camera, PickerFrame* out) {
  if (!options_.normal.arm_motion) return;
  ArmPlaneView view;
  view.image = image;
  view.camera = slam.camera;
  view.base_from_camera = base_from_camera;
  view.button_px = {out->track.center.x, out->track.center.y};
  const double focal = 0.5 * (slam.camera.fx + slam.camera.fy);
  // The panel around the button at its last located depth; the whole picture before.
  view.region_radius_px = last_depth_m_ > 0 ? options_.normal.radius_m * focal / last_depth_m_ : 0;
  if (slam.tracking && slam.scale_converged && button_in_world_) {
    view.button_in_camera = slam.camera_from_world * *button_in_world_;
  }
  StatusOr<PanelNormal> arm = arm_plane_.Add(view);
  if (arm.ok()) {
    arm_normal_.Add(out->stamp_s, base_from_camera.linear() * arm->normal_in_camera,
                    arm->sigma_rad);
  }
}

void ButtonPicker::UpdateApproach(const SlamView& slam, const ButtonLocation& at,
                                  const Eigen::Isometry3d& base_from_camera, PickerFrame* out) {
  std::vector<Eigen::Vector3d> in_camera;
  in_camera.reserve(slam.map_points_in_world->size());
  for (const Eigen::Vector3d& x : *slam.map_points_in_world) {
    in_camera.push_back(slam.camera_from_world * x);
  }
  StatusOr<PanelNormal> normal =
      EstimatePanelNormal(in_camera, at.button_in_camera, options_.normal);
  if (normal.ok()) {
    panel_normal_.Add(out->stamp_s, base_from_camera.linear() * normal->normal_in_camera,
                      normal->sigma_rad);
  }
  const NormalAverage& used = !arm_normal_.empty() ? arm_normal_ : panel_normal_;
  if (used.empty()) return;
  out->approach_in_base = -used.normal();
  // The mount's rotation turns the normal into the base frame: its sigma adds.
  const double sigma_rad = std::hypot(used.sigma_rad(), HandEyeSigmaRad(slam));
  out->approach_sigma_deg =
      std::max(sigma_rad * 180.0 / M_PI, options_.normal.stated_min_sigma_deg);
}

void ButtonPicker::CombineWithArm(const SlamView& slam, const ButtonLocation& at,
                                  PickerFrame* out) {
  const ArmTriangulationOptions& o = options_.triangulate;
  const std::optional<Eigen::Vector3d> prior =
      out->button_in_base.allFinite() ? std::optional(out->button_in_base) : std::nullopt;
  StatusOr<ArmTriangulation> arm = TriangulateFromArm(arm_views_, slam.camera, o, prior);
  if (!arm.ok()) return;
  out->arm_in_base = arm->in_base;
  out->arm_sigma_m = arm->SigmaMaxM();
  if (!o.enabled || !prior) return;
  // The mount moves both estimates alike: its terms are not averaged away.
  const double distance = at.button_in_camera.norm();
  const double hand_eye_rot = HandEyeSigmaRad(slam) * distance;
  const double hand_eye_t =
      slam.hand_eye_translation_observable
          ? std::max(options_.uncertainty.hand_eye_sigma_m, slam.hand_eye_translation_m)
          : options_.uncertainty.hand_eye_sigma_m;
  const double mount2 = hand_eye_t * hand_eye_t + hand_eye_rot * hand_eye_rot;
  const double map2 = std::max(1e-12, out->uncertainty_m * out->uncertainty_m - mount2);
  const Eigen::Matrix3d arm_info = arm->covariance.inverse();
  const Eigen::Matrix3d cov = (arm_info + Eigen::Matrix3d::Identity() / map2).inverse();
  out->button_in_base = cov * (arm_info * arm->in_base + *prior / map2);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  out->uncertainty_m = std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()) + mount2);
}

PickerFrame ButtonPicker::Process(int64_t frame_id, double stamp_s, const cv::Mat& image,
                                  const SlamView& slam, const Eigen::Isometry3d& base_from_camera,
                                  double now_s) {
  PickerFrame out;
  out.frame_id = frame_id;
  out.stamp_s = stamp_s;
  SafetyState safety;
  safety.stopped = stopped_;
  safety.operator_confirmed = tracker_ != nullptr;
  if (stopped_ || !tracker_) {
    out.state = state_;
    out.verdict = CheckSafety(safety, options_.gate);
    return out;
  }
  const auto start = std::chrono::steady_clock::now();
  auto track = tracker_->Track(image, Predict(slam));
  out.tracking_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (track.ok()) out.track = *track;
  safety.tracking = track.ok() && track->found;
  safety.tracking_confidence = out.track.confidence;
  if (safety.tracking && slam.tracking && slam.lambda > 0) {  // A metric arm pose.
    const ButtonTrack& t = out.track;
    const double radius_px = !options_.triangulate.anchor_size ? t.radius_px
                             : t.scale > 0 ? t.radius_px / t.scale * t.anchor_scale
                                           : 0;
    arm_views_.push_back(
        ArmView{base_from_camera, Eigen::Vector2d(t.center.x, t.center.y), radius_px});
  }
  if (safety.tracking && slam.arm_pose) AddArmPlane(slam, image, base_from_camera, &out);
  if (safety.tracking && slam.tracking && slam.map_points_in_world) {
    LocatorInput in;
    in.camera = slam.camera;
    in.camera_from_world = slam.camera_from_world;
    in.points_in_world = slam.map_points_in_world.get();
    in.button_px = {out.track.center.x, out.track.center.y};
    in.button_radius_px = out.track.radius_px;
    in.scale_sigma_rel = slam.scale_sigma_rel;
    auto at = ButtonLocator(options_.locate).Locate(in);
    if (at.ok()) {
      out.location = *at;
      button_in_world_ = slam.camera_from_world.inverse() * at->button_in_camera;
      last_scale_ = out.track.scale;
      last_depth_m_ = at->button_in_camera.z();
      out.button_in_base = base_from_camera * at->button_in_camera;
      UpdateApproach(slam, *at, base_from_camera, &out);
      out.fused_estimates = 1;
      if (at->plane_sound && slam.scale_converged && options_.fuse.window != 1) {
        FuseWith(slam, *at, base_from_camera, &out);
      }
      safety.has_estimate = true;
      safety.plane_sound = at->plane_sound;
      out.uncertainty_m = TargetUncertainty(slam, *at, out.fused_estimates > 1);
      if (at->plane_sound && slam.scale_converged) CombineWithArm(slam, *at, &out);
      safety.uncertainty_m = out.uncertainty_m;
      safety.approach_sigma_deg = out.approach_sigma_deg;
      safety.approach_in_base = out.approach_in_base;
      safety.target_in_base = out.button_in_base;
    }
  }
  safety.estimate_age_ms = (now_s - stamp_s) * 1e3;
  safety.scale_converged = slam.scale_converged;
  safety.hand_eye_deg = slam.hand_eye_deg;
  safety.hand_eye_translation_verified = slam.hand_eye_translation_observable;
  out.verdict = CheckSafety(safety, options_.gate);
  if (out.verdict.send) {
    ArmTarget t;
    t.stamp_s = stamp_s;
    t.position_m = out.button_in_base;
    t.approach = out.approach_in_base;
    t.uncertainty_m = out.uncertainty_m;
    t.approach_sigma_deg = out.approach_sigma_deg;
    t.source_frames = {frame_id};
    if (tap_frame_ >= 0) t.source_frames.insert(t.source_frames.begin(), tap_frame_);
    out.target = t;
    out.state = PickerState::kTargetSent;
  } else if (!safety.tracking) {
    out.state = PickerState::kLost;
  } else if (safety.has_estimate) {
    out.state = PickerState::kLocating;
  } else {
    out.state = PickerState::kTracking;
  }
  state_ = out.state;
  return out;
}

}  // namespace sightline
