#include "core/mono/mono_slam.h"

#include <algorithm>
#include <cmath>
#include <ctime>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace sightline {

MonoSlam::MonoSlam(MonoSlamOptions options) : options_(std::move(options)) {}

MonoSlam::~MonoSlam() { StopThread(); }

namespace {

// CPU time of the calling thread [ms]: what tracking itself costs, whoever else shares the core.
double ThreadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

}  // namespace

Status MonoSlam::Configure(const PinholeCamera& camera, TimingStats* timing) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  SIGHTLINE_RETURN_IF_ERROR(camera.Validate());
  StopThread();
  camera_ = camera;
  timing_ = timing;
  const double factor = options_.features.scale_factor;
  extractor_ = std::make_unique<FeatureExtractor>(options_.features, camera_);
  initializer_ = std::make_unique<TwoViewInitializer>(options_.init, camera_, factor);
  tracker_ = std::make_unique<Tracker>(options_.tracking, camera_, factor);
  mapper_ = std::make_unique<LocalMapper>(options_.mapping, camera_, factor, &map_, &map_mutex_);
  loop_closer_ = std::make_unique<LoopCloser>(options_.mapping, options_.tracking, camera_, factor);
  configured_ = true;
  Reset();
  return Status::Ok();
}

void MonoSlam::StartMappingThread() {
  if (!options_.mapping.threaded || mapping_thread_.joinable()) return;
  keyframe_queue_ = std::make_unique<BoundedQueue<std::shared_ptr<KeyFrame>>>(
      "keyframes", 2, QueuePolicy::kBlockWhenFull);
  mapping_thread_ = std::thread([this] { MappingLoop(); });
}

void MonoSlam::StopThread() {
  if (keyframe_queue_) keyframe_queue_->Shutdown();
  if (mapping_thread_.joinable()) mapping_thread_.join();
  keyframe_queue_.reset();
}

void MonoSlam::Stop() {
  StopThread();
  if (!configured_ || !initialised_ || final_bundle_done_ ||
      options_.mapping.final_ba_iterations <= 0) {
    return;
  }
  final_bundle_done_ = true;
  FlushPointCounts(true);
  const double start = HostTimeS();
  const MonoMappingOptions& o = options_.mapping;
  const int keyframes = static_cast<int>(map_.keyframes().size());
  IdleBundleTotals stop;
  if (keyframes <= o.final_ba_max_keyframes) {
    // A small map: the full global adjustment (two rounds), as PTAM does it.
    const BundleSummary summary = mapper_->FinalBundle(o.final_ba_iterations);
    stop.stop_full = true;
    stop.stop_keyframes_adjusted = 2 * keyframes;
    stop.stop_iterations = summary.iterations;
    stop.stop_longest_step_ms = (HostTimeS() - start) * 1000.0;
  } else {
    // A large map: what is left of the idle-time pass, at most final_ba_max_slices slices.
    for (int i = 0; i < o.final_ba_max_slices && mapper_->idle_slices_left() > 0; ++i) {
      const double step_start = HostTimeS();
      const IdleBundleStats slice = mapper_->IdleBundle(o.final_ba_iterations);
      ++stop.stop_slices;
      stop.stop_keyframes_adjusted += slice.keyframes;
      stop.stop_iterations += slice.bundle.iterations;
      stop.stop_longest_step_ms =
          std::max(stop.stop_longest_step_ms, (HostTimeS() - step_start) * 1000.0);
    }
  }
  if (timing_) timing_->Add("final_bundle_adjustment", (HostTimeS() - start) * 1000.0);
  {
    std::lock_guard<std::mutex> lock(snapshot_mutex_);
    idle_totals_.stop_full = stop.stop_full;
    idle_totals_.stop_slices = stop.stop_slices;
    idle_totals_.stop_keyframes_adjusted = stop.stop_keyframes_adjusted;
    idle_totals_.stop_iterations = stop.stop_iterations;
    idle_totals_.stop_longest_step_ms = stop.stop_longest_step_ms;
  }
  PublishSnapshot();
}

int MonoSlam::revisits() const {
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return static_cast<int>(corrections_.size());
}

IdleBundleTotals MonoSlam::idle_bundle() const {
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return idle_totals_;
}

void MonoSlam::RunIdleSlice() {
  const MonoMappingOptions& o = options_.mapping;
  if (o.idle_ba_iterations <= 0 || mapper_->idle_slices_left() <= 0) return;
  const double start = HostTimeS();
  // Threaded mode: a keyframe waiting ends the slice after the current iteration, so idle-time
  // adjustment never holds up mapping.
  std::function<bool()> keyframe_waiting;
  if (options_.mapping.threaded && keyframe_queue_) {
    keyframe_waiting = [this] { return keyframe_queue_->size() > 0; };
  }
  const IdleBundleStats slice = mapper_->IdleBundle(o.idle_ba_iterations, keyframe_waiting);
  if (slice.keyframes == 0) return;
  if (timing_) timing_->Add("idle_bundle_adjustment", (HostTimeS() - start) * 1000.0);
  {
    std::lock_guard<std::mutex> lock(snapshot_mutex_);
    if (idle_totals_.slices == 0) idle_totals_.first_initial_rms_px = slice.bundle.initial_rms_px;
    ++idle_totals_.slices;
    idle_totals_.keyframes_adjusted += slice.keyframes;
    idle_totals_.iterations += slice.bundle.iterations;
    idle_totals_.last_final_rms_px = slice.bundle.final_rms_px;
  }
  PublishSnapshot();
}

void MonoSlam::ApplyCorrections() {
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  for (; corrections_applied_ < corrections_.size(); ++corrections_applied_) {
    const MapCorrection& c = corrections_[corrections_applied_];
    camera_from_map_ = c.CorrectPose(camera_from_map_);
    velocity_.translation() *= c.scale;
  }
}

void MonoSlam::RefreshLocalPoints(double mean_depth) {
  const double radius = options_.mapping.local_map_distance * mean_depth;
  Eigen::Vector3d built;
  {
    std::lock_guard<std::mutex> lock(snapshot_mutex_);
    local_camera_ = camera_from_map_;
    local_radius_ = radius;
    built = local_built_at_;
  }
  const Eigen::Vector3d centre = camera_from_map_.inverse().translation();
  if (radius <= 0 || (centre - built).norm() < 0.25 * radius) return;
  std::unique_lock<std::mutex> map_lock(map_mutex_, std::defer_lock);
  if (options_.mapping.threaded) {
    if (!map_lock.try_lock()) return;  // Mapping holds the map: next frame.
  } else {
    map_lock.lock();
  }
  std::vector<int64_t> keyframes;
  auto local = std::make_shared<const std::vector<LocalPoint>>(
      LocalPointsOf(camera_from_map_, radius, &keyframes));
  map_lock.unlock();
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  local_points_ = std::move(local);
  local_keyframes_ = std::move(keyframes);
  local_built_at_ = centre;
}

void MonoSlam::FlushPointCounts(bool wait) {
  if (pending_visible_.empty() && pending_found_.empty()) return;
  std::unique_lock<std::mutex> lock(map_mutex_, std::defer_lock);
  if (wait) {
    lock.lock();
  } else if (!lock.try_lock()) {
    return;
  }
  for (int64_t id : pending_visible_) {
    if (MapPoint* p = map_.FindPoint(id)) ++p->visible;
  }
  for (int64_t id : pending_found_) {
    if (MapPoint* p = map_.FindPoint(id)) ++p->found;
  }
  pending_visible_.clear();
  pending_found_.clear();
}

void MonoSlam::MappingLoop() {
#ifdef __linux__
  // Tracking must keep the frame rate; mapping takes what the core has left.
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), options_.mapping.thread_nice);
#endif
  // An empty item is the tracker's signal of idle time (frames without a keyframe): one slice
  // of the global adjustment.
  while (std::optional<std::shared_ptr<KeyFrame>> keyframe = keyframe_queue_->Pop()) {
    if (*keyframe) {
      MapKeyFrame(std::move(*keyframe));
      mapping_busy_ = false;
    } else if (!mapping_paused_) {
      RunIdleSlice();
    }
  }
}

void MonoSlam::Reset() {
  StopThread();
  {
    std::lock_guard<std::mutex> lock(map_mutex_);
    map_.Clear();
  }
  {
    std::lock_guard<std::mutex> lock(snapshot_mutex_);
    snapshot_ = std::make_shared<MapSnapshot>();
    local_points_ = std::make_shared<std::vector<LocalPoint>>();
    keyframe_history_.clear();
    corrections_.clear();
    local_keyframes_.clear();
    idle_totals_ = {};
    local_camera_ = Eigen::Isometry3d::Identity();
    local_radius_ = 0;
    local_built_at_ = Eigen::Vector3d::Zero();
  }
  corrections_applied_ = 0;
  if (initializer_)
    initializer_ = std::make_unique<TwoViewInitializer>(options_.init, camera_,
                                                        options_.features.scale_factor);
  initialised_ = false;
  final_bundle_done_ = false;
  pending_visible_.clear();
  pending_found_.clear();
  init_model_.clear();
  camera_from_map_ = velocity_ = Eigen::Isometry3d::Identity();
  lost_ = false;
  frames_since_keyframe_ = keyframe_inliers_ = lost_frames_ = relocalisations_ = 0;
  frames_processed_ = 0;
  low_rate_ = false;
  recent_steps_s_.clear();
  mapping_busy_ = false;
  if (configured_) StartMappingThread();
}

std::shared_ptr<const MapSnapshot> MonoSlam::Snapshot() const {
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return snapshot_;
}

std::vector<KeyFrameStats> MonoSlam::KeyFrameHistory() const {
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return keyframe_history_;
}

void MonoSlam::PublishSnapshot() {
  std::shared_ptr<const MapSnapshot> snapshot;
  std::shared_ptr<const std::vector<LocalPoint>> local;
  Eigen::Isometry3d camera;
  double radius = 0;
  {
    std::lock_guard<std::mutex> lock(snapshot_mutex_);
    camera = local_camera_;
    radius = local_radius_;
  }
  std::vector<int64_t> keyframes;
  {
    std::lock_guard<std::mutex> lock(map_mutex_);
    snapshot = SnapshotOf(map_);
    local =
        std::make_shared<const std::vector<LocalPoint>>(LocalPointsOf(camera, radius, &keyframes));
  }
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  snapshot_ = std::move(snapshot);
  local_points_ = std::move(local);
  local_keyframes_ = std::move(keyframes);
  local_built_at_ = camera.inverse().translation();
}

std::shared_ptr<const std::vector<LocalPoint>> MonoSlam::LocalPoints() const {
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return local_points_;
}

std::vector<LocalPoint> MonoSlam::LocalPointsOf(const Eigen::Isometry3d& camera_from_map,
                                                double radius,
                                                std::vector<int64_t>* keyframe_ids) const {
  // The points seen by the most recent keyframes (PTAM projects the whole map; recent
  // keyframes' points are what the camera can see and keep tracking cost bounded), and by the
  // old keyframes nearest the camera that look the same way: a revisited place is tracked on
  // the points mapped there before instead of being mapped again.
  constexpr int kLocalKeyFrames = 12, kOldKeyFrames = 12;
  const auto& keyframes = map_.keyframes();
  const int n = static_cast<int>(keyframes.size());
  std::vector<int> chosen;
  for (int k = n - 1; k >= 0 && k >= n - kLocalKeyFrames; --k) chosen.push_back(k);
  // Old keyframes join once the newest keyframe is linked to them (it observes old points,
  // as after a revisit): before that the old map lies where drift put it, and its points
  // would only be mismatched.
  const int old_end = n - kLocalKeyFrames - options_.mapping.loop_min_age;
  int old_points = 0;
  if (old_end > 0) {
    for (int64_t id : keyframes.back()->point_ids) {
      const MapPoint* p = id >= 0 ? map_.FindPoint(id) : nullptr;
      if (p != nullptr && p->first_keyframe < old_end) ++old_points;
    }
  }
  if (radius > 0 && old_end > 0 && old_points >= options_.mapping.loop_min_inliers / 2) {
    const Eigen::Vector3d centre = camera_from_map.inverse().translation();
    const Eigen::Vector3d axis = camera_from_map.rotation().row(2).transpose();
    std::vector<std::pair<double, int>> near;
    for (int k = 0; k < old_end; ++k) {
      const double d = (keyframes[k]->CentreInMap() - centre).norm();
      if (d > radius || keyframes[k]->camera_from_map.rotation().row(2).dot(axis) < 0.5) continue;
      near.emplace_back(d, k);
    }
    const size_t count = std::min<size_t>(kOldKeyFrames, near.size());
    std::partial_sort(near.begin(), near.begin() + count, near.end());
    for (size_t i = 0; i < count; ++i) chosen.push_back(near[i].second);
  }
  keyframe_ids->assign(chosen.begin(), chosen.end());  // Ids are indices.
  std::vector<int64_t> ids;
  for (int k : chosen) {
    for (int64_t id : keyframes[k]->point_ids) {
      if (id >= 0) ids.push_back(id);
    }
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<LocalPoint> points;
  points.reserve(ids.size());
  for (int64_t id : ids) {
    const MapPoint* p = map_.FindPoint(id);
    if (p != nullptr) points.push_back({id, p->position, p->descriptor});
  }
  return points;
}

bool MonoSlam::TryInitialise(const FrameFeatures& features, const FrameStamp& stamp,
                             MonoFrameStats* stats) {
  const bool enough = static_cast<int>(features.size()) >= options_.init.min_matches;
  if (!initializer_->has_first()) {
    if (enough) {
      initializer_->SetFirst(features, stamp, frames_processed_);
      stats->status = "initialising: first frame taken; move the camera sideways";
    } else {
      stats->status = "initialising: too few features (" + std::to_string(features.size()) + ")";
    }
    return false;
  }
  std::string why;
  std::optional<TwoViewResult> result = initializer_->TryInitialize(features, &why);
  if (!result) {
    stats->status = "initialising: " + why;
    // A frame the newest candidate no longer matches well (the view changed, or the frame
    // rate is low) becomes a candidate too; so does one after max_frames tries.
    if (enough && (initializer_->newest_matches() < options_.init.new_reference_matches ||
                   initializer_->frames_tried() >= options_.init.max_frames)) {
      initializer_->AddReference(features, stamp, frames_processed_);
    }
    return false;
  }
  first_stamp_ = initializer_->reference().stamp;
  const int64_t first_number = initializer_->reference().number;
  auto first = std::make_shared<KeyFrame>();
  first->features = initializer_->first();
  first->frame_index = first_stamp_.sequence_id;
  first->time_s = first_stamp_.sensor_time_s;
  auto second = std::make_shared<KeyFrame>();
  second->features = features;
  second->frame_index = stamp.sequence_id;
  second->time_s = stamp.sensor_time_s;
  second->camera_from_map = result->second_from_first;
  {
    std::lock_guard<std::mutex> lock(map_mutex_);
    map_.Clear();
    const int64_t a = map_.AddKeyFrame(first);
    const int64_t b = map_.AddKeyFrame(second);
    for (size_t k = 0; k < result->points.size(); ++k) {
      MapPoint p;
      p.position = result->points[k];
      p.descriptor = features.descriptors.row(result->matches[k].second).clone();
      p.first_keyframe = b;
      const int64_t id = map_.AddPoint(std::move(p));
      map_.AddObservation(id, a, result->matches[k].first);
      map_.AddObservation(id, b, result->matches[k].second);
    }
  }
  mapper_->GlobalBundle(options_.init.baseline);
  initialised_ = true;
  init_model_ = result->model;
  camera_from_map_ = second->camera_from_map;
  // Constant-velocity start: the initial motion spread over the frames it took (frames given
  // to Process, so that a subsampled sequence predicts a whole step).
  const double frames = std::max<int64_t>(1, frames_processed_ - first_number);
  const Eigen::AngleAxisd aa(camera_from_map_.rotation());
  velocity_ = Eigen::Isometry3d::Identity();
  velocity_.linear() = Eigen::AngleAxisd(aa.angle() / frames, aa.axis()).toRotationMatrix();
  velocity_.translation() = camera_from_map_.translation() / frames;
  frames_since_keyframe_ = 0;
  keyframe_inliers_ = static_cast<int>(result->points.size());
  PublishSnapshot();
  char text[192];
  std::snprintf(text, sizeof(text),
                "initialised (%s%s, %zu points, median parallax %.1f deg, baseline %.3f of depth, "
                "inliers H %d E %d)",
                result->model.c_str(), result->guided ? " guided" : "", result->points.size(),
                result->median_parallax_deg, result->baseline_ratio, result->homography_inliers,
                result->essential_inliers);
  stats->status = text;
  return true;
}

bool MonoSlam::TryRelocalise(const FrameFeatures& features, TrackOutcome* outcome) {
  // The keyframes of the local map first (the recent ones, newest first, then old ones near
  // the camera on a revisit), then every other keyframe, newest first.
  std::vector<std::shared_ptr<KeyFrame>> keyframes;
  std::vector<int64_t> local_ids;
  {
    std::lock_guard<std::mutex> lock(snapshot_mutex_);
    local_ids = local_keyframes_;
  }
  {
    std::lock_guard<std::mutex> lock(map_mutex_);
    const auto& all = map_.keyframes();
    std::vector<bool> taken(all.size(), false);
    for (int64_t id : local_ids) {
      if (id < static_cast<int64_t>(all.size()) && !taken[id]) {
        keyframes.push_back(all[id]);
        taken[id] = true;
      }
    }
    for (auto it = all.rbegin(); it != all.rend(); ++it) {
      if (!taken[(*it)->id]) keyframes.push_back(*it);
    }
  }
  const std::shared_ptr<const std::vector<LocalPoint>> all = LocalPoints();
  for (auto it = keyframes.begin(); it != keyframes.end(); ++it) {
    std::vector<LocalPoint> seen;
    {
      std::lock_guard<std::mutex> lock(map_mutex_);
      for (int64_t id : (*it)->point_ids) {
        const MapPoint* p = id >= 0 ? map_.FindPoint(id) : nullptr;
        if (p != nullptr) seen.push_back({id, p->position, p->descriptor});
      }
    }
    if (tracker_->Relocalise(features, **it, seen, *all, outcome)) return true;
  }
  return false;
}

TrackOutcome MonoSlam::TrackFrame(const FrameFeatures& features, MonoFrameStats* stats) {
  const std::shared_ptr<const std::vector<LocalPoint>> points = LocalPoints();
  TrackOutcome outcome = tracker_->Track(features, *points, velocity_ * camera_from_map_);
  const bool moving = !velocity_.isApprox(Eigen::Isometry3d::Identity());
  if (low_rate_ && moving && outcome.inliers < options_.tracking.fallback_inliers) {
    // At low frame rates the motion between frames is not constant: try the last pose too.
    TrackOutcome still =
        tracker_->Track(features, *points, camera_from_map_, options_.tracking.unsure_radius_px);
    if (still.inliers > outcome.inliers) outcome = std::move(still);
  }
  if (tracker_->QualityOf(outcome) == TrackingQuality::kLost) {
    TrackOutcome relocalised;
    if (TryRelocalise(features, &relocalised)) {
      outcome = std::move(relocalised);
      stats->relocalised = true;
      ++relocalisations_;
      velocity_ = Eigen::Isometry3d::Identity();
    }
  }
  return outcome;
}

bool MonoSlam::NeedKeyFrame(const TrackOutcome& outcome) const {
  if (mapping_paused_ || mapping_busy_) return false;
  const MonoMappingOptions& o = options_.mapping;
  const Eigen::Vector3d centre = camera_from_map_.inverse().translation();
  double nearest = 1e300;
  // The published keyframes: the one in the mapper's hands is excluded by mapping_busy_ above.
  for (const MapSnapshot::Frame& k : Snapshot()->keyframes) {
    nearest = std::min(nearest, (k.map_from_camera.translation() - centre).norm());
  }
  // Low frame rates: a large step or a large loss of points does not wait for the gap.
  if (low_rate_ && (outcome.inliers < o.urgent_keyframe_ratio * keyframe_inliers_ ||
                    nearest > o.urgent_keyframe_distance * outcome.mean_depth)) {
    return true;
  }
  if (frames_since_keyframe_ < o.min_keyframe_gap) return false;
  if (outcome.inliers < o.keyframe_match_ratio * keyframe_inliers_) return true;
  return nearest > o.keyframe_distance * outcome.mean_depth;
}

void MonoSlam::MapKeyFrame(std::shared_ptr<KeyFrame> keyframe) {
  {
    // Threaded mode: tracked before a revisit bent the map.
    std::lock_guard<std::mutex> lock(snapshot_mutex_);
    for (size_t i = keyframe->corrections_seen; i < corrections_.size(); ++i) {
      keyframe->camera_from_map = corrections_[i].CorrectPose(keyframe->camera_from_map);
    }
  }
  KeyFrameStats stats = mapper_->ProcessKeyFrame(keyframe);
  const double revisit_start = HostTimeS();
  if (std::optional<LoopMatch> loop = loop_closer_->Detect(map_, *keyframe)) {
    {
      std::lock_guard<std::mutex> lock(map_mutex_);
      stats.merged = loop_closer_->Apply(*loop, &map_);
    }
    stats.revisit_of = loop->partner;
    mapper_->MapChanged();
    std::lock_guard<std::mutex> lock(snapshot_mutex_);
    corrections_.push_back(loop->correction);
  }
  if (timing_) {
    timing_->Add("mapping", stats.mapping_ms);
    timing_->Add("bundle_adjustment", stats.bundle_ms);
    timing_->Add("revisit_search", (HostTimeS() - revisit_start) * 1000.0);
  }
  PublishSnapshot();
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  keyframe_history_.push_back(stats);
}

void MonoSlam::HandOver(std::shared_ptr<KeyFrame> keyframe) {
  if (options_.mapping.threaded && keyframe_queue_) {
    mapping_busy_ = true;
    if (!keyframe_queue_->Push(std::move(keyframe))) mapping_busy_ = false;
  } else {
    MapKeyFrame(std::move(keyframe));
  }
}

StatusOr<std::shared_ptr<const MonoSlamResult>> MonoSlam::Process(const MonoFrame& frame) {
  if (!configured_) return FailedPrecondition("MonoSlam::Process before Configure");
  if (!frame.image.empty() &&
      (frame.image.cols != camera_.width || frame.image.rows != camera_.height)) {
    return InvalidArgument("frame " + std::to_string(frame.stamp.sequence_id) + " is " +
                           std::to_string(frame.image.cols) + "x" +
                           std::to_string(frame.image.rows) + ", the camera " +
                           std::to_string(camera_.width) + "x" + std::to_string(camera_.height));
  }
  const double start = HostTimeS();
  const double start_cpu = ThreadCpuMs();
  auto result = std::make_shared<MonoSlamResult>();
  result->stamp = frame.stamp;
  result->image = frame.image;
  const FrameFeatures features = extractor_->Extract(frame.image);
  if (timing_) timing_->Add("features", (HostTimeS() - start) * 1000.0);
  MonoFrameStats& stats = result->stats;
  stats.keypoints = static_cast<int>(features.size());
  result->keypoint_state.assign(features.size(), 0);
  for (const cv::KeyPoint& k : features.keypoints) result->keypoints.push_back(k.pt);

  std::shared_ptr<KeyFrame> new_keyframe;
  ++frames_processed_;
  if (frames_processed_ > 1) {
    // This step, or the usual step of the last few frames (jitter around the threshold does not
    // flip the rules from frame to frame), with a microsecond for stamps computed as i / rate.
    const double step = frame.stamp.sensor_time_s - last_time_s_;
    recent_steps_s_.push_back(step);
    if (recent_steps_s_.size() > kRecentSteps) recent_steps_s_.pop_front();
    std::vector<double> sorted(recent_steps_s_.begin(), recent_steps_s_.end());
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double usual = sorted[sorted.size() / 2];
    low_rate_ = std::max(step, usual) + 1e-6 >= options_.tracking.low_rate_interval_s;
  }
  last_time_s_ = frame.stamp.sensor_time_s;
  if (!initialised_) {
    result->tracked = TryInitialise(features, frame.stamp, &stats);
    result->quality = result->tracked ? TrackingQuality::kGood : TrackingQuality::kInitialising;
  } else {
    ApplyCorrections();
    TrackOutcome outcome = TrackFrame(features, &stats);
    const TrackingQuality quality = tracker_->QualityOf(outcome);
    stats.matches = static_cast<int>(outcome.matches.size());
    stats.predicted = static_cast<int>(outcome.predicted.size());
    stats.inliers = outcome.inliers;
    stats.rms_px = outcome.rms_px;
    result->quality = quality;
    if (quality == TrackingQuality::kLost) {
      ++lost_frames_;
      lost_ = true;
      velocity_ = Eigen::Isometry3d::Identity();
      stats.status = "lost (" + std::to_string(outcome.inliers) + " inliers); relocalising";
    } else {
      // A relocalisation right after a tracked frame (tracking fell behind in a fast turn)
      // keeps the motion, so the next frame is predicted where the camera is going.
      if (!stats.relocalised || !lost_) {
        velocity_ = outcome.camera_from_map * camera_from_map_.inverse();
      }
      lost_ = false;
      camera_from_map_ = outcome.camera_from_map;
      result->tracked = true;
      stats.status = stats.relocalised ? "relocalised" : TrackingQualityName(quality);
      pending_visible_.insert(pending_visible_.end(), outcome.predicted.begin(),
                              outcome.predicted.end());
      for (const PointMatch& m : outcome.matches) {
        if (m.inlier) pending_found_.push_back(m.point);
      }
      FlushPointCounts(false);
      for (const PointMatch& m : outcome.matches)
        result->keypoint_state[m.keypoint] = m.inlier ? 1 : 2;
      ++frames_since_keyframe_;
      if (NeedKeyFrame(outcome)) {
        new_keyframe = std::make_shared<KeyFrame>();
        new_keyframe->features = features;
        new_keyframe->frame_index = frame.stamp.sequence_id;
        new_keyframe->time_s = frame.stamp.sensor_time_s;
        new_keyframe->camera_from_map = camera_from_map_;
        new_keyframe->corrections_seen = static_cast<int>(corrections_applied_);
        new_keyframe->point_ids.assign(features.size(), -1);
        for (const PointMatch& m : outcome.matches) {
          if (m.inlier) new_keyframe->point_ids[m.keypoint] = m.point;
        }
        frames_since_keyframe_ = 0;
        keyframe_inliers_ = outcome.inliers;
        stats.new_keyframe = true;
      }
      RefreshLocalPoints(outcome.mean_depth);
    }
  }
  stats.tracking_ms = (HostTimeS() - start) * 1000.0;
  if (timing_) {
    timing_->Add("tracking", stats.tracking_ms);
    timing_->Add("tracking_cpu", ThreadCpuMs() - start_cpu);
  }
  if (new_keyframe) {
    HandOver(std::move(new_keyframe));
  } else if (result->tracked && !mapping_paused_ && frames_since_keyframe_ > 0 &&
             frames_since_keyframe_ % options_.mapping.idle_ba_every_frames == 0) {
    // Frames without a keyframe are the mapper's idle time: one slice, inline or on the
    // mapping thread when it has nothing queued (only this thread pushes, so this never blocks).
    if (!options_.mapping.threaded) {
      RunIdleSlice();
    } else if (keyframe_queue_ && !mapping_busy_ && keyframe_queue_->size() == 0) {
      keyframe_queue_->Push(nullptr);
    }
  }
  if (initialised_) ApplyCorrections();  // A revisit found with this keyframe moves it too.
  result->map_from_camera = camera_from_map_.inverse();
  result->map = Snapshot();
  stats.map_points = static_cast<int>(result->map->points.size());
  stats.keyframes = static_cast<int>(result->map->keyframes.size());
  return std::shared_ptr<const MonoSlamResult>(std::move(result));
}

}  // namespace sightline
