#include "core/button/button_picker.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/button/option_check.h"

namespace sightline {

namespace {

// Per-axis median of the last `window` vectors (all when 0).
Eigen::Vector3d Median(const std::vector<Eigen::Vector3d>& values, int window) {
  const size_t n = window > 0 ? std::min(values.size(), size_t(window)) : values.size();
  Eigen::Vector3d out;
  std::vector<double> axis(n);
  for (int k = 0; k < 3; ++k) {
    for (size_t i = 0; i < n; ++i) axis[i] = values[values.size() - n + i][k];
    std::nth_element(axis.begin(), axis.begin() + n / 2, axis.end());
    out[k] = axis[n / 2];
  }
  return out;
}

}  // namespace

bool ButtonFuseOptions::IsValid(std::string* error) const {
  if (window < 0) return button_internal::Invalid(error, "button.fuse.window must be >= 0");
  return true;
}

OptionTable<ButtonFuseOptions> ButtonFuseOptions::Describe() {
  using O = ButtonFuseOptions;
  return OptionTable<O>("button.fuse")
      .Int("window", &O::window, "estimates", 0, 100000, 1,
           "The target is the per-axis median of this many recent base-frame positions (sound "
           "plane, converged scale); 0 = every one since the tap, 1 = no fusion.");
}

bool ButtonPickerOptions::IsValid(std::string* error) const {
  return detect.IsValid(error) && track.IsValid(error) && locate.IsValid(error) &&
         gate.IsValid(error) && fuse.IsValid(error);
}

OptionTable<ButtonPickerOptions> ButtonPickerOptions::Describe() {
  using O = ButtonPickerOptions;
  return OptionTable<O>("")  // The nested tables carry "button.detect" etc.
      .Nested(&O::detect, ButtonDetectorOptions::Describe())
      .Nested(&O::track, ButtonTrackerOptions::Describe())
      .Nested(&O::locate, ButtonLocatorOptions::Describe())
      .Nested(&O::gate, SafetyGateOptions::Describe())
      .Nested(&O::fuse, ButtonFuseOptions::Describe());
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
  fused_positions_.clear();
  fused_approaches_.clear();
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
  fused_positions_.clear();
  fused_approaches_.clear();
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
      out.approach_in_base = base_from_camera.linear() * at->approach_in_camera;
      out.fused_estimates = 1;
      if (at->plane_sound && slam.scale_converged && options_.fuse.window != 1) {
        fused_positions_.push_back(out.button_in_base);
        fused_approaches_.push_back(out.approach_in_base);
        out.button_in_base = Median(fused_positions_, options_.fuse.window);
        out.approach_in_base = Median(fused_approaches_, options_.fuse.window).normalized();
        out.fused_estimates = options_.fuse.window > 0
                                  ? std::min(int(fused_positions_.size()), options_.fuse.window)
                                  : int(fused_positions_.size());
      }
      safety.has_estimate = true;
      safety.plane_sound = at->plane_sound;
      safety.uncertainty_m = at->uncertainty_m;
      safety.target_in_base = out.button_in_base;
    }
  }
  safety.estimate_age_ms = (now_s - stamp_s) * 1e3;
  safety.scale_converged = slam.scale_converged;
  out.verdict = CheckSafety(safety, options_.gate);
  if (out.verdict.send) {
    ArmTarget t;
    t.stamp_s = stamp_s;
    t.position_m = out.button_in_base;
    t.approach = out.approach_in_base;
    t.uncertainty_m = out.location->uncertainty_m;
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
