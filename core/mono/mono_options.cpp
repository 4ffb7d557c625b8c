#include "core/mono/mono_options.h"

#include "core/mono/option_check.h"

namespace sightline {

using mono_internal::Invalid;

bool MonoFeatureOptions::IsValid(std::string* error) const {
  if (max_features < 50) return Invalid(error, "mono.features.max_features must be >= 50");
  if (!(scale_factor > 1 && scale_factor < 2)) {
    return Invalid(error, "mono.features.scale_factor must lie in (1, 2)");
  }
  if (levels < 1 || levels > 12) return Invalid(error, "mono.features.levels must lie in [1, 12]");
  if (fast_threshold < 1) return Invalid(error, "mono.features.fast_threshold must be >= 1");
  if (grid_cell_px < 4) return Invalid(error, "mono.features.grid_cell_px must be >= 4");
  return true;
}

OptionTable<MonoFeatureOptions> MonoFeatureOptions::Describe() {
  using O = MonoFeatureOptions;
  return OptionTable<O>("features")
      .Int("max_features", &O::max_features, "keypoints", 50, 20000, 50,
           "ORB keypoints extracted per frame.")
      .Double("scale_factor", &O::scale_factor, "", 1.05, 1.95, 0.05,
              "Scale between pyramid levels.")
      .Int("levels", &O::levels, "levels", 1, 12, 1, "Pyramid levels.")
      .Int("fast_threshold", &O::fast_threshold, "grey levels", 1, 100, 1, "FAST corner threshold.")
      .Int("grid_cell_px", &O::grid_cell_px, "px", 4, 256, 4,
           "Cell of the keypoint grid used by window searches.");
}

bool MonoInitOptions::IsValid(std::string* error) const {
  if (min_matches < 8) return Invalid(error, "mono.init.min_matches must be >= 8");
  if (!(min_median_parallax_deg >= 0)) {
    return Invalid(error, "mono.init.min_median_parallax_deg must be >= 0");
  }
  if (!(min_baseline_ratio >= 0))
    return Invalid(error, "mono.init.min_baseline_ratio must be >= 0");
  if (!(ransac_threshold_px > 0))
    return Invalid(error, "mono.init.ransac_threshold_px must be > 0");
  if (!(homography_ratio > 0 && homography_ratio < 1)) {
    return Invalid(error, "mono.init.homography_ratio must lie in (0, 1)");
  }
  if (!(min_point_parallax_deg >= 0)) {
    return Invalid(error, "mono.init.min_point_parallax_deg must be >= 0");
  }
  if (!(max_reprojection_px > 0))
    return Invalid(error, "mono.init.max_reprojection_px must be > 0");
  if (min_points < 8) return Invalid(error, "mono.init.min_points must be >= 8");
  if (!(baseline > 0)) return Invalid(error, "mono.init.baseline must be > 0");
  if (max_frames < 1) return Invalid(error, "mono.init.max_frames must be >= 1");
  if (reference_frames < 1 || reference_frames > 16) {
    return Invalid(error, "mono.init.reference_frames must lie in [1, 16]");
  }
  if (new_reference_matches < 0) {
    return Invalid(error, "mono.init.new_reference_matches must be >= 0");
  }
  if (min_seed_matches < 8) return Invalid(error, "mono.init.min_seed_matches must be >= 8");
  if (!(guided_epipolar_px > 0)) return Invalid(error, "mono.init.guided_epipolar_px must be > 0");
  if (!(guided_ratio > 0 && guided_ratio <= 1)) {
    return Invalid(error, "mono.init.guided_ratio must lie in (0, 1]");
  }
  return true;
}

OptionTable<MonoInitOptions> MonoInitOptions::Describe() {
  using O = MonoInitOptions;
  return OptionTable<O>("init")
      .Int("min_matches", &O::min_matches, "matches", 8, 10000, 10,
           "Matches with the first frame needed before initialisation is tried.")
      .Double("min_median_parallax_deg", &O::min_median_parallax_deg, "deg", 0, 30, 0.1,
              "Median angle between the rays of a match needed before trying (move sideways).")
      .Double("min_baseline_ratio", &O::min_baseline_ratio, "", 0, 2, 0.01,
              "Baseline over the median depth of the first points needed to accept (0.07 is a "
              "4 deg ray angle sideways); a short baseline gives a distorted first map and a "
              "drifting scale.")
      .Double("ransac_threshold_px", &O::ransac_threshold_px, "px", 0.1, 20, 0.1,
              "RANSAC inlier distance of the essential matrix and the homography.")
      .Double("homography_ratio", &O::homography_ratio, "", 0.01, 0.99, 0.01,
              "The homography is chosen when its share of the inliers exceeds this.")
      .Double("min_point_parallax_deg", &O::min_point_parallax_deg, "deg", 0, 30, 0.1,
              "Ray angle a first map point needs.")
      .Double("max_reprojection_px", &O::max_reprojection_px, "px", 0.1, 20, 0.1,
              "Reprojection error a first map point may have in either view.")
      .Int("min_points", &O::min_points, "points", 8, 10000, 10,
           "Triangulated points needed to accept the initialisation.")
      .Double("baseline", &O::baseline, "map units", 1e-3, 1000, 0.01,
              "Length of the first baseline in map units (PTAM: 0.1); metric scale comes later.")
      .Int("max_frames", &O::max_frames, "frames", 1, 10000, 1,
           "Frames tried against one first frame before it is replaced.")
      .Int("reference_frames", &O::reference_frames, "frames", 1, 16, 1,
           "Candidate first frames kept (a ring of recent frames); each new frame is tried "
           "against every one, oldest first (the largest baseline).")
      .Int("new_reference_matches", &O::new_reference_matches, "matches", 0, 10000, 10,
           "A frame with fewer matches than this with the newest candidate becomes a candidate "
           "too (the oldest leaves a full ring); at low frame rates every frame does.")
      .Int("min_seed_matches", &O::min_seed_matches, "matches", 8, 10000, 1,
           "With fewer than min_matches but this many matches, an essential matrix from them "
           "guides a second matching along epipolar lines (large motion).")
      .Double("guided_epipolar_px", &O::guided_epipolar_px, "px", 0.1, 50, 0.1,
              "Guided matching: distance from the epipolar line a match may have.")
      .Double("guided_ratio", &O::guided_ratio, "", 0.05, 1, 0.05,
              "Guided matching: best over second-best descriptor distance along the line.");
}

bool MonoTrackingOptions::IsValid(std::string* error) const {
  if (!(search_radius_px > 0) || !(wide_radius_px >= search_radius_px) || !(fine_radius_px > 0)) {
    return Invalid(error,
                   "mono.tracking: radii must be > 0 and wide_radius_px >= search_radius_px");
  }
  if (max_descriptor_distance < 1 || max_descriptor_distance > 256) {
    return Invalid(error, "mono.tracking.max_descriptor_distance must lie in [1, 256]");
  }
  if (!(match_ratio > 0 && match_ratio <= 1)) {
    return Invalid(error, "mono.tracking.match_ratio must lie in (0, 1]");
  }
  if (!(huber_px > 0) || !(outlier_px > 0)) {
    return Invalid(error, "mono.tracking.huber_px and outlier_px must be > 0");
  }
  if (min_inliers < 6 || good_inliers < min_inliers) {
    return Invalid(error,
                   "mono.tracking: min_inliers must be >= 6 and good_inliers >= min_inliers");
  }
  if (!(min_found_fraction >= 0 && min_found_fraction < 1)) {
    return Invalid(error, "mono.tracking.min_found_fraction must lie in [0, 1)");
  }
  if (reloc_min_matches < 6 || reloc_min_inliers < 6) {
    return Invalid(error, "mono.tracking.reloc_min_matches and reloc_min_inliers must be >= 6");
  }
  if (!(low_rate_interval_s > 0)) {
    return Invalid(error, "mono.tracking.low_rate_interval_s must be > 0");
  }
  if (fallback_inliers < 0) return Invalid(error, "mono.tracking.fallback_inliers must be >= 0");
  if (!(unsure_radius_px > 0)) return Invalid(error, "mono.tracking.unsure_radius_px must be > 0");
  return true;
}

OptionTable<MonoTrackingOptions> MonoTrackingOptions::Describe() {
  using O = MonoTrackingOptions;
  return OptionTable<O>("tracking")
      .Double("search_radius_px", &O::search_radius_px, "px", 1, 500, 1,
              "Search window around a map point's predicted position.")
      .Double("wide_radius_px", &O::wide_radius_px, "px", 1, 1000, 1,
              "Window used when the first search finds too few points.")
      .Double("fine_radius_px", &O::fine_radius_px, "px", 1, 100, 0.5,
              "Window of the second pass, after a first pose.")
      .Int("max_descriptor_distance", &O::max_descriptor_distance, "bits", 1, 256, 1,
           "Largest Hamming distance of a tracked ORB match.")
      .Double("match_ratio", &O::match_ratio, "", 0.05, 1, 0.05,
              "Best over second-best descriptor distance in a window; 1 = off.")
      .Double("huber_px", &O::huber_px, "px", 0.1, 50, 0.1,
              "Huber threshold of the robust pose optimisation.")
      .Double("outlier_px", &O::outlier_px, "px", 0.1, 50, 0.1,
              "Residual beyond which a match is an outlier.")
      .Int("good_inliers", &O::good_inliers, "points", 6, 10000, 1,
           "Tracking quality is good from this many inliers.")
      .Int("min_inliers", &O::min_inliers, "points", 6, 10000, 1,
           "Tracking quality is poor from this many inliers; fewer is lost.")
      .Double("min_found_fraction", &O::min_found_fraction, "", 0, 0.99, 0.01,
              "Tracking is lost when fewer than this share of the map points predicted in the "
              "image are found (PTAM's test against a wrong pose after a jump).")
      .Int("reloc_min_matches", &O::reloc_min_matches, "matches", 6, 10000, 1,
           "Descriptor matches with a keyframe needed to try relocalisation.")
      .Int("reloc_min_inliers", &O::reloc_min_inliers, "points", 6, 10000, 1,
           "Inliers needed to accept a relocalisation.")
      .Double("low_rate_interval_s", &O::low_rate_interval_s, "s", 0.001, 1000, 0.05,
              "A frame this far after the last, or in a sequence whose recent frames are (median "
              "of five steps), is low-rate (keyframe-rate): the zero-motion try below and the "
              "urgent keyframes of mono.mapping apply.")
      .Int("fallback_inliers", &O::fallback_inliers, "points", 0, 10000, 1,
           "At low rates, when the constant-velocity prediction tracks fewer inliers, the last "
           "pose (zero motion) is tried too and the better kept (0 = off).")
      .Double("unsure_radius_px", &O::unsure_radius_px, "px", 1, 2000, 1,
              "Coarse search window of the zero-motion try.");
}

bool MonoMappingOptions::IsValid(std::string* error) const {
  if (min_keyframe_gap < 1) return Invalid(error, "mono.mapping.min_keyframe_gap must be >= 1");
  if (!(urgent_keyframe_ratio >= 0 && urgent_keyframe_ratio <= 1)) {
    return Invalid(error, "mono.mapping.urgent_keyframe_ratio must lie in [0, 1]");
  }
  if (!(urgent_keyframe_distance > 0)) {
    return Invalid(error, "mono.mapping.urgent_keyframe_distance must be > 0");
  }
  if (!(keyframe_distance > 0)) return Invalid(error, "mono.mapping.keyframe_distance must be > 0");
  if (!(keyframe_match_ratio > 0 && keyframe_match_ratio <= 1)) {
    return Invalid(error, "mono.mapping.keyframe_match_ratio must lie in (0, 1]");
  }
  if (neighbours < 1) return Invalid(error, "mono.mapping.neighbours must be >= 1");
  if (!(epipolar_px > 0)) return Invalid(error, "mono.mapping.epipolar_px must be > 0");
  if (max_descriptor_distance < 1 || max_descriptor_distance > 256) {
    return Invalid(error, "mono.mapping.max_descriptor_distance must lie in [1, 256]");
  }
  if (!(min_parallax_deg >= 0)) return Invalid(error, "mono.mapping.min_parallax_deg must be >= 0");
  if (!(max_reprojection_px > 0)) {
    return Invalid(error, "mono.mapping.max_reprojection_px must be > 0");
  }
  if (local_window < 2) return Invalid(error, "mono.mapping.local_window must be >= 2");
  if (ba_iterations < 0) return Invalid(error, "mono.mapping.ba_iterations must be >= 0");
  if (thread_nice < 0 || thread_nice > 19) {
    return Invalid(error, "mono.mapping.thread_nice must lie in [0, 19]");
  }
  if (final_ba_iterations < 0)
    return Invalid(error, "mono.mapping.final_ba_iterations must be >= 0");
  if (!(ba_huber_px > 0)) return Invalid(error, "mono.mapping.ba_huber_px must be > 0");
  if (!(local_map_distance >= 0)) {
    return Invalid(error, "mono.mapping.local_map_distance must be >= 0");
  }
  if (loop_min_age < 1) return Invalid(error, "mono.mapping.loop_min_age must be >= 1");
  if (!(loop_search_radius >= 0)) {
    return Invalid(error, "mono.mapping.loop_search_radius must be >= 0");
  }
  if (loop_min_inliers < 10) return Invalid(error, "mono.mapping.loop_min_inliers must be >= 10");
  if (idle_ba_window < 2) return Invalid(error, "mono.mapping.idle_ba_window must be >= 2");
  if (idle_ba_iterations < 0) {
    return Invalid(error, "mono.mapping.idle_ba_iterations must be >= 0");
  }
  if (idle_ba_every_frames < 1) {
    return Invalid(error, "mono.mapping.idle_ba_every_frames must be >= 1");
  }
  if (final_ba_max_keyframes < 3) {
    return Invalid(error, "mono.mapping.final_ba_max_keyframes must be >= 3");
  }
  if (final_ba_max_slices < 0) {
    return Invalid(error, "mono.mapping.final_ba_max_slices must be >= 0");
  }
  if (!(min_found_ratio >= 0 && min_found_ratio < 1)) {
    return Invalid(error, "mono.mapping.min_found_ratio must lie in [0, 1)");
  }
  return true;
}

OptionTable<MonoMappingOptions> MonoMappingOptions::Describe() {
  using O = MonoMappingOptions;
  return OptionTable<O>("mapping")
      .Int("min_keyframe_gap", &O::min_keyframe_gap, "frames", 1, 1000, 1,
           "Frames between two keyframes at least (see urgent_keyframe_ratio).")
      .Double("urgent_keyframe_ratio", &O::urgent_keyframe_ratio, "", 0, 1, 0.05,
              "At low rates (mono.tracking.low_rate_interval_s), a frame tracking fewer than "
              "this share of the last keyframe's points becomes a keyframe within "
              "min_keyframe_gap too (0 = off).")
      .Double("urgent_keyframe_distance", &O::urgent_keyframe_distance, "x mean depth", 0.001, 100,
              0.01,
              "At low rates, a frame this far from every keyframe (relative to the mean depth) "
              "becomes a keyframe within min_keyframe_gap too.")
      .Double("keyframe_distance", &O::keyframe_distance, "x mean depth", 0.001, 10, 0.01,
              "A frame this far from every keyframe (relative to the mean depth) becomes one.")
      .Double("keyframe_match_ratio", &O::keyframe_match_ratio, "", 0.05, 1, 0.05,
              "A frame tracking fewer than this share of the last keyframe's points becomes one.")
      .Int("neighbours", &O::neighbours, "keyframes", 1, 20, 1,
           "Recent keyframes a new keyframe triangulates new points with.")
      .Double("epipolar_px", &O::epipolar_px, "px", 0.1, 50, 0.1,
              "Distance from the epipolar line allowed for a new-point match.")
      .Int("max_descriptor_distance", &O::max_descriptor_distance, "bits", 1, 256, 1,
           "Largest Hamming distance of a new-point match.")
      .Double("min_parallax_deg", &O::min_parallax_deg, "deg", 0, 30, 0.1,
              "Ray angle a new map point needs.")
      .Double("max_reprojection_px", &O::max_reprojection_px, "px", 0.1, 50, 0.1,
              "Reprojection error a new map point may have in either keyframe.")
      .Int("local_window", &O::local_window, "keyframes", 2, 100, 1,
           "Most recent keyframes whose poses local bundle adjustment optimises.")
      .Int("ba_iterations", &O::ba_iterations, "iterations", 0, 1000, 1,
           "Iterations of each local bundle adjustment (0 = none).")
      .Double("ba_huber_px", &O::ba_huber_px, "px", 0.1, 50, 0.1,
              "Huber loss threshold of bundle adjustment.")
      .Double("min_found_ratio", &O::min_found_ratio, "", 0, 0.99, 0.05,
              "Points found in fewer of the frames that should see them are culled.")
      .Bool(
          "threaded", &O::threaded,
          "Run mapping on its own thread (live); off = inline after each keyframe, deterministic.")
      .Int("thread_nice", &O::thread_nice, "", 0, 19, 1,
           "Niceness of the mapping thread (threaded mode, Linux); 10 lets tracking win a core "
           "it shares with mapping, but starves mapping on a loaded machine.")
      .Int("final_ba_iterations", &O::final_ba_iterations, "iterations", 0, 1000, 5,
           "Global bundle adjustment of every keyframe and point when the run stops (0 = none).")
      .Double("local_map_distance", &O::local_map_distance, "x mean depth", 0, 100, 0.1,
              "Once a revisit links the map to old keyframes, those whose centre is this close "
              "to the camera (relative to the mean depth) join the recent ones in the map "
              "tracked against, so the place is tracked on its old points (0 = recent keyframes "
              "only).")
      .Int("loop_min_age", &O::loop_min_age, "keyframes", 1, 100000, 1,
           "A new keyframe looks for a revisit among keyframes at least this many keyframes "
           "older.")
      .Double("loop_search_radius", &O::loop_search_radius, "x mean depth", 0, 100, 0.1,
              "Old keyframes this close to a new keyframe (relative to the mean depth) are tried "
              "as a revisit (0 = no revisit search).")
      .Int("loop_min_inliers", &O::loop_min_inliers, "points", 10, 10000, 5,
           "Inliers against the old map that confirm a revisit; the map since then is then "
           "bent onto the old one.")
      .Int("idle_ba_window", &O::idle_ba_window, "keyframes", 2, 1000, 1,
           "Keyframes whose poses one slice of the idle-time global adjustment optimises.")
      .Int("idle_ba_iterations", &O::idle_ba_iterations, "iterations", 0, 1000, 1,
           "Iterations of one idle-time adjustment slice (0 = no adjustment in idle time).")
      .Int("idle_ba_every_frames", &O::idle_ba_every_frames, "frames", 1, 10000, 1,
           "Synchronous mode: frames without a new keyframe between two idle-time slices.")
      .Int("final_ba_max_keyframes", &O::final_ba_max_keyframes, "keyframes", 3, 100000, 1,
           "Maps with up to this many keyframes get the full global adjustment at stop; larger "
           "ones get at most final_ba_max_slices slices of the idle-time adjustment.")
      .Int("final_ba_max_slices", &O::final_ba_max_slices, "slices", 0, 1000, 1,
           "Idle-time adjustment slices run at stop on a large map (bounds the stop time).");
}

bool MonoSlamOptions::IsValid(std::string* error) const {
  return features.IsValid(error) && init.IsValid(error) && tracking.IsValid(error) &&
         mapping.IsValid(error) && scale.IsValid(error);
}

OptionTable<MonoSlamOptions> MonoSlamOptions::Describe() {
  using O = MonoSlamOptions;
  return OptionTable<O>("mono")
      .Nested(&O::features, MonoFeatureOptions::Describe())
      .Nested(&O::init, MonoInitOptions::Describe())
      .Nested(&O::tracking, MonoTrackingOptions::Describe())
      .Nested(&O::mapping, MonoMappingOptions::Describe())
      .Nested(&O::scale, ScaleEstimatorOptions::Describe());
}

}  // namespace sightline
