// Tracking of one frame against the map (PTAM's tracker): map points projected at the predicted
// pose, matched by ORB descriptor inside a window, a robust pose (pose_optimizer.h) in a coarse
// and a fine pass; relocalisation against keyframes by descriptor matching and PnP RANSAC.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "core/common/camera.h"
#include "core/mono/mono_options.h"
#include "core/mono/mono_types.h"
#include "core/mono/slam_map.h"

namespace sightline {

// A map point as the tracker sees it: a copy taken under the map lock.
struct LocalPoint {
  int64_t id = -1;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  cv::Mat descriptor;
};

// One keypoint of the frame matched with a map point.
struct PointMatch {
  int keypoint = -1;
  int64_t point = -1;
  bool inlier = false;
};

// The outcome of tracking one frame.
struct TrackOutcome {
  Eigen::Isometry3d camera_from_map = Eigen::Isometry3d::Identity();
  std::vector<PointMatch> matches;  // After the fine pass.
  std::vector<int64_t> predicted;   // Points predicted inside the image (PTAM's "visible").
  int inliers = 0;
  double rms_px = 0;
  double mean_depth = 0;  // Of the inliers, in map units.
};

// The tracker's computations; stateless apart from options and the camera.
class Tracker {
 public:
  Tracker(const MonoTrackingOptions& options, const PinholeCamera& camera, double scale_factor);

  // Tracks `features` against `points` from the predicted pose; the coarse pass searches
  // `coarse_radius_px` (0 = search_radius_px, widened to wide_radius_px when too few are found).
  TrackOutcome Track(const FrameFeatures& features, const std::vector<LocalPoint>& points,
                     const Eigen::Isometry3d& predicted_camera_from_map,
                     double coarse_radius_px = 0) const;

  // Relocalises against one keyframe and the points it observes (descriptor matches, PnP RANSAC,
  // then Track from that pose). Returns false when too few matches or inliers.
  bool Relocalise(const FrameFeatures& features, const KeyFrame& keyframe,
                  const std::vector<LocalPoint>& keyframe_points,
                  const std::vector<LocalPoint>& local_points, TrackOutcome* outcome) const;

  // Good, poor or lost from the inliers and the share of predicted points found.
  TrackingQuality QualityOf(const TrackOutcome& outcome) const;

 private:
  // Matches projected points within `radius` (scaled by the keypoint's level).
  std::vector<PointMatch> SearchByProjection(const FrameFeatures& features,
                                             const std::vector<LocalPoint>& points,
                                             const Eigen::Isometry3d& camera_from_map,
                                             double radius, std::vector<int64_t>* predicted) const;
  // Optimises the pose over `matches` and marks their inliers.
  double Optimise(const FrameFeatures& features, const std::vector<LocalPoint>& points,
                  std::vector<PointMatch>* matches, Eigen::Isometry3d* camera_from_map,
                  int* inliers) const;

  MonoTrackingOptions options_;
  PinholeCamera camera_;
  double scale_factor_;
};

}  // namespace sightline
