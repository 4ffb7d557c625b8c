// Monocular SLAM in the manner of PTAM (seed 004): two-view initialisation while the camera
// moves sideways, tracking every frame against the map, keyframes handed to a mapper that
// triangulates new points and runs local bundle adjustment, relocalisation when lost. The map
// starts in arbitrary units (first baseline = mono.init.baseline); metric scale comes from
// measured motion (scale_estimator.h, metric_motion.h).
//
// Two modes: synchronous (mono.mapping.threaded = false; mapping runs inline after each new
// keyframe, deterministic; the default of every front end) and threaded (mapping on its own
// thread, fed through a bounded queue; mono.mapping.threaded). Both stop cleanly.
//
// Bounded map (PTAM's and ORB-SLAM's habits): a new keyframe that comes back to mapped space
// after a long way round is matched against the old keyframes there (loop_closer.h); the map
// since then is bent onto the old one, and tracking continues on the old points, so a revisit
// adds almost no keyframes. Idle time (the mapping thread with no keyframe waiting, or frames
// without a keyframe in synchronous mode) runs the global adjustment in bounded slices.
#pragma once

#include <Eigen/Geometry>
#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <string>
#include <thread>
#include <vector>

#include "core/common/bounded_queue.h"
#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/common/timing.h"
#include "core/mono/features.h"
#include "core/mono/local_mapper.h"
#include "core/mono/loop_closer.h"
#include "core/mono/mono_options.h"
#include "core/mono/mono_types.h"
#include "core/mono/slam_map.h"
#include "core/mono/tracker.h"
#include "core/mono/two_view_initializer.h"

namespace sightline {

// Bundle adjustment outside keyframe mapping: in idle time (slices) and when the run stops.
struct IdleBundleTotals {
  int slices = 0;                   // Idle-time slices run.
  int keyframes_adjusted = 0;       // Keyframe poses optimised, summed over slices.
  int iterations = 0;               // Solver iterations, summed.
  double first_initial_rms_px = 0;  // Reprojection RMS before the first slice ...
  double last_final_rms_px = 0;     // ... and after the latest.
  // Stop():
  bool stop_full = false;           // The full global adjustment ran (small map).
  int stop_slices = 0;              // Or this many slices.
  int stop_keyframes_adjusted = 0;  // Keyframe poses optimised at stop (each slice or round).
  int stop_iterations = 0;          // Solver iterations at stop.
  double stop_longest_step_ms = 0;  // Longest single step at stop (a slice or the full one).
};

// The SLAM system.
//
//   MonoSlam slam(options);
//   SIGHTLINE_RETURN_IF_ERROR(slam.Configure(*source.info().camera, &timing));
//   while (...) {
//     auto r = slam.Process(mono_frame);
//     if (!r.ok()) return r.status();
//     if ((*r)->tracked) trajectory.Add((*r)->stamp.sensor_time_s, (*r)->map_from_camera);
//   }
//   slam.Stop();  // Finishes queued mapping work (threaded mode).
class MonoSlam {
 public:
  explicit MonoSlam(MonoSlamOptions options = {});
  ~MonoSlam();
  MonoSlam(const MonoSlam&) = delete;
  MonoSlam& operator=(const MonoSlam&) = delete;

  // Checks options and camera. `timing` (optional, must outlive this object) receives
  // "features" and "tracking" (features included) per frame, "mapping" and
  // "bundle_adjustment" per keyframe.
  Status Configure(const PinholeCamera& camera, TimingStats* timing = nullptr);

  // Processes the next frame. Errors only when not configured or the image is empty of pixels
  // of the wrong size; bad images (black, textureless, a jump) are reported in the result.
  StatusOr<std::shared_ptr<const MonoSlamResult>> Process(const MonoFrame& frame);

  // Forgets the map and starts initialising again.
  void Reset();
  // Paused mapping adds no keyframes; tracking continues on the map as it is.
  void SetMappingPaused(bool paused) { mapping_paused_ = paused; }
  // Waits for queued mapping work and stops the mapping thread (threaded mode), then runs the
  // global bundle adjustment of mono.mapping.final_ba_iterations once per map: in full on a
  // small map (final_ba_max_keyframes), else at most final_ba_max_slices slices of what the
  // idle-time adjustment has left, so stopping is bounded. Idempotent.
  void Stop();

  std::shared_ptr<const MapSnapshot> Snapshot() const;
  std::vector<KeyFrameStats> KeyFrameHistory() const;
  bool initialised() const { return initialised_; }
  int lost_frames() const { return lost_frames_; }
  int relocalisations() const { return relocalisations_; }
  const std::string& init_model() const { return init_model_; }
  const MonoSlamOptions& options() const { return options_; }
  // Revisits of mapped space found and applied (loop corrections).
  int revisits() const;
  // What the idle-time and stop-time adjustments did (read after Stop() in threaded mode).
  IdleBundleTotals idle_bundle() const;

 private:
  bool TryInitialise(const FrameFeatures& features, const FrameStamp& stamp, MonoFrameStats* stats);
  // The points seen by the most recent keyframes and, once linked to them, by old keyframes
  // near the camera (call with the map lock held); `keyframe_ids` receives the keyframes.
  std::vector<LocalPoint> LocalPointsOf(const Eigen::Isometry3d& camera_from_map, double radius,
                                        std::vector<int64_t>* keyframe_ids) const;
  // Rebuilds the published local map around the camera when it moved away from where the
  // last one was built (skipped in threaded mode while mapping holds the map).
  void RefreshLocalPoints(double mean_depth);
  // Applies revisit corrections the mapper made since the last call to the tracked pose.
  void ApplyCorrections();
  // One idle-time adjustment slice and the snapshot it changed.
  void RunIdleSlice();
  std::shared_ptr<const std::vector<LocalPoint>> LocalPoints() const;  // The published copy.
  void StopThread();
  // Applies the visible / found counts of tracked frames if the map lock is free (it always is
  // in synchronous mode); otherwise they wait for the next frame.
  void FlushPointCounts(bool wait);
  bool TryRelocalise(const FrameFeatures& features, TrackOutcome* outcome);
  // Tracks from the constant-velocity prediction and, when that finds few inliers, from the
  // last pose with a wide window (low frame rates); then relocalises when lost.
  TrackOutcome TrackFrame(const FrameFeatures& features, MonoFrameStats* stats);
  bool NeedKeyFrame(const TrackOutcome& outcome) const;
  void HandOver(std::shared_ptr<KeyFrame> keyframe);
  void MapKeyFrame(std::shared_ptr<KeyFrame> keyframe);
  void MappingLoop();
  void StartMappingThread();
  void PublishSnapshot();

  MonoSlamOptions options_;
  PinholeCamera camera_;
  bool configured_ = false;
  TimingStats* timing_ = nullptr;
  std::unique_ptr<FeatureExtractor> extractor_;
  std::unique_ptr<TwoViewInitializer> initializer_;
  std::unique_ptr<Tracker> tracker_;

  mutable std::mutex map_mutex_;  // Guards map_ (see local_mapper.h for who locks when).
  SlamMap map_;
  std::unique_ptr<LocalMapper> mapper_;
  std::unique_ptr<LoopCloser> loop_closer_;

  // Threaded mode.
  std::unique_ptr<BoundedQueue<std::shared_ptr<KeyFrame>>> keyframe_queue_;
  std::thread mapping_thread_;
  std::atomic<bool> mapping_busy_{false};
  std::atomic<bool> mapping_paused_{false};

  // Guards snapshot_, local_points_ and keyframe_history_. The mapper publishes them after
  // each keyframe, so the tracker never waits for the map lock while bundle adjustment runs.
  mutable std::mutex snapshot_mutex_;
  std::shared_ptr<const MapSnapshot> snapshot_;
  std::shared_ptr<const std::vector<LocalPoint>> local_points_;
  std::vector<KeyFrameStats> keyframe_history_;
  std::vector<MapCorrection> corrections_;  // Revisit corrections, in order.
  std::vector<int64_t> local_keyframes_;    // Keyframes of local_points_, most relevant first.
  IdleBundleTotals idle_totals_;
  // The camera and radius the local map is built around, and where the published one was.
  Eigen::Isometry3d local_camera_ = Eigen::Isometry3d::Identity();
  double local_radius_ = 0;
  Eigen::Vector3d local_built_at_ = Eigen::Vector3d::Zero();

  // Tracking state (tracking thread only).
  bool initialised_ = false;
  bool final_bundle_done_ = false;
  std::vector<int64_t> pending_visible_,
      pending_found_;  // Point ids to count (see FlushPointCounts).
  std::string init_model_;
  FrameStamp first_stamp_;
  int64_t frames_processed_ = 0;  // Frames given to Process since Reset (for the velocity).
  double last_time_s_ = 0;        // The previous frame's sensor time.
  bool low_rate_ = false;  // This frame, or the median of recent ones, low_rate_interval_s or
                           // more after the last.
  static constexpr size_t kRecentSteps = 5;
  std::deque<double> recent_steps_s_;  // Sensor-time steps between the last frames [s].
  Eigen::Isometry3d camera_from_map_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d velocity_ = Eigen::Isometry3d::Identity();  // current_from_previous.
  bool lost_ = false;
  int frames_since_keyframe_ = 0;
  int keyframe_inliers_ = 0;
  int lost_frames_ = 0;
  int relocalisations_ = 0;
  size_t corrections_applied_ = 0;  // Of corrections_, applied to camera_from_map_.
};

}  // namespace sightline
