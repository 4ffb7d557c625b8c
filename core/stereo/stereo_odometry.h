// Stereo visual odometry (seed 003), frame by frame: rectify, track Shi-Tomasi features on the
// left image with KLT, match them in the right image, replenish features, triangulate at both
// times, RANSAC with the rigidity test + absolute orientation, reprojection refinement, gating,
// pose accumulation. Every stage is timed; the result carries what a view needs to draw.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/common/timing.h"
#include "core/common/trajectory.h"
#include "core/options/option_table.h"
#include "core/stereo/disparity_offset.h"
#include "core/stereo/feature_tracker.h"
#include "core/stereo/image_pyramid.h"
#include "core/stereo/keyframe.h"
#include "core/stereo/motion_estimator.h"
#include "core/stereo/motion_gate.h"
#include "core/stereo/motion_refiner.h"
#include "core/stereo/rectifier.h"
#include "core/stereo/stereo_matcher.h"
#include "core/stereo/stereo_types.h"
#include "core/stereo/track_anchor.h"
#include "core/stereo/turn_search.h"
#include "core/stereo/window_bundle_adjuster.h"

namespace sightline {

// Every option of the odometry, keys "stereo.<stage>.*".
struct StereoOdometryOptions {
  RectifierOptions rectify;
  FeatureTrackerOptions tracking;
  TrackAnchorOptions anchor;
  StereoMatcherOptions matching;
  MotionEstimatorOptions ransac;
  MotionRefinerOptions refine;
  MotionGateOptions gate;
  KeyframeOptions keyframe;
  WindowBundleOptions window;
  DisparityOffsetOptions disparity_offset;
  int refine_rounds = 2;  // Refine, re-select inliers by UMBRAL3, refine again (rounds in total).

  bool IsValid(std::string* error) const;
  static OptionTable<StereoOdometryOptions> Describe();
};

// The odometry. Construct, Configure() with the rig, then Process() frames in order.
//
//   StereoOdometry vo(options);
//   SIGHTLINE_RETURN_IF_ERROR(vo.Configure(*source.info().stereo));
//   while (...) {
//     StatusOr<std::shared_ptr<const StereoOdometryResult>> r = vo.Process(frame);
//     if (!r.ok()) return r.status();
//     trajectory.Add((*r)->stamp.sensor_time_s, (*r)->world_from_camera);
//   }
//
// Bad input (empty, black or uniform images, no stereo matches) is not an error: the frame's
// stats say why and the gate holds the pose.
class StereoOdometry {
 public:
  explicit StereoOdometry(const StereoOdometryOptions& options = {});

  // Checks the options and sets up rectification. Fails naming the bad option or calibration field.
  Status Configure(const StereoRig& rig);
  const RectifiedStereoCamera& camera() const { return rectifier_.camera(); }
  const StereoOdometryOptions& options() const { return options_; }

  // Processes the next frame. Errors only when not configured; `timing` (optional) receives
  // every stage's duration under "rectify", "pyramid", "tracking", "matching", "detection",
  // "ransac", "refine", "window".
  StatusOr<std::shared_ptr<const StereoOdometryResult>> Process(const StereoFrame& frame,
                                                                TimingStats* timing = nullptr);
  // Forgets features, motion history and pose (back to identity).
  void Reset();

 private:
  struct Feature {
    int64_t id;
    cv::Point2f left, right;
    int age;
    bool has_keyframe = false;                  // Seen at the current keyframe ...
    cv::Point2f keyframe_left, keyframe_right;  // ... there.
    TrackAnchor anchor;                         // What its position is aligned against.
  };
  struct FrameState;  // One frame's working data, passed between the steps of Process().

  // The steps of Process(), in order (stereo_odometry.cpp).
  // An unusable frame: the gate's motion; the state stays at the last good frame.
  void RejectInput(const std::string& why, FrameState* s);
  // Tracks the features into the new left image (KLT from a constant-motion prediction, then
  // anchor alignment); fills s->points, guesses, source and alignment.
  void TrackFeatures(FrameState* s);
  // Where the features should land under constant motion (empty when there is no motion
  // history); returns the predicted current_from_previous.
  Eigen::Isometry3d PredictMotion(double dt, std::vector<cv::Point2f>* predicted,
                                  std::vector<float>* predicted_disparity) const;
  // Where the features land under `motion` (current_from_previous).
  void PredictPoints(const Eigen::Isometry3d& motion, std::vector<cv::Point2f>* predicted,
                     std::vector<float>* predicted_disparity) const;
  // When few points tracked: tracks them again from the rotation the image's global shift
  // gives, keeping the attempt that tracks more (stereo.tracking.turn_search_*).
  void SearchTurn(const std::vector<cv::Point2f>& previous_points, FrameState* s,
                  Eigen::Isometry3d* motion, std::vector<float>* predicted_disparity,
                  std::vector<cv::Point2f>* tracked, std::vector<unsigned char>* tracked_ok);
  // Refines the tracked positions against their anchors; fills s->alignment.
  void AlignToAnchors(const Eigen::Isometry3d& predicted_motion,
                      const std::vector<unsigned char>& tracked_ok,
                      std::vector<cv::Point2f>* tracked, FrameState* s);
  // Adds new corners where tracks are missing.
  void DetectFeatures(FrameState* s);
  // Matches every feature in the right image; fills s->kept and the correspondences.
  void MatchFeatures(FrameState* s);
  // The first frame: nothing to measure, the window starts.
  void StartFirstFrame(FrameState* s);
  // Measures, gates and applies the motion. False when the frame holds the pose (nothing to
  // track from) and Process() ends without updating the state.
  bool EstimateMotion(FrameState* s);
  // RANSAC and refinement rounds over the correspondences; sets s->inliers.
  MotionCandidate MeasureMotion(FrameState* s);
  // Re-estimates *world_from_current against the keyframe; returns whether a new keyframe is due.
  bool AlignToKeyframe(FrameState* s, Eigen::Isometry3d* world_from_current);
  // Sliding-window adjustment of *world_from_current.
  void AdjustWindow(FrameState* s, Eigen::Isometry3d* world_from_current);
  // The kept features with their roles, for views.
  void PublishFeatures(FrameState* s) const;
  // Feeds the disparity offset estimator with the kept features.
  void ObserveDisparityOffset(const FrameState& s);
  // Anchors new tracks and those whose anchor failed or expires; keeps the frame's image.
  void RenewAnchors(const cv::Mat& left_image);
  // Makes this frame the keyframe when none is set.
  void SetKeyframeIfNeeded();
  // Records the total time and hands out the result.
  std::shared_ptr<const StereoOdometryResult> FinishFrame(FrameState* s) const;

  StereoOdometryOptions options_;
  Rectifier rectifier_;
  FeatureTracker tracker_;
  StereoMatcher matcher_;
  MotionEstimator estimator_;
  MotionRefiner refiner_;
  MotionGate gate_;
  WindowBundleAdjuster window_;
  DisparityOffsetEstimator disparity_offset_;
  TrackAnchors anchors_;
  int64_t frame_number_ = 0;  // Of the next frame with images (the anchors' clock).
  bool configured_ = false;
  int pyramid_levels_ = 3;
  int pyramid_window_ = 15;

  ImagePyramid previous_left_;
  std::vector<Feature> features_;
  double tracked_fraction_ = 1.0;  // Fraction of the features tracked into the last frame.
  // Its slow average (one fifth per frame): the turn search compares against it, so that one
  // poorly tracked frame (the turn's first) does not hide the next.
  double usual_tracked_fraction_ = 1.0;
  TurnAxis turn_axis_;  // The axis the camera turns about (the turn search's yaw).
  double previous_time_s_ = 0;
  Eigen::Isometry3d last_motion_ = Eigen::Isometry3d::Identity();  // Last applied motion ...
  double last_motion_dt_s_ = 0;                                    // ... and its time span.
  bool has_previous_ = false;
  int64_t next_id_ = 0;
  Eigen::Isometry3d world_from_camera_ = Eigen::Isometry3d::Identity();
  bool has_keyframe_ = false;
  Eigen::Isometry3d world_from_keyframe_ = Eigen::Isometry3d::Identity();
  size_t keyframe_tracks_ = 0;  // Features with a stereo match at the keyframe.
};

}  // namespace sightline
