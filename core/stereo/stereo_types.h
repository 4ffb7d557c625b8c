// The data stereo visual odometry produces per frame: features with their roles, the frame's
// statistics and the shared immutable result. Free of the estimator, so views may include it.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/frame.h"

namespace sightline {

// How a feature took part in the frame's motion estimate.
enum class FeatureRole {
  kInlier,   // Tracked from the previous frame and consistent with the motion.
  kOutlier,  // Tracked, but rejected by RANSAC / reprojection.
  kNew,      // Detected in this frame (no motion information yet).
};

// One feature of the current frame, in rectified pixel coordinates.
struct TrackedFeature {
  int64_t id = -1;            // Stable across frames while tracked.
  cv::Point2f left;           // Left image position [px].
  cv::Point2f right;          // Right image position (same row) [px].
  cv::Point2f previous_left;  // Left position in the previous frame; == left for new features.
  int age = 0;                // Frames tracked (0 = new).
  FeatureRole role = FeatureRole::kNew;
};

// Statistics of one frame (also written as a row of frames.csv).
struct FrameStats {
  int tracked = 0;                 // Features tracked from the previous left image.
  bool retracked = false;          // Lost tracks were tracked again with more pyramid levels.
  bool turn_searched = false;      // Tracks were started from the image's global shift instead
                                   // (stereo.tracking.turn_search_fraction).
  int anchored = 0;                // Tracked positions refined against their anchors.
  int new_features = 0;            // Detected this frame (and matched in the right image).
  int stereo_matches = 0;          // Features matched in the right image (tracked + new).
  int correspondences = 0;         // Features with stereo at both times (RANSAC input).
  int inliers = 0;                 // After refinement.
  int ransac_iterations = 0;       // Rigid samples tried.
  int rigidity_failures = 0;       // Samples rejected by the rigidity test.
  double residual_px = 0;          // Refined RMS reprojection error over the inliers [px].
  int window_points = 0;           // Points of the sliding-window bundle adjustment.
  double window_rms_px = 0;        // Its RMS reprojection error after adjustment [px].
  double disparity_offset_px = 0;  // Disparity offset applied to this frame's matches [px].
  double translation_m = 0;        // Length of the applied motion [m].
  double rotation_deg = 0;         // Angle of the applied motion [deg].
  bool gated = false;              // The estimate was rejected (or failed) and a fallback applied.
  std::string status = "ok";       // "ok", "first frame", or why the estimate was rejected.
  // Per-stage wall time [ms].
  double rectify_ms = 0, pyramid_ms = 0, tracking_ms = 0, matching_ms = 0, detection_ms = 0,
         ransac_ms = 0, refine_ms = 0, window_ms = 0, total_ms = 0;
};

// The result of one frame, shared immutable with views.
struct StereoOdometryResult {
  FrameStamp stamp;
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();      // Left camera pose.
  Eigen::Isometry3d current_from_previous = Eigen::Isometry3d::Identity();  // Applied motion.
  FrameStats stats;
  std::vector<TrackedFeature> features;  // After this frame's replenishment.
  cv::Mat left_rectified;                // CV_8UC1, what the feature positions refer to.
  cv::Mat right_rectified;               // CV_8UC1.
};

}  // namespace sightline
