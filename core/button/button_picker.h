// The button picker's run logic for one button, frame by frame (Qt-free, no threads): the
// operator's tap and answer, tracking with the window predicted from the SLAM pose, the 3D
// position from the SLAM's map, and the safety gate. The caller publishes the targets (e.g.
// ArmServer) and shows the state (OperatorPanel). The SLAM plugs in through SlamView.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/button/arm_plane_normal.h"
#include "core/button/arm_protocol.h"
#include "core/button/arm_triangulation.h"
#include "core/button/button_detector.h"
#include "core/button/button_locator.h"
#include "core/button/button_tracker.h"
#include "core/button/button_types.h"
#include "core/button/panel_normal.h"
#include "core/button/position_fusion.h"
#include "core/button/safety_gate.h"

namespace sightline {

// Fusion of the per-frame positions in the arm's base frame. Keys "button.fuse.*". The button
// and the arm's base stay put during one approach, so the positions located frame by frame
// (each from a noisy plane fit on the SLAM's map) estimate one point: the target is their
// per-axis median over the sound estimates made with a converged scale since the tap, each placed
// with the newest scale (position_fusion.h; optionally weighted by its own variance).
struct ButtonFuseOptions {
  int window = 0;  // Recent estimates in the median; 0 = every one since the tap, 1 = no fusion.
  bool rescale = true;    // Place every kept estimate again with the newest scale.
  bool weighted = false;  // Weigh the estimates by 1 / their own variance (near frames most).
  double weigh_below_m = 0.003;  // ... and so from the first estimate this sure on [m]; 0 = off.

  bool IsValid(std::string* error) const;
  static OptionTable<ButtonFuseOptions> Describe();
};

// What the target's stated uncertainty adds to the located button's own (plane fit and scale),
// so that it covers the true error. Keys "button.uncertainty.*".
struct ButtonUncertaintyOptions {
  double tracking_sigma_px = 1.0;   // Tracked centre error, moves the point across the ray [px].
  double hand_eye_sigma_m = 0.001;  // Hand-eye calibration, translation [m].
  double hand_eye_sigma_deg = 0.1;  // Hand-eye calibration, rotation (times the distance) [deg].
  double spread_factor = 1.0;       // Weight of the fused positions' spread (1.4826 MAD) [-].

  bool IsValid(std::string* error) const;
  static OptionTable<ButtonUncertaintyOptions> Describe();
};

// All button options. Keys "button.*".
struct ButtonPickerOptions {
  ButtonDetectorOptions detect;
  ButtonTrackerOptions track;
  ButtonLocatorOptions locate;
  SafetyGateOptions gate;
  ButtonFuseOptions fuse;
  PanelNormalOptions normal;
  ButtonUncertaintyOptions uncertainty;
  ArmTriangulationOptions triangulate;

  bool IsValid(std::string* error) const;
  static OptionTable<ButtonPickerOptions> Describe();
};

// What the monocular SLAM provides for one frame (plain inputs; metric once converged).
struct SlamView {
  bool tracking = false;  // The pose of this frame is valid.
  PinholeCamera camera;
  Eigen::Isometry3d camera_from_world = Eigen::Isometry3d::Identity();
  std::shared_ptr<const std::vector<Eigen::Vector3d>> map_points_in_world;
  bool scale_converged = false;  // The metric scale estimate has converged.
  double scale_sigma_rel = 0;    // 1-sigma relative scale error.
  double lambda = 0;             // The metric scale: map units per metre (0 = unknown).
  // The online hand-eye check (core/pipeline/hand_eye_check.h): the mount rotation error the
  // keyframes' displacement directions show [deg]; whether the arm rotated enough to see the
  // mount's translation, and the translation error then implied [m].
  double hand_eye_deg = 0;
  bool hand_eye_translation_observable = false;
  double hand_eye_translation_m = 0;
  // The caller's base_from_camera is the arm's pose times the mount (metric), whether or not the
  // SLAM tracks or has a scale yet; false in tracking-only runs.
  bool arm_pose = false;
};

// One picker per button; constructible many times.
//
//   ButtonPicker picker(options);
//   Status s = picker.Tap(still, {412, 230});   // NotFound: "no button here", ask again.
//   picker.Confirm();                           // The operator said Yes.
//   PickerFrame f = picker.Process(id, stamp, image, slam_view, base_from_camera, now_s);
//   if (f.target) server->PublishTarget(*f.target);
//   picker.Stop(); server->PublishStop("operator");
class ButtonPicker {
 public:
  explicit ButtonPicker(ButtonPickerOptions options = {})
      : options_(std::move(options)),
        panel_normal_(options_.normal),
        arm_plane_(options_.normal),
        arm_normal_(ArmNormalAveraging(options_.normal)) {}

  // Finds the button at the tap on the still frame; asks for confirmation. NotFound = "no
  // button here"; InvalidArgument for bad input. Ignored (FailedPrecondition) while stopped.
  Status Tap(const cv::Mat& still, cv::Point2d tap, int64_t frame_id = -1);
  // The candidate shown to the operator (null before a tap).
  std::shared_ptr<const ButtonModel> candidate() const { return candidate_; }
  void Confirm();
  void Cancel();
  // STOP: no target until Start().
  void Stop();
  void Start();
  PickerState state() const { return state_; }

  // Tracks, locates and gates one frame. `now_s` is the time the result would be sent, on the
  // clock of stamp_s, for the age check: in a recording the frame's own sensor time (data time,
  // so a replay gives the same targets on any machine); for a live device the caller may add
  // the host clock's delay since the frame arrived.
  PickerFrame Process(int64_t frame_id, double stamp_s, const cv::Mat& image, const SlamView& slam,
                      const Eigen::Isometry3d& base_from_camera, double now_s);

 private:
  TrackPrediction Predict(const SlamView& slam) const;
  // The target's 1-sigma position uncertainty: the location's own, tracking, hand-eye and the
  // spread of the fused positions.
  double TargetUncertainty(const SlamView& slam, const ButtonLocation& at, bool fused) const;
  // A located position's own 1-sigma: plane fit and scale (the location's) and tracked centre.
  double OwnSigma(const SlamView& slam, const ButtonLocation& at) const;
  // Keeps this frame's position and sets out->button_in_base to the fusion of all kept ones.
  void FuseWith(const SlamView& slam, const ButtonLocation& at,
                const Eigen::Isometry3d& base_from_camera, PickerFrame* out);
  // 1-sigma of the mount's rotation: stated (button.uncertainty.hand_eye_sigma_deg) and seen by
  // the online check (SlamView::hand_eye_deg) [rad].
  double HandEyeSigmaRad(const SlamView& slam) const;
  // Feeds the tracked frame to the plane from the arm's motion (every tracked frame with an arm
  // pose, located or not: its tracks run from frame to frame) and averages its normals.
  void AddArmPlane(const SlamView& slam, const cv::Mat& image,
                   const Eigen::Isometry3d& base_from_camera, PickerFrame* out);
  // Adds this frame's map normal to its average; sets out->approach_in_base and its sigma from
  // the arm motion's average when it has one, else from the map's.
  void UpdateApproach(const SlamView& slam, const ButtonLocation& at,
                      const Eigen::Isometry3d& base_from_camera, PickerFrame* out);
  void ResetApproach();
  // The arm plane's normals fade over a minute, not seconds: the panel and the arm's base stay
  // put, and the approach (straight at the panel) adds none, so the sideways moves' must last.
  static PanelNormalOptions ArmNormalAveraging(PanelNormalOptions o) {
    o.smoothing_s = std::max(o.smoothing_s, kArmNormalSmoothingS);
    return o;
  }
  static constexpr double kArmNormalSmoothingS = 60;
  // Triangulates the button from the arm's poses of the tracked frames (out->arm_in_base) and,
  // with button.triangulate.enabled, combines it with the map's fused position by their
  // variances (out->button_in_base, out->uncertainty_m; the mount's terms added after).
  void CombineWithArm(const SlamView& slam, const ButtonLocation& at, PickerFrame* out);

  ButtonPickerOptions options_;
  PickerState state_ = PickerState::kIdle;
  bool stopped_ = false;
  std::shared_ptr<const ButtonModel> candidate_;
  int64_t tap_frame_ = -1;
  std::unique_ptr<ButtonTracker> tracker_;
  std::optional<Eigen::Vector3d> button_in_world_;  // Last located position.
  double last_scale_ = 1.0, last_depth_m_ = 0;      // Track scale and depth at that time.
  std::vector<FusedEstimate> fused_;                // Since the tap.
  double fused_spread_m_ = 0;                       // Of the last fusion.
  NormalAverage panel_normal_;                      // Base frame, since the tap (data time).
  ArmPlaneNormal arm_plane_;                        // Tracks the panel for the arm's plane.
  NormalAverage arm_normal_;                        // Its normals, base frame, since the tap.
  std::vector<ArmView> arm_views_;                  // Tracked frames with an arm pose.
};

}  // namespace sightline
