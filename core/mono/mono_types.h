// The monocular SLAM's data for views and writers: a frame's tracking quality, statistics and
// result, and a row of the scale estimate's history. No estimator classes: the GUI may include
// this header.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/frame.h"
#include "core/mono/slam_map.h"

namespace sightline {

// How well the current frame is tracked.
enum class TrackingQuality { kInitialising, kGood, kPoor, kLost };
const char* TrackingQualityName(TrackingQuality quality);  // "initialising", "good", ...

// Statistics of one frame.
struct MonoFrameStats {
  int keypoints = 0;   // ORB keypoints extracted.
  int predicted = 0;   // Map points predicted inside the image (fine pass).
  int matches = 0;     // Map points matched (fine pass).
  int inliers = 0;     // After robust pose optimisation.
  double rms_px = 0;   // Inlier reprojection RMS (level-scaled) [px].
  int map_points = 0;  // In the map after this frame.
  int keyframes = 0;   // In the map after this frame.
  bool new_keyframe = false;
  bool relocalised = false;
  std::string status;      // What happened, for people ("initialised (homography, 212 points)").
  double tracking_ms = 0;  // Features + tracking (+ relocalisation) of this frame.
};

// The result of one frame, shared immutable with views.
struct MonoSlamResult {
  FrameStamp stamp;
  TrackingQuality quality = TrackingQuality::kInitialising;
  bool tracked = false;  // The pose below is valid for this frame.
  Eigen::Isometry3d map_from_camera = Eigen::Isometry3d::Identity();  // Map units.
  MonoFrameStats stats;
  std::vector<cv::Point2f> keypoints;      // Every keypoint (image pixels).
  std::vector<uint8_t> keypoint_state;     // 0 unmatched, 1 inlier, 2 outlier.
  std::shared_ptr<const MapSnapshot> map;  // The latest map (shared until it changes).
  cv::Mat image;                           // The frame as given.
};

// The scale estimate after one added displacement pair (a row of scale.csv).
struct ScaleSample {
  int index = 0;              // Pairs offered so far (1-based).
  double pair_ratio = 0;      // |x| / |y| of this pair alone (0 when dropped as too short).
  double single_ratio = 0;    // The single-ratio estimate (first accepted pair), 0 = none yet.
  double max_likelihood = 0;  // ML estimate over the accepted pairs, 0 = none yet.
  int pairs_used = 0;         // Pairs inside the ML estimate after outlier rejection.
};

}  // namespace sightline
