#include "core/pipeline/stereo_vo_result.h"

namespace sightline {

const StatisticTable& StereoVoStatistics() {
  static const StatisticTable kTable = {
      {"vo/tracked", "count", "Features tracked from the previous left image."},
      {"vo/retracked", "", "1 when lost tracks were tracked again with more pyramid levels."},
      {"vo/anchored", "count", "Tracked positions refined against their anchors."},
      {"vo/new_features", "count", "Features detected this frame and matched in the right image."},
      {"vo/stereo_matches", "count", "Features matched in the right image (tracked and new)."},
      {"vo/correspondences", "count", "Features with stereo at both times (RANSAC input)."},
      {"vo/inliers", "count", "Inliers of the motion after refinement."},
      {"vo/ransac_iterations", "count", "Rigid samples tried by RANSAC."},
      {"vo/rigidity_failures", "count", "Samples rejected by the rigidity test."},
      {"vo/residual_px", "px", "Refined RMS reprojection error over the inliers."},
      {"vo/disparity_offset_px", "px", "Disparity offset applied to this frame's matches."},
      {"vo/window_points", "count", "Points of the sliding-window bundle adjustment."},
      {"vo/window_rms_px", "px", "RMS reprojection error of the window after adjustment."},
      {"vo/translation_m", "m", "Length of the applied motion."},
      {"vo/rotation_deg", "deg", "Angle of the applied motion."},
      {"vo/gated", "", "1 when the estimate was rejected (or failed) and a fallback applied."},
      {"vo/turn_searched", "",
       "1 when tracks were started from the rotation the image's global shift gives (a sharp "
       "turn)."},
      {"vo/rectify_ms", "ms", "Rectifying the pair."},
      {"vo/pyramid_ms", "ms", "Building the left image pyramid."},
      {"vo/tracking_ms", "ms", "KLT tracking from the previous left image."},
      {"vo/detection_ms", "ms", "Detecting new features."},
      {"vo/matching_ms", "ms", "Matching features in the right image."},
      {"vo/ransac_ms", "ms", "RANSAC with the rigidity test."},
      {"vo/refine_ms", "ms", "Reprojection refinement of the motion."},
      {"vo/window_ms", "ms", "Sliding-window bundle adjustment."},
      // The run's "total" stage (frames.csv's total_ms, metrics.json, the GUI's plot).
      {"vo/total_ms", "ms", "The odometry's time for the whole frame."},
  };
  return kTable;
}

}  // namespace sightline
