#include "core/button/arm_triangulation.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/button/option_check.h"

namespace sightline {

bool ArmTriangulationOptions::IsValid(std::string* error) const {
  using button_internal::Invalid;
  if (!(pixel_sigma_px > 0 && pixel_sigma_rel >= 0 && size_sigma_rel > 0 && robust_sigmas > 0)) {
    return Invalid(error, "button.triangulate: the sigmas and robust_sigmas must be > 0");
  }
  if (min_views < 2) return Invalid(error, "button.triangulate.min_views must be >= 2");
  if (!(min_depth_span > 0 && min_baseline_m > 0 && floor_sigma_m >= 0)) {
    return Invalid(error,
                   "button.triangulate.min_depth_span and min_baseline_m must be > 0, "
                   "floor_sigma_m >= 0");
  }
  if (iterations < 1) return Invalid(error, "button.triangulate.iterations must be >= 1");
  return true;
}

OptionTable<ArmTriangulationOptions> ArmTriangulationOptions::Describe() {
  using O = ArmTriangulationOptions;
  return OptionTable<O>("button.triangulate")
      .Bool("enabled", &O::enabled,
            "Also locate the button from the arm's metric camera poses alone (the tracked centre's "
            "rays and its apparent size, core/button/arm_triangulation.h) and combine that point "
            "with the map's by their variances. Off by default: on the simulated approach's seeds "
            "1-5 the mean final error goes 4.77 -> 3.68 mm and the worst 10.1 -> 5.9 mm, but "
            "seeds 1 and 4 and the 12 cm sideways approach get worse (docs/button.md).")
      .Double("pixel_sigma_px", &O::pixel_sigma_px, "px", 0.01, 100, 0.1,
              "1-sigma of the tracked centre in the triangulation ...")
      .Double("pixel_sigma_rel", &O::pixel_sigma_rel, "", 0, 1, 0.01,
              "... plus this fraction of the tracked radius (a model centre off by a fixed "
              "amount on the button grows with its apparent size).")
      .Bool("use_size", &O::use_size,
            "Use the apparent size (looming: the radius grows as 1 / depth while the arm moves "
            "forward by a measured distance) besides the rays.")
      .Bool("anchor_size", &O::anchor_size,
            "The size from the tap's own keypoints only (ButtonTrack::anchor_scale: the "
            "keypoints the tracker's refresh adds carry each refresh's scale error on); false: "
            "the tracked radius.")
      .Bool("pixel_offset", &O::pixel_offset,
            "Also estimate a constant offset of the tracked centre in the image (a detector's "
            "sub-pixel convention): it would tilt the rays of the approach against the "
            "sideways move's.")
      .Double("size_sigma_rel", &O::size_sigma_rel, "", 1e-4, 1, 0.001,
              "1-sigma relative error of the tracked radius.")
      .Double("robust_sigmas", &O::robust_sigmas, "sigmas", 0.1, 100, 0.5,
              "Huber threshold of the robust least squares.")
      .Int("min_views", &O::min_views, "views", 2, 100000, 1,
           "Fewer tracked views with an arm pose: no triangulated point.")
      .Double("min_depth_span", &O::min_depth_span, "", 1e-3, 10, 0.05,
              "Looming needs the largest and smallest depth to differ by this fraction ...")
      .Double("min_baseline_m", &O::min_baseline_m, "m", 1e-4, 10, 0.005,
              "... or the camera centres to lie this far apart (rays crossing).")
      .Double("floor_sigma_m", &O::floor_sigma_m, "m", 0, 1, 0.0005,
              "Added to the triangulation's stated 1-sigma: biases no residual shows (the "
              "tracked centre's offset on the button, the size's depth on a relief).")
      .Int("iterations", &O::iterations, "", 1, 1000, 1, "Reweighted Gauss-Newton iterations.");
}

double ArmTriangulation::SigmaMaxM() const {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance);
  return std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
}

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

double HuberWeight(double normalized, double k) { return normalized <= k ? 1.0 : k / normalized; }

// The normal equations of one reweighted step at `theta`: the point, the log radius at 1 m and
// the tracked centre's constant offset in the image (u, v).
struct Step {
  Matrix6 h = Matrix6::Zero();
  Vector6 g = Vector6::Zero();
  double chi2 = 0, sum_px2 = 0, sum_s2 = 0;
  int residuals = 0, inliers = 0, inliers_px = 0, inliers_s = 0;
};

Step Linearize(const std::vector<ArmView>& views, const PinholeCamera& camera,
               const ArmTriangulationOptions& o, bool use_size, bool use_offset,
               const Vector6& theta) {
  // Unknowns left out are held (an identity block keeps the system regular).
  Step s;
  const Eigen::Vector3d p = theta.head<3>();
  for (const ArmView& v : views) {
    const Eigen::Matrix3d rt = v.base_from_camera.linear().transpose();
    const Eigen::Vector3d x = rt * (p - v.base_from_camera.translation());
    if (!(x.z() > 1e-3)) continue;
    const double sigma = std::hypot(o.pixel_sigma_px, o.pixel_sigma_rel * v.radius_px);
    const Eigen::Vector2d e = (camera.Project(x) + theta.tail<2>() - v.pixel) / sigma;
    Eigen::Matrix<double, 2, 3> d;
    d << camera.fx / x.z(), 0, -camera.fx * x.x() / (x.z() * x.z()), 0, camera.fy / x.z(),
        -camera.fy * x.y() / (x.z() * x.z());
    Eigen::Matrix<double, 2, 6> j = Eigen::Matrix<double, 2, 6>::Zero();
    j.leftCols<3>() = d * rt / sigma;
    j.rightCols<2>() = Eigen::Matrix2d::Identity() / sigma;
    double w = HuberWeight(e.norm(), o.robust_sigmas);
    s.h += w * j.transpose() * j;
    s.g += w * j.transpose() * e;
    s.chi2 += w * e.squaredNorm();
    s.residuals += 2;
    const bool in_px = e.norm() <= o.robust_sigmas;
    if (in_px) s.sum_px2 += (e * sigma).squaredNorm(), ++s.inliers_px;
    bool in_s = true;
    if (use_size && v.radius_px > 0) {
      const double es = (theta(3) - std::log(x.z()) - std::log(v.radius_px)) / o.size_sigma_rel;
      Vector6 js = Vector6::Zero();
      js.head<3>() = -rt.row(2).transpose() / (x.z() * o.size_sigma_rel);
      js(3) = 1.0 / o.size_sigma_rel;
      w = HuberWeight(std::abs(es), o.robust_sigmas);
      s.h += w * js * js.transpose();
      s.g += w * js * es;
      s.chi2 += w * es * es;
      s.residuals += 1;
      in_s = std::abs(es) <= o.robust_sigmas;
      if (in_s) s.sum_s2 += std::pow(es * o.size_sigma_rel, 2), ++s.inliers_s;
    }
    s.inliers += in_px && in_s;
  }
  auto hold = [&s](int k) {  // Not estimated: no coupling, an identity diagonal.
    s.h.row(k).setZero();
    s.h.col(k).setZero();
    s.h(k, k) = 1;
    s.g(k) = 0;
  };
  if (!use_size) hold(3);
  if (!use_offset) hold(4), hold(5);
  return s;
}

// The point nearest all viewing rays (least squares), pulled weakly toward `start`.
Eigen::Vector3d NearestToRays(const std::vector<ArmView>& views, const PinholeCamera& camera,
                              const Eigen::Vector3d& start) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const ArmView& v : views) {
    const Eigen::Vector3d d =
        (v.base_from_camera.linear() * camera.Unproject(v.pixel.x(), v.pixel.y(), 1.0))
            .normalized();
    const Eigen::Matrix3d m = Eigen::Matrix3d::Identity() - d * d.transpose();
    a += m;
    b += m * v.base_from_camera.translation();
  }
  const double eps = 1e-4 * a.trace();
  return (a + eps * Eigen::Matrix3d::Identity()).ldlt().solve(b + eps * start);
}

// The depth span of the views (largest over smallest depth, less 1) and the camera centres'
// largest distance across the ray to `p` [m].
void Spread(const std::vector<ArmView>& views, const Eigen::Vector3d& p, double* depth_span,
            double* baseline_m) {
  double z_min = 1e18, z_max = 0;
  *baseline_m = 0;
  const Eigen::Vector3d c0 = views.front().base_from_camera.translation();
  const Eigen::Vector3d ray = (p - c0).normalized();
  for (const ArmView& v : views) {
    const Eigen::Vector3d d = v.base_from_camera.translation() - c0;
    *baseline_m = std::max(*baseline_m, (d - ray * ray.dot(d)).norm());
    const double z = (v.base_from_camera.inverse() * p).z();
    z_min = std::min(z_min, z), z_max = std::max(z_max, z);
  }
  *depth_span = z_min > 0 ? (z_max - z_min) / z_min : 0;
}

}  // namespace

StatusOr<ArmTriangulation> TriangulateFromArm(const std::vector<ArmView>& views,
                                              const PinholeCamera& camera,
                                              const ArmTriangulationOptions& options,
                                              const std::optional<Eigen::Vector3d>& prior_in_base) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  if (static_cast<int>(views.size()) < options.min_views) {
    return FailedPrecondition("triangulation from the arm: " + std::to_string(views.size()) +
                              " view(s), need " + std::to_string(options.min_views));
  }
  int sized = 0;
  for (const ArmView& v : views) sized += v.radius_px > 0;
  const bool use_size = options.use_size && sized >= options.min_views;
  const Eigen::Isometry3d& first = views.front().base_from_camera;
  const Eigen::Vector3d start = prior_in_base.value_or(
      first * camera.Unproject(views.front().pixel.x(), views.front().pixel.y(), 1.0));
  Vector6 theta = Vector6::Zero();
  theta.head<3>() = NearestToRays(views, camera, start);
  double depth_span = 0, baseline_m = 0;
  Spread(views, theta.head<3>(), &depth_span, &baseline_m);
  const bool looms = depth_span >= options.min_depth_span;
  if (baseline_m < options.min_baseline_m && !(use_size && looms)) {
    return FailedPrecondition("triangulation from the arm: the views neither cross nor loom");
  }
  // A constant image offset is told from a sideways shift only by views at different depths.
  const bool use_offset = options.pixel_offset && looms;
  theta(3) = 0;
  if (use_size) {
    double sum = 0;
    int n = 0;
    for (const ArmView& v : views) {
      const double z = (v.base_from_camera.inverse() * theta.head<3>()).z();
      if (v.radius_px > 0 && z > 1e-3) sum += std::log(v.radius_px * z), ++n;
    }
    theta(3) = n > 0 ? sum / n : 0;
  }
  Step step;
  for (int it = 0; it < options.iterations; ++it) {
    step = Linearize(views, camera, options, use_size, use_offset, theta);
    const Vector6 delta = step.h.ldlt().solve(-step.g);
    if (!delta.allFinite()) return FailedPrecondition("triangulation from the arm: degenerate");
    theta += delta;
    if (delta.head<3>().norm() < 1e-8) break;
  }
  step = Linearize(views, camera, options, use_size, use_offset, theta);
  const int unknowns = 3 + (use_size ? 1 : 0) + (use_offset ? 2 : 0);
  Eigen::SelfAdjointEigenSolver<Matrix6> eig(step.h);
  if (step.residuals <= unknowns || !(eig.eigenvalues().minCoeff() > 1e-12)) {
    return FailedPrecondition("triangulation from the arm: degenerate geometry");
  }
  const double variance_factor = std::max(1.0, step.chi2 / (step.residuals - unknowns));
  const Matrix6 cov = step.h.inverse() * variance_factor;
  ArmTriangulation out;
  out.in_base = theta.head<3>();
  out.covariance = cov.topLeftCorner<3, 3>() +
                   options.floor_sigma_m * options.floor_sigma_m * Eigen::Matrix3d::Identity();
  out.radius_at_1m_px = use_size ? std::exp(theta(3)) : 0;
  out.pixel_offset_px = theta.tail<2>();
  out.views = static_cast<int>(views.size());
  out.inliers = step.inliers;
  out.rms_px = step.inliers_px > 0 ? std::sqrt(step.sum_px2 / step.inliers_px) : 0;
  out.rms_size = step.inliers_s > 0 ? std::sqrt(step.sum_s2 / step.inliers_s) : 0;
  out.used_size = use_size;
  if (!out.in_base.allFinite() || !out.covariance.allFinite()) {
    return FailedPrecondition("triangulation from the arm: did not converge");
  }
  return out;
}

}  // namespace sightline
