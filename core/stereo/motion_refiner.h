// Non-linear least-squares refinement of a frame-to-frame motion: Gauss-Newton on the
// reprojection error in both images of the rectified pair (as libviso2), with Huber weights,
// seeded by the RANSAC estimate. By default the points are refined too (two-frame bundle
// adjustment, reduced to the 6 motion parameters by the Schur complement). Optionally symmetric:
// previous points into the current images and current points into the previous images, which uses
// both depth estimates.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/options/option_table.h"
#include "core/stereo/stereo_correspondence.h"
#include "core/stereo/stereo_geometry.h"

namespace sightline {

// Refinement options. Keys "stereo.refine.*".
struct MotionRefinerOptions {
  int max_iterations = 5;  // Gauss-Newton iterations (per refinement round).
  double huber_px = 0.3;   // Residuals beyond this get weight huber / |r| [px]; about
                           // twice the typical residual, so that points on slowly moving
                           // objects, which pass the 1 px inlier test, count less.
  double min_step = 1e-6;  // Stop when the update (rad or m) is smaller.
  bool symmetric = true;   // Also project the current points into the previous images.
  // Estimate the 3D points together with the motion (two-frame bundle adjustment, Schur
  // complement): removes the depth bias of triangulated points (E[1/d] > 1/E[d]) that makes
  // motion-only refinement overestimate translation. Replaces `symmetric` when on.
  bool joint_points = true;
  // Weight observations by 1 / (|u - cx| / cx + 0.05) as libviso2 does: the image centre, where
  // rectification and lens model are best, counts more (joint refinement only). Off by default:
  // it down-weights the image sides twenty-fold, and there (the walls of a corridor, the
  // roadside) are most of the features that fix the rotation.
  bool center_weighting = false;

  bool IsValid(std::string* error) const;
  static OptionTable<MotionRefinerOptions> Describe();
};

// What a refinement did.
struct RefinementSummary {
  int iterations = 0;
  double initial_rms_px = 0;  // RMS reprojection error of the seed over the points used [px].
  double final_rms_px = 0;    // After refinement [px].
  bool converged = false;
};

// Refines current_from_previous over the given correspondences.
//
//   MotionRefiner refiner(options);
//   RefinementSummary s = refiner.Refine(camera, correspondences, inliers, &motion);
class MotionRefiner {
 public:
  explicit MotionRefiner(MotionRefinerOptions options = {}) : options_(options) {}

  // Refines *current_from_previous in place over correspondences[indices]. Leaves it unchanged
  // (and reports so) when fewer than 3 points or a degenerate system.
  RefinementSummary Refine(const RectifiedStereoCamera& camera,
                           const std::vector<StereoCorrespondence>& correspondences,
                           const std::vector<int>& indices,
                           Eigen::Isometry3d* current_from_previous) const;

  // RMS of the 4-vector reprojection residual (left u, v; right u, v) of previous points moved
  // into the current images [px].
  static double RmsReprojectionPx(const RectifiedStereoCamera& camera,
                                  const std::vector<StereoCorrespondence>& correspondences,
                                  const std::vector<int>& indices,
                                  const Eigen::Isometry3d& current_from_previous);

 private:
  // The joint motion + points refinement.
  RefinementSummary RefineJoint(const RectifiedStereoCamera& camera,
                                const std::vector<StereoCorrespondence>& correspondences,
                                const std::vector<int>& indices,
                                Eigen::Isometry3d* current_from_previous) const;

  MotionRefinerOptions options_;
};

}  // namespace sightline
