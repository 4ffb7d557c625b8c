#include "core/mono/bundle_adjustment.h"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <cmath>
#include <limits>

namespace sightline {

namespace {

// Residual of a keypoint against a point seen from a pose [angle-axis, translation].
struct ReprojectionCost {
  ReprojectionCost(const PinholeCamera& camera, const Eigen::Vector2d& pixel, double scale)
      : fx(camera.fx),
        fy(camera.fy),
        cx(camera.cx),
        cy(camera.cy),
        u(pixel.x()),
        v(pixel.y()),
        inv_scale(1.0 / scale) {}

  template <typename T>
  bool operator()(const T* pose, const T* point, T* residual) const {
    T p[3];
    ceres::AngleAxisRotatePoint(pose, point, p);
    p[0] += pose[3];
    p[1] += pose[4];
    p[2] += pose[5];
    if (p[2] < T(1e-9)) return false;
    residual[0] = (T(fx) * p[0] / p[2] + T(cx) - T(u)) * T(inv_scale);
    residual[1] = (T(fy) * p[1] / p[2] + T(cy) - T(v)) * T(inv_scale);
    return true;
  }

  double fx, fy, cx, cy, u, v, inv_scale;
};

void ToArray(const Eigen::Isometry3d& pose, double* a) {
  const Eigen::AngleAxisd aa(pose.rotation());
  const Eigen::Vector3d r = aa.angle() * aa.axis();
  for (int i = 0; i < 3; ++i) {
    a[i] = r[i];
    a[3 + i] = pose.translation()[i];
  }
}

Eigen::Isometry3d FromArray(const double* a) {
  const Eigen::Vector3d r(a[0], a[1], a[2]);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const double angle = r.norm();
  if (angle > 1e-15) pose.linear() = Eigen::AngleAxisd(angle, r / angle).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(a[3], a[4], a[5]);
  return pose;
}

double Rms(const PinholeCamera& camera, const BundleProblem& problem) {
  double sum = 0;
  int n = 0;
  for (const auto& o : problem.observations) {
    const double e = ReprojectionErrorPx(camera, problem, o);
    if (std::isfinite(e)) {
      sum += e * e;
      ++n;
    }
  }
  return n > 0 ? std::sqrt(sum / n) : 0;
}

}  // namespace

double ReprojectionErrorPx(const PinholeCamera& camera, const BundleProblem& problem,
                           const BundleProblem::Observation& o) {
  const Eigen::Vector3d p =
      problem.poses[o.pose].camera_from_map * problem.points[o.point].position;
  if (p.z() <= 1e-9) return std::numeric_limits<double>::infinity();
  const Eigen::Vector2d proj(camera.fx * p.x() / p.z() + camera.cx,
                             camera.fy * p.y() / p.z() + camera.cy);
  return (proj - o.pixel).norm();
}

namespace {

// Ends a solve early when asked to.
class StopCallback : public ceres::IterationCallback {
 public:
  explicit StopCallback(const std::function<bool()>& should_stop) : should_stop_(should_stop) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return should_stop_() ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  const std::function<bool()>& should_stop_;
};

}  // namespace

BundleSummary SolveBundle(const PinholeCamera& camera, BundleProblem* problem, int iterations,
                          double huber_px, const std::function<bool()>& should_stop) {
  BundleSummary summary;
  summary.initial_rms_px = Rms(camera, *problem);
  summary.final_rms_px = summary.initial_rms_px;
  if (iterations <= 0 || problem->observations.empty()) {
    summary.usable = true;
    summary.message = "not run";
    return summary;
  }
  std::vector<double> poses(problem->poses.size() * 6);
  std::vector<double> points(problem->points.size() * 3);
  for (size_t i = 0; i < problem->poses.size(); ++i)
    ToArray(problem->poses[i].camera_from_map, &poses[6 * i]);
  for (size_t i = 0; i < problem->points.size(); ++i) {
    for (int k = 0; k < 3; ++k) points[3 * i + k] = problem->points[i].position[k];
  }
  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem ceres_problem(problem_options);
  ceres::HuberLoss loss(huber_px);
  for (const auto& o : problem->observations) {
    auto* cost = new ceres::AutoDiffCostFunction<ReprojectionCost, 2, 6, 3>(
        new ReprojectionCost(camera, o.pixel, o.level_scale));
    ceres_problem.AddResidualBlock(cost, &loss, &poses[6 * o.pose], &points[3 * o.point]);
  }
  for (size_t i = 0; i < problem->poses.size(); ++i) {
    if (problem->poses[i].fixed && ceres_problem.HasParameterBlock(&poses[6 * i])) {
      ceres_problem.SetParameterBlockConstant(&poses[6 * i]);
    }
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_SCHUR;
  options.max_num_iterations = iterations;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  StopCallback stop(should_stop);
  if (should_stop) options.callbacks.push_back(&stop);
  ceres::Solver::Summary ceres_summary;
  ceres::Solve(options, &ceres_problem, &ceres_summary);
  summary.iterations = static_cast<int>(ceres_summary.iterations.size());
  summary.message = ceres_summary.BriefReport();
  summary.usable = ceres_summary.IsSolutionUsable();
  if (!summary.usable) return summary;
  for (size_t i = 0; i < problem->poses.size(); ++i) {
    if (!problem->poses[i].fixed) problem->poses[i].camera_from_map = FromArray(&poses[6 * i]);
  }
  for (size_t i = 0; i < problem->points.size(); ++i) {
    problem->points[i].position =
        Eigen::Vector3d(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
  }
  summary.final_rms_px = Rms(camera, *problem);
  return summary;
}

}  // namespace sightline
