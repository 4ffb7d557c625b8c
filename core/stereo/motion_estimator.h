// Frame-to-frame motion from stereo correspondences (the seed's Fig. 7): RANSAC over 3-point
// samples that pass the rigidity test (pairwise distances preserved, UMBRAL1, with a tolerance
// that grows with depth uncertainty), motion of a sample by absolute orientation (Umeyama,
// rotation without reflection) polished by a few Gauss-Newton steps on its reprojection error,
// inliers by reprojection error in both images (UMBRAL3); stops at UMBRAL4 inliers, UMBRAL5
// iterations or when the adaptive count for the requested confidence is reached, fails after
// UMBRAL2 rigidity failures without a usable sample.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/options/option_table.h"
#include "core/stereo/stereo_correspondence.h"
#include "core/stereo/stereo_geometry.h"

namespace sightline {

// RANSAC options. Keys "stereo.ransac.*" (the seed's UMBRAL1..5 named for what they mean).
struct MotionEstimatorOptions {
  double rigidity_tolerance_m = 0.05;  // UMBRAL1: pairwise distance change allowed at zero depth
                                       // uncertainty [m] ...
  double rigidity_sigmas = 3.0;        // ... plus this many depth sigmas of both points.
  double disparity_sigma_px = 0.5;     // Disparity noise behind the depth sigma Z^2 s / (f b) [px].
  int max_rigidity_failures = 2000;    // UMBRAL2: rigidity rejections before RANSAC gives up.
  double inlier_threshold_px = 1.0;    // UMBRAL3: reprojection error of an inlier [px].
  double stop_inlier_fraction = 0.95;  // UMBRAL4: stop once this fraction is inlier.
  int max_iterations = 200;            // UMBRAL5: samples that pass the rigidity test.
  // Adaptive termination: stop once a sample free of outliers has been drawn with this
  // probability, given the best inlier fraction w so far: log(1 - p) / log(1 - w^3)
  // samples. 1 = always run max_iterations (or until UMBRAL4).
  double confidence = 0.999;
  int min_iterations = 10;           // Rigid samples tried at least, whatever the estimate.
  int min_inliers = 12;              // Fewer inliers means the estimate failed.
  int sample_refine_iterations = 3;  // Gauss-Newton steps on each sample's 3 points.
  int seed = 42;                     // Random generator seed (runs are deterministic).

  bool IsValid(std::string* error) const;
  static OptionTable<MotionEstimatorOptions> Describe();
};

// What RANSAC found.
struct MotionHypothesis {
  bool ok = false;      // False: failed; `failure` says why.
  std::string failure;  // "too few correspondences", "rigidity test failed", ...
  Eigen::Isometry3d current_from_previous = Eigen::Isometry3d::Identity();
  std::vector<int> inliers;   // Indices into the correspondences.
  int iterations = 0;         // Samples that passed the rigidity test.
  int rigidity_failures = 0;  // Samples rejected by the rigidity test.
};

// The RANSAC motion estimator. Deterministic: each call reseeds from options.seed.
//
//   MotionEstimator ransac(options);
//   MotionHypothesis h = ransac.Estimate(camera, correspondences);
class MotionEstimator {
 public:
  explicit MotionEstimator(MotionEstimatorOptions options = {}) : options_(options) {}
  const MotionEstimatorOptions& options() const { return options_; }

  MotionHypothesis Estimate(const RectifiedStereoCamera& camera,
                            const std::vector<StereoCorrespondence>& correspondences) const;

  // Indices whose previous point, moved by `current_from_previous`, reprojects within
  // threshold_px (RMS of left and right image distances) of its current observation.
  static std::vector<int> Inliers(const RectifiedStereoCamera& camera,
                                  const std::vector<StereoCorrespondence>& correspondences,
                                  const Eigen::Isometry3d& current_from_previous,
                                  double threshold_px);

  // The rigidity test of one pair of correspondences.
  bool Rigid(const RectifiedStereoCamera& camera, const StereoCorrespondence& a,
             const StereoCorrespondence& b) const;

 private:
  // Samples needed to draw an outlier-free one with the configured confidence.
  int AdaptiveIterations(double inlier_fraction) const;

  MotionEstimatorOptions options_;
};

// Absolute orientation: the rigid motion (no reflection, no scale) taking `from` onto `to` in
// the least-squares sense (Umeyama). Columns are points.
Eigen::Isometry3d AbsoluteOrientation(const Eigen::Matrix3Xd& from, const Eigen::Matrix3Xd& to);

}  // namespace sightline
