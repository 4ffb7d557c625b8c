#include "core/stereo/keyframe.h"

#include "core/stereo/motion_estimator.h"
#include "core/stereo/option_check.h"

namespace sightline {

using stereo_internal::Invalid;

bool KeyframeOptions::IsValid(std::string* error) const {
  if (!(min_track_fraction >= 0 && min_track_fraction <= 1)) {
    return Invalid(error, "stereo.keyframe.min_track_fraction must lie in [0, 1]");
  }
  if (min_inliers < 3) return Invalid(error, "stereo.keyframe.min_inliers must be >= 3");
  return true;
}

OptionTable<KeyframeOptions> KeyframeOptions::Describe() {
  using O = KeyframeOptions;
  return OptionTable<O>("stereo.keyframe")
      .Bool("enabled", &O::enabled,
            "Estimate each pose against the last keyframe's stereo observations of the tracks "
            "(after the frame-to-frame estimate), so per-frame errors do not accumulate.")
      .Double("min_track_fraction", &O::min_track_fraction, "", 0, 1, 0.05,
              "The current frame becomes the keyframe when fewer of the keyframe's tracks "
              "survive.")
      .Int("min_inliers", &O::min_inliers, "", 3, 10000, 1,
           "The current frame becomes the keyframe when fewer keyframe tracks agree with the "
           "motion.");
}

int RefineAgainstKeyframe(const RectifiedStereoCamera& camera, const MotionRefiner& refiner,
                          const std::vector<StereoCorrespondence>& correspondences,
                          double inlier_threshold_px, int rounds, int min_inliers,
                          Eigen::Isometry3d* current_from_keyframe) {
  Eigen::Isometry3d motion = *current_from_keyframe;
  std::vector<int> inliers =
      MotionEstimator::Inliers(camera, correspondences, motion, inlier_threshold_px);
  if (static_cast<int>(inliers.size()) < min_inliers) return static_cast<int>(inliers.size());
  for (int round = 0; round < rounds; ++round) {
    refiner.Refine(camera, correspondences, inliers, &motion);
    std::vector<int> again =
        MotionEstimator::Inliers(camera, correspondences, motion, inlier_threshold_px);
    if (static_cast<int>(again.size()) < min_inliers) return static_cast<int>(again.size());
    inliers = std::move(again);
  }
  *current_from_keyframe = motion;
  return static_cast<int>(inliers.size());
}

}  // namespace sightline
