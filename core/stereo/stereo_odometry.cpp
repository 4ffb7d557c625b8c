#include "core/stereo/stereo_odometry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/stereo/option_check.h"
#include "core/stereo/turn_search.h"

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

// The length and angle of the applied motion.
void SetMotionStats(const Eigen::Isometry3d& current_from_previous, FrameStats* stats) {
  stats->translation_m = current_from_previous.translation().norm();
  stats->rotation_deg = Eigen::AngleAxisd(current_from_previous.rotation()).angle() * 180.0 / M_PI;
}

}  // namespace

StereoOdometry::StereoOdometry(const StereoOdometryOptions& options)
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
  usual_tracked_fraction_ = 1.0;
  turn_axis_.Reset();
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

// One frame's working data, passed between the steps of Process().
struct StereoOdometry::FrameState {
  std::shared_ptr<StereoOdometryResult> result;
  TimingStats* timing = nullptr;
  StageClock total_clock, clock;
  double dt = 0;  // Since the previous frame [s].
  ImagePyramid left_pyramid, right_pyramid;
  // Tracking and detection: left positions, disparity guesses (NaN for new corners) and the
  // feature each continues (index into features_, or -1 for new).
  std::vector<cv::Point2f> points;
  std::vector<float> guesses;
  std::vector<int> source;
  std::vector<AnchorAlignment> alignment;  // Per feature of the previous frame.
  // Matching: the features with a stereo match, the index into features_ each continues (or
  // -1), and the correspondences of the tracked ones.
  std::vector<Feature> kept;
  std::vector<int> kept_source;
  std::vector<StereoCorrespondence> correspondences;
  std::vector<int> correspondence_feature;  // Index into kept.
  std::vector<int> inliers;                 // Index into correspondences.
};

StatusOr<std::shared_ptr<const StereoOdometryResult>> StereoOdometry::Process(
    const StereoFrame& frame, TimingStats* timing) {
  if (!configured_) return FailedPrecondition("StereoOdometry::Process before Configure");
  FrameState s;
  s.result = std::make_shared<StereoOdometryResult>();
  s.timing = timing;
  s.result->stamp = frame.stamp;
  FrameStats& stats = s.result->stats;
  s.dt = has_previous_ ? frame.stamp.sensor_time_s - previous_time_s_ : 0.0;

  cv::Mat left, right;
  const Status rectified = rectifier_.Rectify(frame, &left, &right);
  Record(timing, "rectify", s.clock.Lap(), &stats.rectify_ms);
  if (!rectified.ok()) {
    RejectInput("bad input: " + rectified.message(), &s);
    return FinishFrame(&s);
  }
  s.result->left_rectified = left;
  s.result->right_rectified = right;

  s.left_pyramid = BuildImagePyramid(left, pyramid_window_, pyramid_levels_);
  s.right_pyramid = BuildImagePyramid(right, pyramid_window_, pyramid_levels_);
  Record(timing, "pyramid", s.clock.Lap(), &stats.pyramid_ms);

  TrackFeatures(&s);
  DetectFeatures(&s);
  MatchFeatures(&s);
  if (!has_previous_) {
    StartFirstFrame(&s);
  } else if (!EstimateMotion(&s)) {
    return FinishFrame(&s);
  }
  s.result->world_from_camera = world_from_camera_;
  SetMotionStats(s.result->current_from_previous, &stats);

  PublishFeatures(&s);
  ObserveDisparityOffset(s);
  features_ = std::move(s.kept);
  RenewAnchors(s.left_pyramid.image);
  ++frame_number_;
  SetKeyframeIfNeeded();
  previous_left_ = s.left_pyramid;
  previous_time_s_ = frame.stamp.sensor_time_s;
  has_previous_ = true;
  return FinishFrame(&s);
}

void StereoOdometry::RejectInput(const std::string& why, FrameState* s) {
  FrameStats& stats = s->result->stats;
  MotionCandidate candidate;
  candidate.failure = why;
  const GateDecision decision = gate_.Check(candidate, s->dt);
  s->result->current_from_previous = decision.current_from_previous;
  s->result->world_from_camera = world_from_camera_ * decision.current_from_previous.inverse();
  stats.gated = has_previous_;
  stats.status = has_previous_ ? decision.reason : why + "; pose held";
  stats.gated = true;
}

void StereoOdometry::TrackFeatures(FrameState* s) {
  FrameStats& stats = s->result->stats;
  std::vector<cv::Point2f> previous_points, tracked;
  std::vector<unsigned char> tracked_ok;
  previous_points.reserve(features_.size());
  for (const Feature& f : features_) previous_points.push_back(f.left);
  // Predict where features land under constant motion, so KLT starts near the answer even for
  // fast motion and subsampled input.
  std::vector<cv::Point2f> predicted;
  std::vector<float> predicted_disparity;
  Eigen::Isometry3d motion = PredictMotion(s->dt, &predicted, &predicted_disparity);
  if (has_previous_) {
    stats.retracked = tracker_.Track(previous_left_, s->left_pyramid, previous_points, predicted,
                                     &tracked, &tracked_ok, tracked_fraction_);
    SearchTurn(previous_points, s, &motion, &predicted_disparity, &tracked, &tracked_ok);
  }
  AlignToAnchors(motion, tracked_ok, &tracked, s);
  for (size_t i = 0; i < tracked_ok.size(); ++i) {
    if (!tracked_ok[i]) continue;
    s->points.push_back(tracked[i]);
    s->guesses.push_back(predicted_disparity.empty() ? features_[i].left.x - features_[i].right.x
                                                     : predicted_disparity[i]);
    s->source.push_back(static_cast<int>(i));
  }
  stats.tracked = static_cast<int>(s->points.size());
  if (!previous_points.empty()) {
    tracked_fraction_ = static_cast<double>(s->points.size()) / previous_points.size();
    usual_tracked_fraction_ = frame_number_ <= 1
                                  ? tracked_fraction_
                                  : 0.8 * usual_tracked_fraction_ + 0.2 * tracked_fraction_;
  }
  Record(s->timing, "tracking", s->clock.Lap(), &stats.tracking_ms);
}

Eigen::Isometry3d StereoOdometry::PredictMotion(double dt, std::vector<cv::Point2f>* predicted,
                                                std::vector<float>* predicted_disparity) const {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();  // Predicted current_from_previous.
  if (!(has_previous_ && last_motion_dt_s_ > 0 && dt > 0)) return motion;
  const double scale = dt / last_motion_dt_s_;
  const Eigen::AngleAxisd aa(last_motion_.rotation());
  motion.linear() = Eigen::AngleAxisd(aa.angle() * scale, aa.axis()).toRotationMatrix();
  motion.translation() = last_motion_.translation() * scale;
  PredictPoints(motion, predicted, predicted_disparity);
  return motion;
}

void StereoOdometry::PredictPoints(const Eigen::Isometry3d& motion,
                                   std::vector<cv::Point2f>* predicted,
                                   std::vector<float>* predicted_disparity) const {
  const RectifiedStereoCamera& c = rectifier_.camera();
  predicted->clear();
  predicted_disparity->clear();
  predicted->reserve(features_.size());
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
    predicted->push_back(p);
    predicted_disparity->push_back(d);
  }
}

void StereoOdometry::SearchTurn(const std::vector<cv::Point2f>& previous_points, FrameState* s,
                                Eigen::Isometry3d* motion, std::vector<float>* predicted_disparity,
                                std::vector<cv::Point2f>* tracked,
                                std::vector<unsigned char>* tracked_ok) {
  const FeatureTrackerOptions& o = options_.tracking;
  const auto count = [](const std::vector<unsigned char>& ok) {
    return static_cast<int>(std::count(ok.begin(), ok.end(), 1));
  };
  const int ok_count = count(*tracked_ok);
  if (!(o.turn_search_fraction > 0) || previous_points.empty() ||
      ok_count >= o.turn_search_fraction * usual_tracked_fraction_ * previous_points.size()) {
    return;
  }
  TurnSearchOptions search;
  search.width_px = o.turn_search_width_px;
  search.max_yaw_deg = o.turn_search_max_deg;
  const std::optional<TurnEstimate> turn = FindTurn(previous_left_.image, s->left_pyramid.image,
                                                    rectifier_.camera(), search, turn_axis_.axis());
  if (!turn) return;
  Eigen::Isometry3d turned = *motion;
  turned.linear() = turn->current_from_previous;
  std::vector<cv::Point2f> predicted, again;
  std::vector<float> disparity;
  std::vector<unsigned char> again_ok;
  PredictPoints(turned, &predicted, &disparity);
  tracker_.Track(previous_left_, s->left_pyramid, previous_points, predicted, &again, &again_ok,
                 tracked_fraction_);
  if (count(again_ok) <= ok_count) return;
  *motion = turned;
  *predicted_disparity = std::move(disparity);
  *tracked = std::move(again);
  *tracked_ok = std::move(again_ok);
  s->result->stats.turn_searched = true;
}

void StereoOdometry::AlignToAnchors(const Eigen::Isometry3d& predicted_motion,
                                    const std::vector<unsigned char>& tracked_ok,
                                    std::vector<cv::Point2f>* tracked, FrameState* s) {
  // Tracked positions aligned against their anchors (no drift); kRenew marks new anchors.
  s->alignment.assign(tracked_ok.size(), AnchorAlignment::kUnchanged);
  if (!(options_.anchor.enabled && has_previous_)) return;
  const Eigen::Isometry3d world_from_predicted = world_from_camera_ * predicted_motion.inverse();
  for (size_t i = 0; i < tracked_ok.size(); ++i) {
    if (!tracked_ok[i]) continue;
    s->alignment[i] = anchors_.Align(rectifier_.camera(), features_[i].anchor, frame_number_,
                                     s->left_pyramid.image, world_from_predicted, &(*tracked)[i]);
    if (s->alignment[i] == AnchorAlignment::kAligned) ++s->result->stats.anchored;
  }
}

void StereoOdometry::DetectFeatures(FrameState* s) {
  const std::vector<cv::Point2f> fresh = tracker_.Detect(s->left_pyramid, s->points);
  for (const cv::Point2f& p : fresh) {
    s->points.push_back(p);
    s->guesses.push_back(std::numeric_limits<float>::quiet_NaN());
    s->source.push_back(-1);
  }
  Record(s->timing, "detection", s->clock.Lap(), &s->result->stats.detection_ms);
}

void StereoOdometry::MatchFeatures(FrameState* s) {
  FrameStats& stats = s->result->stats;
  std::vector<cv::Point2f> right_points;
  std::vector<unsigned char> matched;
  matcher_.Match(s->left_pyramid, s->right_pyramid, s->points, s->guesses, &right_points, &matched);
  const RectifiedStereoCamera& cam = rectifier_.camera();
  for (size_t i = 0; i < s->points.size(); ++i) {
    if (!matched[i]) continue;
    Feature f;
    const int src = s->source[i];
    f.id = src >= 0 ? features_[static_cast<size_t>(src)].id : next_id_++;
    f.left = s->points[i];
    f.right = right_points[i];
    f.age = src >= 0 ? features_[static_cast<size_t>(src)].age + 1 : 0;
    if (src >= 0) {
      const Feature& p = features_[static_cast<size_t>(src)];
      f.has_keyframe = p.has_keyframe;
      f.keyframe_left = p.keyframe_left;
      f.keyframe_right = p.keyframe_right;
      if (s->alignment[static_cast<size_t>(src)] != AnchorAlignment::kRenew) f.anchor = p.anchor;
      StereoCorrespondence c;
      c.previous = {p.left.x, p.left.y, p.right.x};
      c.current = {f.left.x, f.left.y, f.right.x};
      disparity_offset_.Apply(&c);
      Triangulate(cam, &c);
      s->correspondences.push_back(c);
      s->correspondence_feature.push_back(static_cast<int>(s->kept.size()));
    } else {
      ++stats.new_features;
    }
    s->kept.push_back(f);
    s->kept_source.push_back(src);
  }
  stats.stereo_matches = static_cast<int>(s->kept.size());
  stats.correspondences = static_cast<int>(s->correspondences.size());
  stats.disparity_offset_px = disparity_offset_.offset_px();
  Record(s->timing, "matching", s->clock.Lap(), &stats.matching_ms);
}

void StereoOdometry::StartFirstFrame(FrameState* s) {
  s->result->stats.status = "first frame";
  if (!options_.window.enabled) return;
  window_.Reset();
  window_.Add(rectifier_.camera(), world_from_camera_,
              Observations(s->kept, s->kept_source, std::vector<unsigned char>(s->kept.size(), 1)));
}

bool StereoOdometry::EstimateMotion(FrameState* s) {
  FrameStats& stats = s->result->stats;
  StereoOdometryResult& result = *s->result;
  const MotionCandidate candidate = MeasureMotion(s);
  const GateDecision decision = gate_.Check(candidate, s->dt);
  stats.gated = !decision.accepted;
  if (!decision.accepted) stats.status = decision.reason;
  result.current_from_previous = decision.current_from_previous;
  if (stats.gated && stats.stereo_matches < options_.gate.min_inliers) {
    // Nothing to track from (black frame, lens cap): keep the last good frame as reference so
    // the next frame is measured against it; publish the gate's prediction only.
    result.world_from_camera = world_from_camera_ * decision.current_from_previous.inverse();
    SetMotionStats(result.current_from_previous, &stats);
    return false;
  }
  Eigen::Isometry3d world_from_current =
      world_from_camera_ * decision.current_from_previous.inverse();
  const bool new_keyframe = AlignToKeyframe(s, &world_from_current);
  if (options_.window.enabled) AdjustWindow(s, &world_from_current);
  world_from_camera_ = world_from_current;
  last_motion_ = result.current_from_previous;
  last_motion_dt_s_ = s->dt;
  turn_axis_.Add(result.current_from_previous.linear());
  if (options_.keyframe.enabled && new_keyframe) has_keyframe_ = false;  // Set later.
  return true;
}

MotionCandidate StereoOdometry::MeasureMotion(FrameState* s) {
  FrameStats& stats = s->result->stats;
  const RectifiedStereoCamera& cam = rectifier_.camera();
  MotionCandidate candidate;
  const MotionHypothesis h = estimator_.Estimate(cam, s->correspondences);
  stats.ransac_iterations = h.iterations;
  stats.rigidity_failures = h.rigidity_failures;
  Record(s->timing, "ransac", s->clock.Lap(), &stats.ransac_ms);
  if (h.ok) {
    Eigen::Isometry3d motion = h.current_from_previous;
    s->inliers = h.inliers;
    RefinementSummary summary;
    for (int round = 0; round < options_.refine_rounds; ++round) {
      summary = refiner_.Refine(cam, s->correspondences, s->inliers, &motion);
      if (round + 1 < options_.refine_rounds) {
        std::vector<int> again = MotionEstimator::Inliers(cam, s->correspondences, motion,
                                                          options_.ransac.inlier_threshold_px);
        if (again.size() < 3) break;
        s->inliers = std::move(again);
      }
    }
    candidate.estimated = true;
    candidate.current_from_previous = motion;
    candidate.residual_px = summary.final_rms_px;
    candidate.inliers = static_cast<int>(s->inliers.size());
    stats.residual_px = summary.final_rms_px;
    stats.inliers = candidate.inliers;
  } else {
    candidate.failure = stats.stereo_matches == 0
                            ? "no stereo matches (no texture, lens cap, or identical left and "
                              "right images?)"
                            : "RANSAC failed: " + h.failure;
  }
  Record(s->timing, "refine", s->clock.Lap(), &stats.refine_ms);
  return candidate;
}

bool StereoOdometry::AlignToKeyframe(FrameState* s, Eigen::Isometry3d* world_from_current) {
  if (!(options_.keyframe.enabled && has_keyframe_ && !s->result->stats.gated)) return true;
  // Re-estimate against the keyframe's observations of the surviving tracks.
  const RectifiedStereoCamera& cam = rectifier_.camera();
  std::vector<StereoCorrespondence> from_keyframe;
  for (const Feature& f : s->kept) {
    if (!f.has_keyframe) continue;
    StereoCorrespondence c;
    c.previous = {f.keyframe_left.x, f.keyframe_left.y, f.keyframe_right.x};
    c.current = {f.left.x, f.left.y, f.right.x};
    disparity_offset_.Apply(&c);
    Triangulate(cam, &c);
    from_keyframe.push_back(c);
  }
  Eigen::Isometry3d current_from_keyframe = world_from_current->inverse() * world_from_keyframe_;
  const int agree = RefineAgainstKeyframe(
      cam, refiner_, from_keyframe, options_.ransac.inlier_threshold_px, options_.refine_rounds,
      options_.keyframe.min_inliers, &current_from_keyframe);
  if (agree < options_.keyframe.min_inliers) return true;
  *world_from_current = world_from_keyframe_ * current_from_keyframe.inverse();
  s->result->current_from_previous = world_from_current->inverse() * world_from_camera_;
  return static_cast<double>(from_keyframe.size()) <
         options_.keyframe.min_track_fraction * static_cast<double>(keyframe_tracks_);
}

void StereoOdometry::AdjustWindow(FrameState* s, Eigen::Isometry3d* world_from_current) {
  // Sliding-window adjustment over the frame's consistent tracks (inliers) and its new
  // features (seen again later); a frame whose motion was not measured restarts the window.
  FrameStats& stats = s->result->stats;
  if (stats.gated) window_.Reset();
  std::vector<unsigned char> use(s->kept.size(), stats.gated ? 1 : 0);
  if (!stats.gated) {
    for (int i : s->inliers)
      use[static_cast<size_t>(s->correspondence_feature[static_cast<size_t>(i)])] = 1;
  }
  WindowBundleSummary summary;
  const Eigen::Isometry3d adjusted = window_.Add(rectifier_.camera(), *world_from_current,
                                                 Observations(s->kept, s->kept_source, use),
                                                 &summary, disparity_offset_.offset_px());
  if (summary.adjusted) {
    *world_from_current = adjusted;
    s->result->current_from_previous = world_from_current->inverse() * world_from_camera_;
  }
  stats.window_points = summary.points;
  stats.window_rms_px = summary.final_rms_px;
  Record(s->timing, "window", s->clock.Lap(), &stats.window_ms);
}

void StereoOdometry::PublishFeatures(FrameState* s) const {
  const std::vector<Feature>& kept = s->kept;
  std::vector<unsigned char> is_inlier(kept.size(), 0);
  if (!s->result->stats.gated) {
    for (int i : s->inliers)
      is_inlier[static_cast<size_t>(s->correspondence_feature[static_cast<size_t>(i)])] = 1;
  }
  std::vector<TrackedFeature>& features = s->result->features;
  features.reserve(kept.size());
  for (size_t k = 0; k < kept.size(); ++k) {
    TrackedFeature t;
    t.id = kept[k].id;
    t.left = kept[k].left;
    t.right = kept[k].right;
    t.age = kept[k].age;
    const int src = s->kept_source[k];
    t.previous_left = src >= 0 ? features_[static_cast<size_t>(src)].left : kept[k].left;
    t.role =
        src < 0 ? FeatureRole::kNew : (is_inlier[k] ? FeatureRole::kInlier : FeatureRole::kOutlier);
    features.push_back(t);
  }
}

void StereoOdometry::ObserveDisparityOffset(const FrameState& s) {
  std::vector<OffsetTrack> offset_tracks(s.kept.size());
  for (size_t k = 0; k < s.kept.size(); ++k) {
    offset_tracks[k] = {s.kept[k].id, {s.kept[k].left.x, s.kept[k].left.y, s.kept[k].right.x}};
  }
  disparity_offset_.Observe(rectifier_.camera(), refiner_, options_.ransac.inlier_threshold_px,
                            std::move(offset_tracks), world_from_camera_, !s.result->stats.gated);
}

void StereoOdometry::RenewAnchors(const cv::Mat& left_image) {
  if (!options_.anchor.enabled) return;
  // New tracks, and those whose anchor failed or expires, are anchored here, with the surface
  // their neighbours show.
  const RectifiedStereoCamera& cam = rectifier_.camera();
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
  anchors_.AddFrame(frame_number_, left_image, world_from_camera_);
}

void StereoOdometry::SetKeyframeIfNeeded() {
  if (!options_.keyframe.enabled || has_keyframe_) return;
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

std::shared_ptr<const StereoOdometryResult> StereoOdometry::FinishFrame(FrameState* s) const {
  s->result->stats.total_ms = s->total_clock.Lap();
  if (s->timing) s->timing->Add("total", s->result->stats.total_ms);
  return s->result;
}

}  // namespace sightline
