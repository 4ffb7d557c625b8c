#include "core/mono/mono_slam.h"

#include <cmath>
#include <ctime>
#include <set>

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
  mapper_->FinalBundle(options_.mapping.final_ba_iterations);
  if (timing_) timing_->Add("final_bundle_adjustment", (HostTimeS() - start) * 1000.0);
  PublishSnapshot();
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
  while (std::optional<std::shared_ptr<KeyFrame>> keyframe = keyframe_queue_->Pop()) {
    MapKeyFrame(std::move(*keyframe));
    mapping_busy_ = false;
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
  }
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
  {
    std::lock_guard<std::mutex> lock(map_mutex_);
    snapshot = SnapshotOf(map_);
    local = std::make_shared<const std::vector<LocalPoint>>(LocalPointsOf());
  }
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  snapshot_ = std::move(snapshot);
  local_points_ = std::move(local);
}

std::shared_ptr<const std::vector<LocalPoint>> MonoSlam::LocalPoints() const {
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return local_points_;
}

std::vector<LocalPoint> MonoSlam::LocalPointsOf() const {
  // The points seen by the most recent keyframes (PTAM projects the whole map; recent
  // keyframes' points are what the camera can see and keep tracking cost bounded).
  constexpr int kLocalKeyFrames = 12;
  std::set<int64_t> ids;
  const auto& keyframes = map_.keyframes();
  for (int k = static_cast<int>(keyframes.size()) - 1;
       k >= 0 && k >= static_cast<int>(keyframes.size()) - kLocalKeyFrames; --k) {
    for (int64_t id : keyframes[k]->point_ids) {
      if (id >= 0) ids.insert(id);
    }
  }
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
  std::vector<std::shared_ptr<KeyFrame>> keyframes;
  {
    std::lock_guard<std::mutex> lock(map_mutex_);
    keyframes = map_.keyframes();
  }
  const std::shared_ptr<const std::vector<LocalPoint>> all = LocalPoints();
  for (auto it = keyframes.rbegin(); it != keyframes.rend(); ++it) {
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
  KeyFrameStats stats = mapper_->ProcessKeyFrame(std::move(keyframe));
  if (timing_) {
    timing_->Add("mapping", stats.mapping_ms);
    timing_->Add("bundle_adjustment", stats.bundle_ms);
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
    low_rate_ = frame.stamp.sensor_time_s - last_time_s_ >= options_.tracking.low_rate_interval_s;
  }
  last_time_s_ = frame.stamp.sensor_time_s;
  if (!initialised_) {
    result->tracked = TryInitialise(features, frame.stamp, &stats);
    result->quality = result->tracked ? TrackingQuality::kGood : TrackingQuality::kInitialising;
  } else {
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
      lost_ = false;
      if (!stats.relocalised) velocity_ = outcome.camera_from_map * camera_from_map_.inverse();
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
        new_keyframe->point_ids.assign(features.size(), -1);
        for (const PointMatch& m : outcome.matches) {
          if (m.inlier) new_keyframe->point_ids[m.keypoint] = m.point;
        }
        frames_since_keyframe_ = 0;
        keyframe_inliers_ = outcome.inliers;
        stats.new_keyframe = true;
      }
    }
  }
  stats.tracking_ms = (HostTimeS() - start) * 1000.0;
  if (timing_) {
    timing_->Add("tracking", stats.tracking_ms);
    timing_->Add("tracking_cpu", ThreadCpuMs() - start_cpu);
  }
  if (new_keyframe) HandOver(std::move(new_keyframe));
  result->map_from_camera = camera_from_map_.inverse();
  result->map = Snapshot();
  stats.map_points = static_cast<int>(result->map->points.size());
  stats.keyframes = static_cast<int>(result->map->keyframes.size());
  return std::shared_ptr<const MonoSlamResult>(std::move(result));
}

}  // namespace sightline
