// Motion against a keyframe: tracks keep their stereo observation from the last keyframe, and the
// pose of each frame is re-estimated from those, so that small per-frame rotation errors do not
// add up while the keyframe's tracks survive.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/options/option_table.h"
#include "core/stereo/motion_refiner.h"
#include "core/stereo/stereo_correspondence.h"
#include "core/stereo/stereo_geometry.h"

namespace sightline {

// Keys "stereo.keyframe.*".
struct KeyframeOptions {
  bool enabled = false;             // Estimate each pose against the keyframe.
  double min_track_fraction = 0.8;  // New keyframe when fewer of its tracks survive.
  int min_inliers = 30;             // New keyframe when fewer keyframe tracks agree.

  bool IsValid(std::string* error) const;
  static OptionTable<KeyframeOptions> Describe();
};

// Refines *current_from_keyframe (starting from the frame-to-frame estimate) over the
// correspondences between keyframe and current observations: inliers by the reprojection
// threshold at the start motion, then `rounds` of refinement and re-selection. Returns the
// inlier count; *current_from_keyframe is changed only when it reaches min_inliers.
int RefineAgainstKeyframe(const RectifiedStereoCamera& camera, const MotionRefiner& refiner,
                          const std::vector<StereoCorrespondence>& correspondences,
                          double inlier_threshold_px, int rounds, int min_inliers,
                          Eigen::Isometry3d* current_from_keyframe);

}  // namespace sightline
