#include "core/stereo/motion_refiner.h"

#include <Eigen/Cholesky>
#include <cmath>

#include "core/stereo/option_check.h"
#include "core/stereo/reprojection.h"

namespace sightline {

using stereo_internal::CenterWeight;
using stereo_internal::Invalid;
using stereo_internal::Skew;
using stereo_internal::StereoHuberWeights;
using stereo_internal::StereoResidual;

bool MotionRefinerOptions::IsValid(std::string* error) const {
  if (max_iterations < 0) return Invalid(error, "stereo.refine.max_iterations must be >= 0");
  if (!(huber_px > 0)) return Invalid(error, "stereo.refine.huber_px must be > 0");
  if (!(min_step > 0)) return Invalid(error, "stereo.refine.min_step must be > 0");
  return true;
}

OptionTable<MotionRefinerOptions> MotionRefinerOptions::Describe() {
  using O = MotionRefinerOptions;
  return OptionTable<O>("stereo.refine")
      .Int("max_iterations", &O::max_iterations, "", 0, 100, 1,
           "Gauss-Newton iterations on the reprojection error; 0 keeps the RANSAC motion.")
      .Double("huber_px", &O::huber_px, "px", 0.01, 100, 0.1,
              "Huber threshold of the robust weight.")
      .Double("min_step", &O::min_step, "", 1e-12, 1, 1e-8,
              "Stop when the update is smaller (radians or metres).")
      .Bool("symmetric", &O::symmetric,
            "Also project current points into the previous images (uses both depths).")
      .Bool("joint_points", &O::joint_points,
            "Refine the 3D points with the motion (two-frame bundle adjustment); removes the "
            "depth bias of triangulation.")
      .Bool("center_weighting", &O::center_weighting,
            "Weight observations by 1 / (|u - cx| / cx + 0.05) (libviso2), favouring the centre.");
}

namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// The pose change of a Gauss-Newton step: translation delta[0..2], rotation vector delta[3..5].
Eigen::Isometry3d PoseIncrement(const Vector6d& delta) {
  Eigen::Isometry3d update = Eigen::Isometry3d::Identity();
  const double angle = delta.tail<3>().norm();
  if (angle > 1e-12) {
    update.linear() = Eigen::AngleAxisd(angle, delta.tail<3>() / angle).toRotationMatrix();
  }
  update.translation() = delta.head<3>();
  return update;
}

// Re-orthonormalises the rotation against drift from repeated products.
void Orthonormalize(Eigen::Isometry3d* pose) {
  Eigen::Quaterniond q(pose->rotation());
  q.normalize();
  pose->linear() = q.toRotationMatrix();
}

// Adds the residuals of point y (in the frame of `obs`) with dy/d(delta) = dy_ddelta.
void AddTerm(const RectifiedStereoCamera& c, const Eigen::Vector3d& y,
             const Eigen::Matrix<double, 3, 6>& dy_ddelta, const StereoObservation& obs,
             double huber, Matrix6d* h, Vector6d* g, double* cost, int* count) {
  if (!(y.z() > 1e-3)) return;
  const double iz = 1.0 / y.z();
  const double fx = c.f * iz;
  const double ul = c.f * y.x() * iz + c.cx;
  const double ur = c.f * (y.x() - c.baseline_m) * iz + c.cx;
  const double v = c.f * y.y() * iz + c.cy;
  const double r[4] = {ul - obs.u_left, v - obs.v, ur - obs.u_right, v - obs.v};
  Eigen::Matrix<double, 4, 3> dr_dy;
  dr_dy << fx, 0, -fx * y.x() * iz,              //
      0, fx, -fx * y.y() * iz,                   //
      fx, 0, -fx * (y.x() - c.baseline_m) * iz,  //
      0, fx, -fx * y.y() * iz;
  const Eigen::Matrix<double, 4, 6> j = dr_dy * dy_ddelta;
  for (int k = 0; k < 4; k += 2) {
    // Weight the (u, v) pair of each image together.
    const double e = std::sqrt(r[k] * r[k] + r[k + 1] * r[k + 1]);
    const double w = e <= huber ? 1.0 : huber / e;
    for (int m = k; m < k + 2; ++m) {
      *h += w * j.row(m).transpose() * j.row(m);
      *g += w * j.row(m).transpose() * r[m];
    }
    *cost += r[k] * r[k] + r[k + 1] * r[k + 1];
    *count += 2;
  }
}

}  // namespace

RefinementSummary MotionRefiner::RefineJoint(
    const RectifiedStereoCamera& camera, const std::vector<StereoCorrespondence>& correspondences,
    const std::vector<int>& indices, Eigen::Isometry3d* current_from_previous) const {
  RefinementSummary summary;
  summary.initial_rms_px =
      RmsReprojectionPx(camera, correspondences, indices, *current_from_previous);
  summary.final_rms_px = summary.initial_rms_px;
  if (indices.size() < 3) return summary;
  const size_t n = indices.size();
  std::vector<Eigen::Vector3d> points(n);
  for (size_t k = 0; k < n; ++k)
    points[k] = correspondences[static_cast<size_t>(indices[k])].x_previous;
  std::vector<Eigen::Matrix3d> hll_inv(n);
  std::vector<Eigen::Matrix<double, 6, 3>> hpl(n);
  std::vector<Eigen::Vector3d> gl(n);
  std::vector<unsigned char> valid(n);
  Eigen::Isometry3d t = *current_from_previous;
  for (int it = 0; it < options_.max_iterations; ++it) {
    Matrix6d s = Matrix6d::Zero();
    Vector6d b = Vector6d::Zero();
    const Eigen::Matrix3d rotation = t.rotation();
    int used = 0;
    for (size_t k = 0; k < n; ++k) {
      const StereoCorrespondence& c = correspondences[static_cast<size_t>(indices[k])];
      const Eigen::Vector3d& x = points[k];
      const Eigen::Vector3d y = t * x;
      Eigen::Vector4d r0, r1;
      Eigen::Matrix<double, 4, 3> a0, a1;
      valid[k] = StereoResidual(camera, x, c.previous, &r0, &a0) &&
                 StereoResidual(camera, y, c.current, &r1, &a1);
      if (!valid[k]) continue;
      ++used;
      Eigen::Vector4d w0 = StereoHuberWeights(r0, options_.huber_px);
      Eigen::Vector4d w1 = StereoHuberWeights(r1, options_.huber_px);
      if (options_.center_weighting) {
        w0 *= CenterWeight(camera, c.previous.u_left);
        w1 *= CenterWeight(camera, c.current.u_left);
      }
      Eigen::Matrix<double, 3, 6> dy_dpose;
      dy_dpose << Eigen::Matrix3d::Identity(), -Skew(y);
      const Eigen::Matrix<double, 4, 6> jp = a1 * dy_dpose;
      const Eigen::Matrix<double, 4, 3> jl = a1 * rotation;
      const Eigen::Matrix<double, 6, 4> jpw = jp.transpose() * w1.asDiagonal();
      const Matrix6d hpp = jpw * jp;
      hpl[k] = jpw * jl;
      Eigen::Matrix3d hll =
          a0.transpose() * w0.asDiagonal() * a0 + jl.transpose() * w1.asDiagonal() * jl;
      hll += 1e-9 * Eigen::Matrix3d::Identity();
      const Vector6d gp = jpw * r1;
      gl[k] = a0.transpose() * w0.asDiagonal() * r0 + jl.transpose() * w1.asDiagonal() * r1;
      hll_inv[k] = hll.inverse();
      s += hpp - hpl[k] * hll_inv[k] * hpl[k].transpose();
      b += gp - hpl[k] * hll_inv[k] * gl[k];
    }
    if (used < 3) break;
    Eigen::LDLT<Matrix6d> ldlt(s);
    if (ldlt.info() != Eigen::Success) break;
    const Vector6d delta = -ldlt.solve(b);
    if (!delta.allFinite()) break;
    for (size_t k = 0; k < n; ++k) {
      if (valid[k]) points[k] -= hll_inv[k] * (gl[k] + hpl[k].transpose() * delta);
    }
    t = PoseIncrement(delta) * t;
    summary.iterations = it + 1;
    if (delta.norm() < options_.min_step) {
      summary.converged = true;
      break;
    }
  }
  Orthonormalize(&t);
  // RMS over all four observations with the refined points.
  double sum = 0;
  int count = 0;
  for (size_t k = 0; k < n; ++k) {
    const StereoCorrespondence& c = correspondences[static_cast<size_t>(indices[k])];
    Eigen::Vector4d r0, r1;
    Eigen::Matrix<double, 4, 3> a;
    if (!StereoResidual(camera, points[k], c.previous, &r0, &a) ||
        !StereoResidual(camera, t * points[k], c.current, &r1, &a)) {
      continue;
    }
    sum += r0.squaredNorm() + r1.squaredNorm();
    count += 8;
  }
  summary.final_rms_px = count > 0 ? std::sqrt(sum / count) : summary.initial_rms_px;
  *current_from_previous = t;
  return summary;
}

double MotionRefiner::RmsReprojectionPx(const RectifiedStereoCamera& camera,
                                        const std::vector<StereoCorrespondence>& correspondences,
                                        const std::vector<int>& indices,
                                        const Eigen::Isometry3d& current_from_previous) {
  double sum = 0;
  int n = 0;
  for (int i : indices) {
    const StereoCorrespondence& c = correspondences[static_cast<size_t>(i)];
    const Eigen::Vector3d y = current_from_previous * c.x_previous;
    if (!(y.z() > 1e-3)) continue;
    const Eigen::Vector2d l = camera.ProjectLeft(y), r = camera.ProjectRight(y);
    sum += (l - Eigen::Vector2d(c.current.u_left, c.current.v)).squaredNorm() +
           (r - Eigen::Vector2d(c.current.u_right, c.current.v)).squaredNorm();
    n += 4;
  }
  return n > 0 ? std::sqrt(sum / n) : 0.0;
}

RefinementSummary MotionRefiner::Refine(const RectifiedStereoCamera& camera,
                                        const std::vector<StereoCorrespondence>& correspondences,
                                        const std::vector<int>& indices,
                                        Eigen::Isometry3d* current_from_previous) const {
  if (options_.joint_points)
    return RefineJoint(camera, correspondences, indices, current_from_previous);
  RefinementSummary summary;
  summary.initial_rms_px =
      RmsReprojectionPx(camera, correspondences, indices, *current_from_previous);
  summary.final_rms_px = summary.initial_rms_px;
  if (indices.size() < 3) return summary;
  Eigen::Isometry3d t = *current_from_previous;
  for (int it = 0; it < options_.max_iterations; ++it) {
    Matrix6d h = Matrix6d::Zero();
    Vector6d g = Vector6d::Zero();
    double cost = 0;
    int count = 0;
    const Eigen::Matrix3d rt = t.rotation().transpose();
    for (int i : indices) {
      const StereoCorrespondence& c = correspondences[static_cast<size_t>(i)];
      // Forward: y = exp(delta) * T * x_prev, dy/d(rho, phi) = [I, -[y]x].
      const Eigen::Vector3d y = t * c.x_previous;
      Eigen::Matrix<double, 3, 6> jf;
      jf << Eigen::Matrix3d::Identity(), -Skew(y);
      AddTerm(camera, y, jf, c.current, options_.huber_px, &h, &g, &cost, &count);
      if (options_.symmetric) {
        // Backward: z = T^-1 exp(-delta) x_cur, dz/d(rho, phi) = R^T [-I, [x_cur]x].
        const Eigen::Vector3d z = t.inverse() * c.x_current;
        Eigen::Matrix<double, 3, 6> jb;
        jb << -rt, rt * Skew(c.x_current);
        AddTerm(camera, z, jb, c.previous, options_.huber_px, &h, &g, &cost, &count);
      }
    }
    if (count < 6) break;
    Eigen::LDLT<Matrix6d> ldlt(h);
    if (ldlt.info() != Eigen::Success) break;
    const Vector6d delta = -ldlt.solve(g);
    if (!delta.allFinite()) break;
    t = PoseIncrement(delta) * t;
    summary.iterations = it + 1;
    if (delta.norm() < options_.min_step) {
      summary.converged = true;
      break;
    }
  }
  Orthonormalize(&t);
  summary.final_rms_px = RmsReprojectionPx(camera, correspondences, indices, t);
  *current_from_previous = t;
  if (summary.iterations == options_.max_iterations) summary.converged = true;
  return summary;
}

}  // namespace sightline
