// The mapping side (PTAM's mapper): inserts keyframes, triangulates new points with recent
// keyframes along epipolar lines, adds observations of existing points, runs local bundle
// adjustment and culls bad points.
//
// Locking: only the mapper changes the map's structure and poses, so it reads the map without
// the lock and takes it for every write; the tracker reads the copies MonoSlam publishes after
// each keyframe and takes the lock only to count points seen (try-lock) and to relocalise.
#pragma once

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
  int new_points = 0;   // Triangulated.
  int fused = 0;        // Observations of existing points added.
  int culled = 0;       // Points removed.
  int ba_outliers = 0;  // Observations removed after bundle adjustment.
  BundleSummary bundle;
  double mapping_ms = 0;  // Everything.
  double bundle_ms = 0;   // Bundle adjustment alone.
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
  // adjustment, run when the run stops), rescaled so the keyframes' path length is unchanged:
  // the map keeps its units and the tracked poses stay comparable.
  BundleSummary FinalBundle(int iterations);

 private:
  int TriangulateWith(KeyFrame* current, const KeyFrame& neighbour);
  int FuseNeighbourPoints(KeyFrame* current, const std::vector<KeyFrame*>& neighbours);
  // Local BA over the window; returns the observations removed as outliers.
  int LocalBundle(KeyFrameStats* stats);
  int Cull(int64_t current_keyframe);
  // Global bundle adjustment written back to the map, rescaled so the first two keyframes are
  // `baseline` apart or, with keep_path_length, so the keyframes' path length is unchanged.
  BundleSummary SolveGlobal(int iterations, double baseline, bool keep_path_length);

  MonoMappingOptions options_;
  PinholeCamera camera_;
  double scale_factor_;
  SlamMap* map_;
  std::mutex* mutex_;
};

}  // namespace sightline
