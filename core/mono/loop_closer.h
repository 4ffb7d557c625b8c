// Revisits of mapped space (a loop): a new keyframe is matched against old keyframes near it,
// and when the old map confirms its pose, the map built since then is bent onto the old one (a
// similarity spread along the keyframe path, as a crude pose graph) and the new keyframe's
// points are merged with the old points they match. Afterwards tracking continues on the old
// points instead of mapping the same place again.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "core/common/camera.h"
#include "core/mono/mono_options.h"
#include "core/mono/slam_map.h"
#include "core/mono/tracker.h"

namespace sightline {

// A similarity x' = scale * rotation * x + translation, from the drifted map to the old map.
struct MapCorrection {
  double scale = 1;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d Apply(const Eigen::Vector3d& x) const {
    return scale * rotation * x + translation;
  }
  // The same camera in corrected map coordinates (its units scaled by `scale`).
  Eigen::Isometry3d CorrectPose(const Eigen::Isometry3d& camera_from_map) const;
  // Part `fraction` (0 = none, 1 = all) of this correction, exact at `centre`'s share.
  MapCorrection Partial(double fraction, const Eigen::Vector3d& centre) const;
};

// A confirmed revisit.
struct LoopMatch {
  int64_t keyframe = -1;  // The new keyframe.
  int64_t partner = -1;   // The old keyframe it was matched against.
  int inliers = 0;        // Old map points tracked in the new keyframe.
  MapCorrection correction;
  std::vector<std::pair<int, int64_t>> matches;  // New keyframe's keypoint -> old point.
};

class LoopCloser {
 public:
  LoopCloser(const MonoMappingOptions& mapping, const MonoTrackingOptions& tracking,
             const PinholeCamera& camera, double scale_factor);

  // Looks for a revisit of `keyframe` (already in `map`; call from the mapper, which may read
  // the map without its lock). None when the keyframe already tracks old points.
  std::optional<LoopMatch> Detect(const SlamMap& map, const KeyFrame& keyframe) const;

  // Bends the keyframes after the partner onto the old map and merges the matched points
  // (call with the map lock held). Returns the points merged.
  int Apply(const LoopMatch& loop, SlamMap* map) const;

 private:
  MonoMappingOptions options_;
  Tracker tracker_;
};

}  // namespace sightline
