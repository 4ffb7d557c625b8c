#include "core/stereo/stereo_odometry.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "core/stereo/option_check.h"

namespace sightline {

using stereo_internal::Invalid;

bool StereoOdometryOptions::IsValid(std::string* error) const {
  if (refine_rounds < 1 || refine_rounds > 10) {
    return Invalid(error, "stereo.refine_rounds must lie in [1, 10]");
  }
  return rectify.IsValid(error) && tracking.IsValid(error) && anchor.IsValid(error) &&
         matching.IsValid(error) && ransac.IsValid(error) && refine.IsValid(error) &&
         gate.IsValid(error) && keyframe.IsValid(error) && window.IsValid(error) &&
         disparity_offset.IsValid(error);
}

OptionTable<StereoOdometryOptions> StereoOdometryOptions::Describe() {
  using O = StereoOdometryOptions;
  return OptionTable<O>("")
      .Nested(&O::rectify, RectifierOptions::Describe())
      .Nested(&O::tracking, FeatureTrackerOptions::Describe())
      .Nested(&O::anchor, TrackAnchorOptions::Describe())
      .Nested(&O::matching, StereoMatcherOptions::Describe())
      .Nested(&O::ransac, MotionEstimatorOptions::Describe())
      .Nested(&O::refine, MotionRefinerOptions::Describe())
      .Nested(&O::gate, MotionGateOptions::Describe())
      .Nested(&O::keyframe, KeyframeOptions::Describe())
      .Nested(&O::window, WindowBundleOptions::Describe())
      .Nested(&O::disparity_offset, DisparityOffsetOptions::Describe())
      .Int("stereo.refine_rounds", &O::refine_rounds, "", 1, 10, 1,
           "Refinement rounds: refine, re-select inliers by the reprojection threshold, refine.");
}

namespace {

class StageClock {
 public:
  StageClock() : start_(std::chrono::steady_clock::now()) {}
  // Milliseconds since construction or the last Lap().
  double Lap() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - start_).count();
    start_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

void Record(TimingStats* timing, const char* stage, double ms, double* field) {
  *field = ms;
  if (timing) timing->Add(stage, ms);
}

// Stereo observations for the window: the features marked in `use`, and every new one.
template <typename Feature>
std::vector<TrackObservation> Observations(const std::vector<Feature>& kept,
                                           const std::vector<int>& kept_source,
                                           const std::vector<unsigned char>& use) {
  std::vector<TrackObservation> out;
  out.reserve(kept.size());
  for (size_t k = 0; k < kept.size(); ++k) {
    if (!use[k] && kept_source[k] >= 0) continue;
    out.push_back({kept[k].id, kept[k].left.x, kept[k].left.y, kept[k].right.x});
  }
  return out;
}

}  // namespace

StereoOdometry::StereoOdometry(StereoOdometryOptions options)
    : options_(options),
      rectifier_(options.rectify),
      tracker_(options.tracking),
      matcher_(options.matching),
      estimator_(options.ransac),
      refiner_(options.refine),
      gate_(options.gate),
      window_(options.window),
      disparity_offset_(options.disparity_offset),
      anchors_(options.anchor) {}

Status StereoOdometry::Configure(const StereoRig& rig) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  configured_ = false;
  SIGHTLINE_RETURN_IF_ERROR(rectifier_.Configure(rig));
  pyramid_levels_ = std::max(
      {options_.tracking.pyramid_levels, options_.matching.klt_levels,
       options_.matching.coarse_level,
       options_.tracking.retrack_fraction > 0 ? options_.tracking.retrack_pyramid_levels : 0});
  pyramid_window_ = std::max(options_.tracking.window_px, options_.matching.window_px);
  Reset();
  configured_ = true;
  return Status::Ok();
}

void StereoOdometry::Reset() {
  previous_left_ = ImagePyramid();
  features_.clear();
  tracked_fraction_ = 1.0;
  has_previous_ = false;
  previous_time_s_ = 0;
  last_motion_ = Eigen::Isometry3d::Identity();
  last_motion_dt_s_ = 0;
  world_from_camera_ = Eigen::Isometry3d::Identity();
  has_keyframe_ = false;
  world_from_keyframe_ = Eigen::Isometry3d::Identity();
  keyframe_tracks_ = 0;
  gate_.Reset();
  window_.Reset();
  disparity_offset_.Reset();
  anchors_.Reset();
  frame_number_ = 0;
}

StatusOr<std::shared_ptr<const StereoOdometryResult>> StereoOdometry::Process(
    const StereoFrame& frame, TimingStats* timing) {
  if (!configured_) return FailedPrecondition("StereoOdometry::Process before Configure");
  auto result = std::make_shared<StereoOdometryResult>();
  result->stamp = frame.stamp;
  FrameStats& stats = result->stats;
  StageClock total_clock, clock;
  const double dt = has_previous_ ? frame.stamp.sensor_time_s - previous_time_s_ : 0.0;

  // A frame that cannot be used: the gate decides what motion to assume; the state stays at the
  // last good frame, so the next good frame is measured against it.
  auto reject_input = [&](const std::string& why) {
    MotionCandidate candidate;
    candidate.failure = why;
    const GateDecision decision = gate_.Check(candidate, dt);
    result->current_from_previous = decision.current_from_previous;
    result->world_from_camera = world_from_camera_ * decision.current_from_previous.inverse();
    stats.gated = has_previous_;
    stats.status = has_previous_ ? decision.reason : why + "; pose held";
    stats.gated = true;
    stats.total_ms = total_clock.Lap();
    if (timing) timing->Add("total", stats.total_ms);
  };

  cv::Mat left, right;
  const Status rectified = rectifier_.Rectify(frame, &left, &right);
  Record(timing, "rectify", clock.Lap(), &stats.rectify_ms);
  if (!rectified.ok()) {
    reject_input("bad input: " + rectified.message());
    return std::shared_ptr<const StereoOdometryResult>(result);
  }
  result->left_rectified = left;
  result->right_rectified = right;

  const ImagePyramid left_pyramid = BuildImagePyramid(left, pyramid_window_, pyramid_levels_);
  const ImagePyramid right_pyramid = BuildImagePyramid(right, pyramid_window_, pyramid_levels_);
  Record(timing, "pyramid", clock.Lap(), &stats.pyramid_ms);

  // Temporal tracking on the left image.
  std::vector<cv::Point2f> previous_points, tracked;
  std::vector<unsigned char> tracked_ok;
  previous_points.reserve(features_.size());
  for (const Feature& f : features_) previous_points.push_back(f.left);
  // Predict where features land under constant motion, so KLT starts near the answer even for
  // fast motion and subsampled input.
  std::vector<cv::Point2f> predicted;
  std::vector<float> predicted_disparity;
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();  // Predicted current_from_previous.
  if (has_previous_ && last_motion_dt_s_ > 0 && dt > 0) {
    const double scale = dt / last_motion_dt_s_;
    const Eigen::AngleAxisd aa(last_motion_.rotation());
    motion.linear() = Eigen::AngleAxisd(aa.angle() * scale, aa.axis()).toRotationMatrix();
    motion.translation() = last_motion_.translation() * scale;
    const RectifiedStereoCamera& c = rectifier_.camera();
    predicted.reserve(features_.size());
    for (const Feature& f : features_) {
      const Eigen::Vector3d y = motion * c.Triangulate(f.left.x, f.left.y, f.left.x - f.right.x);
      cv::Point2f p = f.left;
      float d = f.left.x - f.right.x;
      if (y.z() > 0.1) {
        const Eigen::Vector2d q = c.ProjectLeft(y);
        if (q.x() >= 0 && q.y() >= 0 && q.x() < c.width && q.y() < c.height) {
          p = cv::Point2f(static_cast<float>(q.x()), static_cast<float>(q.y()));
          d = static_cast<float>(c.f * c.baseline_m / y.z());
        }
      }
      predicted.push_back(p);
      predicted_disparity.push_back(d);
    }
  }
  if (has_previous_) {
    stats.retracked = tracker_.Track(previous_left_, left_pyramid, previous_points, predicted,
                                     &tracked, &tracked_ok, tracked_fraction_);
  }
  // Tracked positions aligned against their anchors (no drift); kRenew marks new anchors.
  std::vector<AnchorAlignment> alignment(tracked_ok.size(), AnchorAlignment::kUnchanged);
  if (options_.anchor.enabled && has_previous_) {
    const Eigen::Isometry3d world_from_predicted = world_from_camera_ * motion.inverse();
    for (size_t i = 0; i < tracked_ok.size(); ++i) {
      if (!tracked_ok[i]) continue;
      alignment[i] = anchors_.Align(rectifier_.camera(), features_[i].anchor, frame_number_,
                                    left_pyramid.image, world_from_predicted, &tracked[i]);
      if (alignment[i] == AnchorAlignment::kAligned) ++stats.anchored;
    }
  }
  std::vector<cv::Point2f> points;
  std::vector<float> guesses;
  std::vector<int> source;  // Index into features_, or -1 for new.
  for (size_t i = 0; i < tracked_ok.size(); ++i) {
    if (!tracked_ok[i]) continue;
    points.push_back(tracked[i]);
    guesses.push_back(predicted_disparity.empty() ? features_[i].left.x - features_[i].right.x
                                                  : predicted_disparity[i]);
    source.push_back(static_cast<int>(i));
  }
  stats.tracked = static_cast<int>(points.size());
  if (!previous_points.empty()) {
    tracked_fraction_ = static_cast<double>(points.size()) / previous_points.size();
  }
  Record(timing, "tracking", clock.Lap(), &stats.tracking_ms);

  // New corners where tracks are missing.
  const std::vector<cv::Point2f> fresh = tracker_.Detect(left_pyramid, points);
  for (const cv::Point2f& p : fresh) {
    points.push_back(p);
    guesses.push_back(std::numeric_limits<float>::quiet_NaN());
    source.push_back(-1);
  }
  Record(timing, "detection", clock.Lap(), &stats.detection_ms);

  // Stereo matching of every feature.
  std::vector<cv::Point2f> right_points;
  std::vector<unsigned char> matched;
  matcher_.Match(left_pyramid, right_pyramid, points, guesses, &right_points, &matched);
  std::vector<Feature> kept;
  std::vector<int> kept_source;
  std::vector<StereoCorrespondence> correspondences;
  std::vector<int> correspondence_feature;  // Index into kept.
  const RectifiedStereoCamera& cam = rectifier_.camera();
  for (size_t i = 0; i < points.size(); ++i) {
    if (!matched[i]) continue;
    Feature f;
    const int s = source[i];
    f.id = s >= 0 ? features_[static_cast<size_t>(s)].id : next_id_++;
    f.left = points[i];
    f.right = right_points[i];
    f.age = s >= 0 ? features_[static_cast<size_t>(s)].age + 1 : 0;
    if (s >= 0) {
      const Feature& p = features_[static_cast<size_t>(s)];
      f.has_keyframe = p.has_keyframe;
      f.keyframe_left = p.keyframe_left;
      f.keyframe_right = p.keyframe_right;
      if (alignment[static_cast<size_t>(s)] != AnchorAlignment::kRenew) f.anchor = p.anchor;
      StereoCorrespondence c;
      c.previous = {p.left.x, p.left.y, p.right.x};
      c.current = {f.left.x, f.left.y, f.right.x};
      disparity_offset_.Apply(&c);
      Triangulate(cam, &c);
      correspondences.push_back(c);
      correspondence_feature.push_back(static_cast<int>(kept.size()));
    } else {
      ++stats.new_features;
    }
    kept.push_back(f);
    kept_source.push_back(s);
  }
  stats.stereo_matches = static_cast<int>(kept.size());
  stats.correspondences = static_cast<int>(correspondences.size());
  stats.disparity_offset_px = disparity_offset_.offset_px();
  Record(timing, "matching", clock.Lap(), &stats.matching_ms);

  // Motion: RANSAC, refinement, gate.
  std::vector<int> inliers;
  if (!has_previous_) {
    stats.status = "first frame";
    if (options_.window.enabled) {
      window_.Reset();
      window_.Add(cam, world_from_camera_,
                  Observations(kept, kept_source, std::vector<unsigned char>(kept.size(), 1)));
    }
  } else {
    MotionCandidate candidate;
    const MotionHypothesis h = estimator_.Estimate(cam, correspondences);
    stats.ransac_iterations = h.iterations;
    stats.rigidity_failures = h.rigidity_failures;
    Record(timing, "ransac", clock.Lap(), &stats.ransac_ms);
    if (h.ok) {
      Eigen::Isometry3d motion = h.current_from_previous;
      inliers = h.inliers;
      RefinementSummary summary;
      for (int round = 0; round < options_.refine_rounds; ++round) {
        summary = refiner_.Refine(cam, correspondences, inliers, &motion);
        if (round + 1 < options_.refine_rounds) {
          std::vector<int> again = MotionEstimator::Inliers(cam, correspondences, motion,
                                                            options_.ransac.inlier_threshold_px);
          if (again.size() < 3) break;
          inliers = std::move(again);
        }
      }
      candidate.estimated = true;
      candidate.current_from_previous = motion;
      candidate.residual_px = summary.final_rms_px;
      candidate.inliers = static_cast<int>(inliers.size());
      stats.residual_px = summary.final_rms_px;
      stats.inliers = candidate.inliers;
    } else {
      candidate.failure = stats.stereo_matches == 0
                              ? "no stereo matches (no texture, lens cap, or identical left and "
                                "right images?)"
                              : "RANSAC failed: " + h.failure;
    }
    Record(timing, "refine", clock.Lap(), &stats.refine_ms);
    const GateDecision decision = gate_.Check(candidate, dt);
    stats.gated = !decision.accepted;
    if (!decision.accepted) stats.status = decision.reason;
    result->current_from_previous = decision.current_from_previous;
    if (stats.gated && stats.stereo_matches < options_.gate.min_inliers) {
      // Nothing to track from (black frame, lens cap): keep the last good frame as reference so
      // the next frame is measured against it; publish the gate's prediction only.
      result->world_from_camera = world_from_camera_ * decision.current_from_previous.inverse();
      stats.translation_m = result->current_from_previous.translation().norm();
      stats.rotation_deg =
          Eigen::AngleAxisd(result->current_from_previous.rotation()).angle() * 180.0 / M_PI;
      stats.total_ms = total_clock.Lap();
      if (timing) timing->Add("total", stats.total_ms);
      return std::shared_ptr<const StereoOdometryResult>(result);
    }
    Eigen::Isometry3d world_from_current =
        world_from_camera_ * decision.current_from_previous.inverse();
    bool new_keyframe = true;
    if (options_.keyframe.enabled && has_keyframe_ && !stats.gated) {
      // Re-estimate against the keyframe's observations of the surviving tracks.
      std::vector<StereoCorrespondence> from_keyframe;
      for (const Feature& f : kept) {
        if (!f.has_keyframe) continue;
        StereoCorrespondence c;
        c.previous = {f.keyframe_left.x, f.keyframe_left.y, f.keyframe_right.x};
        c.current = {f.left.x, f.left.y, f.right.x};
        disparity_offset_.Apply(&c);
        Triangulate(cam, &c);
        from_keyframe.push_back(c);
      }
      Eigen::Isometry3d current_from_keyframe = world_from_current.inverse() * world_from_keyframe_;
      const int agree = RefineAgainstKeyframe(
          cam, refiner_, from_keyframe, options_.ransac.inlier_threshold_px, options_.refine_rounds,
          options_.keyframe.min_inliers, &current_from_keyframe);
      if (agree >= options_.keyframe.min_inliers) {
        world_from_current = world_from_keyframe_ * current_from_keyframe.inverse();
        result->current_from_previous = world_from_current.inverse() * world_from_camera_;
        new_keyframe = static_cast<double>(from_keyframe.size()) <
                       options_.keyframe.min_track_fraction * static_cast<double>(keyframe_tracks_);
      }
    }
    if (options_.window.enabled) {
      // Sliding-window adjustment over the frame's consistent tracks (inliers) and its new
      // features (seen again later); a frame whose motion was not measured restarts the window.
      if (stats.gated) window_.Reset();
      std::vector<unsigned char> use(kept.size(), stats.gated ? 1 : 0);
      if (!stats.gated) {
        for (int i : inliers)
          use[static_cast<size_t>(correspondence_feature[static_cast<size_t>(i)])] = 1;
      }
      WindowBundleSummary summary;
      const Eigen::Isometry3d adjusted =
          window_.Add(cam, world_from_current, Observations(kept, kept_source, use), &summary,
                      disparity_offset_.offset_px());
      if (summary.adjusted) {
        world_from_current = adjusted;
        result->current_from_previous = world_from_current.inverse() * world_from_camera_;
      }
      stats.window_points = summary.points;
      stats.window_rms_px = summary.final_rms_px;
      Record(timing, "window", clock.Lap(), &stats.window_ms);
    }
    world_from_camera_ = world_from_current;
    last_motion_ = result->current_from_previous;
    last_motion_dt_s_ = dt;
    if (options_.keyframe.enabled && new_keyframe) has_keyframe_ = false;  // Set below.
  }
  result->world_from_camera = world_from_camera_;
  stats.translation_m = result->current_from_previous.translation().norm();
  stats.rotation_deg =
      Eigen::AngleAxisd(result->current_from_previous.rotation()).angle() * 180.0 / M_PI;

  // Features for views.
  std::vector<unsigned char> is_inlier(kept.size(), 0);
  if (!stats.gated) {
    for (int i : inliers)
      is_inlier[static_cast<size_t>(correspondence_feature[static_cast<size_t>(i)])] = 1;
  }
  result->features.reserve(kept.size());
  for (size_t k = 0; k < kept.size(); ++k) {
    TrackedFeature t;
    t.id = kept[k].id;
    t.left = kept[k].left;
    t.right = kept[k].right;
    t.age = kept[k].age;
    const int s = kept_source[k];
    t.previous_left = s >= 0 ? features_[static_cast<size_t>(s)].left : kept[k].left;
    t.role =
        s < 0 ? FeatureRole::kNew : (is_inlier[k] ? FeatureRole::kInlier : FeatureRole::kOutlier);
    result->features.push_back(t);
  }

  std::vector<OffsetTrack> offset_tracks(kept.size());
  for (size_t k = 0; k < kept.size(); ++k) {
    offset_tracks[k] = {kept[k].id, {kept[k].left.x, kept[k].left.y, kept[k].right.x}};
  }
  disparity_offset_.Observe(cam, refiner_, options_.ransac.inlier_threshold_px,
                            std::move(offset_tracks), world_from_camera_, !stats.gated);
  features_ = std::move(kept);
  if (options_.anchor.enabled) {
    // New tracks, and those whose anchor failed or expires, are anchored here, with the surface
    // their neighbours show.
    std::vector<Eigen::Vector3d> points;
    std::vector<cv::Point2f> pixels;
    std::vector<size_t> renew;
    points.reserve(features_.size());
    pixels.reserve(features_.size());
    for (size_t k = 0; k < features_.size(); ++k) {
      const Feature& f = features_[k];
      points.push_back(cam.Triangulate(f.left.x, f.left.y, f.left.x - f.right.x));
      pixels.push_back(f.left);
      if (!anchors_.Usable(f.anchor.frame, frame_number_ + 1)) renew.push_back(k);
    }
    const std::vector<Eigen::Vector3f> normals =
        SurfaceNormals(points, pixels, renew, options_.anchor);
    for (size_t r = 0; r < renew.size(); ++r) {
      Feature& f = features_[renew[r]];
      f.anchor = {frame_number_, f.left, f.left.x - f.right.x, normals[r]};
    }
    anchors_.AddFrame(frame_number_, left_pyramid.image, world_from_camera_);
  }
  ++frame_number_;
  if (options_.keyframe.enabled && !has_keyframe_) {
    // This frame becomes the keyframe: its stereo observations are what later frames refer to.
    for (Feature& f : features_) {
      f.has_keyframe = true;
      f.keyframe_left = f.left;
      f.keyframe_right = f.right;
    }
    world_from_keyframe_ = world_from_camera_;
    keyframe_tracks_ = features_.size();
    has_keyframe_ = true;
  }
  previous_left_ = left_pyramid;
  previous_time_s_ = frame.stamp.sensor_time_s;
  has_previous_ = true;
  stats.total_ms = total_clock.Lap();
  if (timing) timing->Add("total", stats.total_ms);
  return std::shared_ptr<const StereoOdometryResult>(result);
}

}  // namespace sightline
