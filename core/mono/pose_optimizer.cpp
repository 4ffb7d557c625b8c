#include "core/mono/pose_optimizer.h"

#include <cmath>

namespace sightline {

namespace {

// Applies the left increment exp([v, w]) to a pose.
Eigen::Isometry3d Increment(const Eigen::Matrix<double, 6, 1>& delta,
                            const Eigen::Isometry3d& pose) {
  Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
  const double angle = delta.tail<3>().norm();
  if (angle > 1e-12) {
    step.linear() = Eigen::AngleAxisd(angle, delta.tail<3>() / angle).toRotationMatrix();
  }
  step.translation() = delta.head<3>();
  Eigen::Isometry3d out = step * pose;
  // Re-orthonormalise against drift.
  out.linear() = Eigen::Quaterniond(out.rotation()).normalized().toRotationMatrix();
  return out;
}

// Residual (pixels / level scale) of one observation; false when behind the camera.
bool Residual(const PinholeCamera& camera, const Eigen::Isometry3d& pose, const PoseObservation& o,
              Eigen::Vector2d* r, Eigen::Matrix<double, 2, 6>* jacobian) {
  const Eigen::Vector3d p = pose * o.x_in_map;
  if (p.z() <= 1e-9) return false;
  const double iz = 1.0 / p.z();
  const Eigen::Vector2d proj(camera.fx * p.x() * iz + camera.cx,
                             camera.fy * p.y() * iz + camera.cy);
  *r = (proj - o.pixel) / o.level_scale;
  if (jacobian) {
    Eigen::Matrix<double, 2, 3> dproj;
    dproj << camera.fx * iz, 0, -camera.fx * p.x() * iz * iz, 0, camera.fy * iz,
        -camera.fy * p.y() * iz * iz;
    Eigen::Matrix<double, 3, 6> dp;
    dp.leftCols<3>().setIdentity();
    dp.rightCols<3>() << 0, p.z(), -p.y(), -p.z(), 0, p.x(), p.y(), -p.x(), 0;
    *jacobian = dproj * dp / o.level_scale;
  }
  return true;
}

}  // namespace

PoseEstimate OptimizePose(const PinholeCamera& camera, const Eigen::Isometry3d& initial,
                          const std::vector<PoseObservation>& observations, double huber_px,
                          double outlier_px, int rounds, int iterations) {
  PoseEstimate out;
  out.camera_from_map = initial;
  out.inliers.assign(observations.size(), true);
  if (observations.size() < 4) {
    out.inliers.assign(observations.size(), false);
    return out;
  }
  Eigen::Isometry3d pose = initial;
  for (int round = 0; round < rounds; ++round) {
    for (int it = 0; it < iterations; ++it) {
      Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
      Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
      int used = 0;
      for (size_t i = 0; i < observations.size(); ++i) {
        if (!out.inliers[i]) continue;
        Eigen::Vector2d r;
        Eigen::Matrix<double, 2, 6> J;
        if (!Residual(camera, pose, observations[i], &r, &J)) continue;
        const double e = r.norm();
        const double w = e <= huber_px ? 1.0 : huber_px / e;
        H += w * J.transpose() * J;
        g += w * J.transpose() * r;
        ++used;
      }
      if (used < 4) break;
      H.diagonal() *= 1.0 + 1e-6;
      const Eigen::Matrix<double, 6, 1> delta = H.ldlt().solve(-g);
      if (!delta.allFinite()) break;
      pose = Increment(delta, pose);
      if (delta.norm() < 1e-9) break;
    }
    // Re-classify: the last round's classification is the result.
    for (size_t i = 0; i < observations.size(); ++i) {
      Eigen::Vector2d r;
      out.inliers[i] =
          Residual(camera, pose, observations[i], &r, nullptr) && r.norm() <= outlier_px;
    }
  }
  double sum = 0;
  out.inlier_count = 0;
  for (size_t i = 0; i < observations.size(); ++i) {
    if (!out.inliers[i]) continue;
    Eigen::Vector2d r;
    Residual(camera, pose, observations[i], &r, nullptr);
    sum += r.squaredNorm();
    ++out.inlier_count;
  }
  out.rms_px = out.inlier_count > 0 ? std::sqrt(sum / out.inlier_count) : 0;
  out.camera_from_map = pose;
  return out;
}

}  // namespace sightline
