// What the `stereo-vo` pipeline gives views and writers for one frame, and the table of its
// per-frame statistics. Free of the estimator classes, so the GUI may include it.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <optional>

#include "core/pipeline/pipeline.h"
#include "core/stereo/stereo_geometry.h"
#include "core/stereo/stereo_types.h"

namespace sightline {

// One frame of stereo visual odometry. `stats` holds the keys of StereoVoStatistics(); a timing
// figure ("vo/ransac_ms", ...) only when its stage ran this frame.
struct StereoVoResult : PipelineResult {
  // Features, matches, pose and rectified images (null when the frame gave no estimate).
  std::shared_ptr<const StereoOdometryResult> odometry;
  // The rectified camera the feature positions refer to (triangulates them).
  RectifiedStereoCamera camera;
  // The recording's ground-truth pose of this frame (within stereo.gt_tolerance_s), expressed
  // relative to the first frame that had one, as the estimate starts at identity.
  std::optional<Eigen::Isometry3d> ground_truth;
};

// The per-frame statistics of stereo-vo, in the order of frames.csv's columns: counts, the
// residuals, the applied motion, the gate flag, then milliseconds per stage and per frame.
const StatisticTable& StereoVoStatistics();

}  // namespace sightline
