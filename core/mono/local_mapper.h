// The mapping side (PTAM's mapper): inserts keyframes, triangulates new points with recent
// keyframes along epipolar lines, adds observations of existing points, runs local bundle
// adjustment and culls bad points.
//
// Locking: only the mapper changes the map's structure and poses, so it reads the map without
// the lock and takes it for every write; the tracker reads the copies MonoSlam publishes after
// each keyframe and takes the lock only to count points seen (try-lock) and to relocalise.
#pragma once

#include <functional>
#include <memory>
#include <mutex>

#include "core/common/camera.h"
#include "core/common/timing.h"
#include "core/mono/bundle_adjustment.h"
#include "core/mono/mono_options.h"
#include "core/mono/slam_map.h"

namespace sightline {

// What processing one keyframe did.
struct KeyFrameStats {
  int64_t keyframe = -1;
  int new_points = 0;       // Triangulated.
  int fused = 0;            // Observations of existing points added.
  int culled = 0;           // Points removed.
  int ba_outliers = 0;      // Observations removed after bundle adjustment.
  int64_t revisit_of = -1;  // The old keyframe a revisit matched it with, or -1.
  int merged = 0;           // Its points merged with old points (revisit).
  BundleSummary bundle;
  double mapping_ms = 0;  // Everything.
  double bundle_ms = 0;   // Bundle adjustment alone.
};

// What one idle-time adjustment slice did.
struct IdleBundleStats {
  int keyframes = 0;     // Poses optimised (0: nothing to do).
  int points = 0;        // Points optimised.
  int removed = 0;       // Observations removed as outliers afterwards.
  BundleSummary bundle;  // Iterations and reprojection RMS before / after.
};

class LocalMapper {
 public:
  LocalMapper(const MonoMappingOptions& options, const PinholeCamera& camera, double scale_factor,
              SlamMap* map, std::mutex* map_mutex);

  // Adds `keyframe` (its point_ids say which points tracking matched) and maps with it.
  KeyFrameStats ProcessKeyFrame(const std::shared_ptr<KeyFrame>& keyframe);

  // Bundle adjustment of every keyframe and point with the first keyframe fixed (used after
  // initialisation), then rescaled so the first two keyframes are `baseline` apart.
  BundleSummary GlobalBundle(double baseline);

  // Bundle adjustment of every keyframe and point with the first keyframe fixed (PTAM's global
  // adjustment, run when the run stops on a small map), rescaled so the keyframes' path length
  // is unchanged: the map keeps its units and the tracked poses stay comparable. The summary's
  // iterations are those of both rounds.
  BundleSummary FinalBundle(int iterations);

  // One slice of PTAM's global adjustment for idle time: the poses of idle_ba_window
  // consecutive keyframes (taken in turn over the map) and every point they see, the other
  // keyframes that see those points fixed; `iterations` bound the work. Slices are only run
  // while the map changed since a whole pass (idle_slices_left() > 0).
  // `should_stop` (optional) ends the slice after the current iteration (a keyframe waits).
  IdleBundleStats IdleBundle(int iterations, const std::function<bool()>& should_stop = {});
  // Slices still to run for one pass over the map since it last changed.
  int idle_slices_left() const { return idle_slices_left_; }
  // The map changed (a keyframe or a revisit): one more pass over it is due.
  void MapChanged();

 private:
  int TriangulateWith(KeyFrame* current, const KeyFrame& neighbour);
  int FuseNeighbourPoints(KeyFrame* current, const std::vector<KeyFrame*>& neighbours);
  // Local BA over the window; returns the observations removed as outliers.
  int LocalBundle(KeyFrameStats* stats);
  // Bundle adjustment of keyframes [first_free, end) and every point they see, written back.
  IdleBundleStats AdjustWindow(int first_free, int end, int iterations,
                               const std::function<bool()>& should_stop = {});
  int Cull(int64_t current_keyframe);
  // Global bundle adjustment written back to the map, rescaled so the first two keyframes are
  // `baseline` apart or, with keep_path_length, so the keyframes' path length is unchanged.
  BundleSummary SolveGlobal(int iterations, double baseline, bool keep_path_length);

  MonoMappingOptions options_;
  int idle_cursor_ = 0;       // First keyframe of the next idle slice.
  int idle_slices_left_ = 0;  // Slices left in the current pass.
  PinholeCamera camera_;
  double scale_factor_;
  SlamMap* map_;
  std::mutex* mutex_;
};

}  // namespace sightline
