#include "core/stereo/motion_estimator.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <random>

#include "core/stereo/motion_refiner.h"
#include "core/stereo/option_check.h"

namespace sightline {

using stereo_internal::Invalid;

bool MotionEstimatorOptions::IsValid(std::string* error) const {
  if (!(rigidity_tolerance_m > 0))
    return Invalid(error, "stereo.ransac.rigidity_tolerance_m must be > 0");
  if (!(rigidity_sigmas >= 0)) return Invalid(error, "stereo.ransac.rigidity_sigmas must be >= 0");
  if (!(disparity_sigma_px >= 0))
    return Invalid(error, "stereo.ransac.disparity_sigma_px must be >= 0");
  if (max_rigidity_failures < 1)
    return Invalid(error, "stereo.ransac.max_rigidity_failures must be >= 1");
  if (!(inlier_threshold_px > 0))
    return Invalid(error, "stereo.ransac.inlier_threshold_px must be > 0");
  if (!(stop_inlier_fraction > 0 && stop_inlier_fraction <= 1)) {
    return Invalid(error, "stereo.ransac.stop_inlier_fraction must lie in (0, 1]");
  }
  if (max_iterations < 1) return Invalid(error, "stereo.ransac.max_iterations must be >= 1");
  if (!(confidence > 0 && confidence <= 1)) {
    return Invalid(error, "stereo.ransac.confidence must lie in (0, 1]");
  }
  if (min_iterations < 1) return Invalid(error, "stereo.ransac.min_iterations must be >= 1");
  if (min_inliers < 3) return Invalid(error, "stereo.ransac.min_inliers must be >= 3");
  if (sample_refine_iterations < 0) {
    return Invalid(error, "stereo.ransac.sample_refine_iterations must be >= 0");
  }
  return true;
}

OptionTable<MotionEstimatorOptions> MotionEstimatorOptions::Describe() {
  using O = MotionEstimatorOptions;
  return OptionTable<O>("stereo.ransac")
      .Double("rigidity_tolerance_m", &O::rigidity_tolerance_m, "m", 1e-4, 10, 0.005,
              "UMBRAL1: change of a pairwise distance a rigid sample may show, before depth "
              "uncertainty is added.")
      .Double("rigidity_sigmas", &O::rigidity_sigmas, "", 0, 20, 0.5,
              "Depth sigmas (of both points at both times) added to the rigidity tolerance.")
      .Double("disparity_sigma_px", &O::disparity_sigma_px, "px", 0, 10, 0.05,
              "Disparity noise giving the depth sigma Z^2 s / (f b).")
      .Int("max_rigidity_failures", &O::max_rigidity_failures, "samples", 1, 1000000, 10,
           "UMBRAL2: rigidity rejections after which RANSAC fails (the last motion is kept).")
      .Double("inlier_threshold_px", &O::inlier_threshold_px, "px", 0.05, 50, 0.1,
              "UMBRAL3: reprojection error (RMS of both images) of an inlier.")
      .Double("stop_inlier_fraction", &O::stop_inlier_fraction, "", 0.01, 1, 0.01,
              "UMBRAL4: stop sampling once this fraction of the points is inlier.")
      .Int("max_iterations", &O::max_iterations, "samples", 1, 100000, 10,
           "UMBRAL5: rigid samples tried before the best inlier set is taken.")
      .Double("confidence", &O::confidence, "", 0.5, 1, 0.001,
              "Adaptive termination: stop when an outlier-free sample was drawn with this "
              "probability given the best inlier fraction; 1 = always max_iterations.")
      .Int("min_iterations", &O::min_iterations, "samples", 1, 100000, 1,
           "Rigid samples tried at least before adaptive termination may stop.")
      .Int("min_inliers", &O::min_inliers, "points", 3, 10000, 1,
           "Fewer inliers than this means the motion could not be estimated.")
      .Int("sample_refine_iterations", &O::sample_refine_iterations, "", 0, 20, 1,
           "Gauss-Newton steps on the reprojection error of each 3-point sample.")
      .Int("seed", &O::seed, "", 0, 2147483647, 1, "Random generator seed.");
}

Eigen::Isometry3d AbsoluteOrientation(const Eigen::Matrix3Xd& from, const Eigen::Matrix3Xd& to) {
  // Eigen's umeyama corrects the reflection case (det = -1) with its S matrix.
  const Eigen::Matrix4d m = Eigen::umeyama(from, to, /*with_scaling=*/false);
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = m.topLeftCorner<3, 3>();
  t.translation() = m.topRightCorner<3, 1>();
  return t;
}

bool MotionEstimator::Rigid(const RectifiedStereoCamera& camera, const StereoCorrespondence& a,
                            const StereoCorrespondence& b) const {
  const double d_prev = (a.x_previous - b.x_previous).norm();
  const double d_cur = (a.x_current - b.x_current).norm();
  const double s = options_.disparity_sigma_px;
  // Each distance is off by about the depth errors of its two points (along the rays).
  const double s1 = camera.DepthSigma(a.x_previous.z(), s),
               s2 = camera.DepthSigma(b.x_previous.z(), s),
               s3 = camera.DepthSigma(a.x_current.z(), s),
               s4 = camera.DepthSigma(b.x_current.z(), s);
  const double sigma = std::sqrt(s1 * s1 + s2 * s2 + s3 * s3 + s4 * s4);
  return std::abs(d_prev - d_cur) <=
         options_.rigidity_tolerance_m + options_.rigidity_sigmas * sigma;
}

std::vector<int> MotionEstimator::Inliers(const RectifiedStereoCamera& camera,
                                          const std::vector<StereoCorrespondence>& correspondences,
                                          const Eigen::Isometry3d& current_from_previous,
                                          double threshold_px) {
  std::vector<int> inliers;
  const double limit = 2 * threshold_px * threshold_px;  // Sum of both images' squared errors.
  const Eigen::Matrix3d r = current_from_previous.rotation();
  const Eigen::Vector3d t = current_from_previous.translation();
  for (size_t i = 0; i < correspondences.size(); ++i) {
    const StereoCorrespondence& c = correspondences[i];
    const Eigen::Vector3d y = r * c.x_previous + t;
    if (!(y.z() > 1e-3)) continue;
    const double iz = camera.f / y.z();
    const double ul = y.x() * iz + camera.cx - c.current.u_left;
    const double ur = (y.x() - camera.baseline_m) * iz + camera.cx - c.current.u_right;
    const double v = y.y() * iz + camera.cy - c.current.v;
    if (ul * ul + ur * ur + 2 * v * v <= limit) inliers.push_back(static_cast<int>(i));
  }
  return inliers;
}

int MotionEstimator::AdaptiveIterations(double inlier_fraction) const {
  if (options_.confidence >= 1) return options_.max_iterations;
  const double clean = std::pow(std::clamp(inlier_fraction, 0.0, 1.0), 3);
  if (clean >= 1) return 0;
  if (clean <= 0) return options_.max_iterations;
  const double k = std::log(1 - options_.confidence) / std::log(1 - clean);
  return static_cast<int>(std::min<double>(options_.max_iterations, std::ceil(k)));
}

MotionHypothesis MotionEstimator::Estimate(
    const RectifiedStereoCamera& camera,
    const std::vector<StereoCorrespondence>& correspondences) const {
  MotionHypothesis best;
  const int n = static_cast<int>(correspondences.size());
  if (n < std::max(3, options_.min_inliers)) {
    best.failure = "too few correspondences (" + std::to_string(n) + ")";
    return best;
  }
  std::mt19937 rng(static_cast<uint32_t>(options_.seed));
  std::uniform_int_distribution<int> pick(0, n - 1);
  MotionRefinerOptions sample_refine;
  sample_refine.max_iterations = options_.sample_refine_iterations;
  sample_refine.symmetric = false;
  sample_refine.joint_points = false;
  sample_refine.huber_px = 1e9;
  const MotionRefiner refiner(sample_refine);
  const size_t stop_count = static_cast<size_t>(std::ceil(options_.stop_inlier_fraction * n));
  int needed = options_.max_iterations;  // Adaptive sample count for the best set so far.
  while (best.iterations <
         std::min(options_.max_iterations, std::max(options_.min_iterations, needed))) {
    const int a = pick(rng), b = pick(rng), c = pick(rng);
    if (a == b || a == c || b == c) continue;
    const StereoCorrespondence &ca = correspondences[static_cast<size_t>(a)],
                               &cb = correspondences[static_cast<size_t>(b)],
                               &cc = correspondences[static_cast<size_t>(c)];
    if (!Rigid(camera, ca, cb) || !Rigid(camera, ca, cc) || !Rigid(camera, cb, cc)) {
      if (++best.rigidity_failures > options_.max_rigidity_failures) break;
      continue;
    }
    Eigen::Matrix3Xd from(3, 3), to(3, 3);
    from << ca.x_previous, cb.x_previous, cc.x_previous;
    to << ca.x_current, cb.x_current, cc.x_current;
    // Degenerate (nearly collinear) samples determine no rotation.
    if ((from.col(1) - from.col(0)).cross(from.col(2) - from.col(0)).norm() < 1e-6) {
      if (++best.rigidity_failures > options_.max_rigidity_failures) break;
      continue;
    }
    ++best.iterations;
    Eigen::Isometry3d motion = AbsoluteOrientation(from, to);
    if (options_.sample_refine_iterations > 0) {
      refiner.Refine(camera, correspondences, {a, b, c}, &motion);
    }
    std::vector<int> inliers =
        Inliers(camera, correspondences, motion, options_.inlier_threshold_px);
    if (inliers.size() > best.inliers.size()) {
      best.inliers = std::move(inliers);
      best.current_from_previous = motion;
      if (best.inliers.size() >= stop_count) break;
      needed = AdaptiveIterations(static_cast<double>(best.inliers.size()) / n);
    }
  }
  if (best.iterations == 0) {
    best.failure = "rigidity test failed for every sample (" +
                   std::to_string(best.rigidity_failures) + " tried)";
    best.inliers.clear();
    return best;
  }
  if (static_cast<int>(best.inliers.size()) < options_.min_inliers) {
    best.failure = "too few inliers (" + std::to_string(best.inliers.size()) + " of " +
                   std::to_string(n) + ")";
    return best;
  }
  best.ok = true;
  return best;
}

}  // namespace sightline
