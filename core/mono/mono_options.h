// Every option of the monocular SLAM, keys "mono.<stage>.*". Defaults suit 640x480 at 30 Hz
// and KITTI at 10 Hz alike.
#pragma once

#include <string>

#include "core/mono/scale_estimator.h"
#include "core/options/option_table.h"

namespace sightline {

// ORB features per frame. Keys "mono.features.*".
struct MonoFeatureOptions {
  int max_features = 1500;    // Keypoints per frame.
  double scale_factor = 1.2;  // Pyramid scale between levels.
  int levels = 8;             // Pyramid levels.
  int fast_threshold = 12;    // FAST corner threshold [grey levels].
  int grid_cell_px = 32;      // Cell of the keypoint grid used for window searches [px].

  bool IsValid(std::string* error) const;
  static OptionTable<MonoFeatureOptions> Describe();
};

// Two-view initialisation. Keys "mono.init.*".
struct MonoInitOptions {
  int min_matches = 100;                 // Matches with the first frame needed to try [matches].
  double min_median_parallax_deg = 1.0;  // Median ray angle needed before trying [deg].
  double min_baseline_ratio = 0.07;      // Baseline / median depth of the first points needed.
  double ransac_threshold_px = 1.5;      // RANSAC inlier distance of E and H [px].
  double homography_ratio = 0.40;  // H is chosen when inliers_H / (inliers_H + inliers_E) > this.
  double min_point_parallax_deg = 0.5;  // A triangulated point needs this ray angle [deg].
  double max_reprojection_px = 2.0;     // ... and this reprojection error in both views [px].
  int min_points = 60;                  // Triangulated points needed to accept [points].
  double baseline = 0.1;                // Length of the first baseline in map units (PTAM).
  int max_frames = 60;                  // Frames to try against one first frame before restarting.
  // Sparse, large-motion input (keyframe-rate sequences):
  int reference_frames = 4;         // Ring of candidate first frames tried, oldest first.
  int new_reference_matches = 100;  // A frame matching the newest candidate less joins the ring.
  int min_seed_matches = 20;  // Fewer matches than min_matches but this many: guided matching.
  double guided_epipolar_px = 2.0;  // Guided matching: distance from the epipolar line [px].
  double guided_ratio = 0.9;        // Guided matching: best / second-best descriptor distance.

  bool IsValid(std::string* error) const;
  static OptionTable<MonoInitOptions> Describe();
};

// Tracking. Keys "mono.tracking.*".
struct MonoTrackingOptions {
  double search_radius_px = 20;      // Window around predicted positions [px] ...
  double wide_radius_px = 60;        // ... widened to this when too few are found [px].
  double fine_radius_px = 5;         // Window of the second pass after the first pose [px].
  int max_descriptor_distance = 80;  // Hamming distance of an ORB match [bits].
  double match_ratio = 0.9;          // Best / second-best distance in a window.
  double huber_px = 2.5;             // M-estimator (Huber) threshold of pose refinement [px].
  double outlier_px = 4.0;           // Residual that makes a match an outlier [px].
  int good_inliers = 60;             // Quality good from this many inliers.
  int min_inliers = 20;              // Quality poor from this many; fewer = lost.
  double min_found_fraction = 0.1;   // Lost when fewer of the predicted points are found.
  int reloc_min_matches = 15;        // Descriptor matches with a keyframe to try PnP.
  int reloc_min_inliers = 30;        // Inliers to accept a relocalisation.
  // Low frame rates (frames at least low_rate_interval_s apart; the keyframe rules in
  // mono.mapping.urgent_* too): when the constant-velocity prediction tracks fewer than
  // fallback_inliers, the last pose is tried too (zero motion) with the unsure window, and the
  // better one kept.
  double low_rate_interval_s = 0.2;  // Steps this long (the frame's or the recent median) [s].
  int fallback_inliers = 60;         // Below this many inliers the zero-motion pose is tried.
  double unsure_radius_px = 120;     // Coarse window of the zero-motion try [px].

  bool IsValid(std::string* error) const;
  static OptionTable<MonoTrackingOptions> Describe();
};

// Keyframes and mapping. Keys "mono.mapping.*".
struct MonoMappingOptions {
  int min_keyframe_gap = 3;  // Frames between keyframes at least ...
  // Low frame rates (mono.tracking.low_rate_interval_s) do not wait for the gap when tracking
  double urgent_keyframe_ratio = 0.5;     // ... fewer than this x the last keyframe's points
  double urgent_keyframe_distance = 0.1;  // ... or this far (x mean depth) from every keyframe.
  double keyframe_distance = 0.04;        // New keyframe when this far (x mean depth) from all ...
  double keyframe_match_ratio =
      0.7;                           // ... or when tracking fewer than this x the last KF's points.
  int neighbours = 3;                // Keyframes to triangulate new points with.
  double epipolar_px = 2.0;          // Epipolar distance of a new-point match [px].
  int max_descriptor_distance = 60;  // Hamming distance of a new-point match [bits].
  double min_parallax_deg = 1.0;     // A new point needs this ray angle [deg].
  double max_reprojection_px = 2.5;  // ... and this reprojection error [px].
  int local_window = 6;              // Keyframes optimised by local bundle adjustment.
  int ba_iterations = 15;            // Ceres iterations per local bundle adjustment.
  double ba_huber_px = 2.5;          // Huber loss of bundle adjustment [px].
  double min_found_ratio =
      0.25;               // Points found in fewer of the frames that should see them are culled.
  bool threaded = false;  // Mapping on its own thread, or inline (deterministic; default).
  int thread_nice = 0;    // Threaded mode: the mapping thread's niceness (Linux).
  int final_ba_iterations = 30;  // Global bundle adjustment when the run stops (0 = none).
  // Bounded map (revisits) and bundle adjustment in idle time (PTAM):
  double local_map_distance = 1.0;  // Linked old keyframes this close (x mean depth) are tracked.
  int loop_min_age = 40;            // Keyframes at least this much older are searched ...
  double loop_search_radius = 2.0;  // ... within this distance (x mean depth) for a revisit.
  int loop_min_inliers = 80;        // Inliers against the old map that confirm a revisit.
  int idle_ba_window = 20;          // Keyframes optimised by one idle-time adjustment slice.
  int idle_ba_iterations = 5;       // Iterations of one slice (0 = no idle-time adjustment).
  int idle_ba_every_frames = 10;    // Synchronous mode: frames without a keyframe between slices.
  int final_ba_max_keyframes = 80;  // Larger maps get bounded slices at stop, not a full one ...
  int final_ba_max_slices = 3;      // ... at most this many.

  bool IsValid(std::string* error) const;
  static OptionTable<MonoMappingOptions> Describe();
};

// The whole SLAM. Keys "mono.*".
struct MonoSlamOptions {
  MonoFeatureOptions features;
  MonoInitOptions init;
  MonoTrackingOptions tracking;
  MonoMappingOptions mapping;
  ScaleEstimatorOptions scale;

  bool IsValid(std::string* error) const;
  static OptionTable<MonoSlamOptions> Describe();
};

}  // namespace sightline
