// The stereo reprojection pieces the estimators share (two-frame refinement, the disparity-offset
// measurement, the window adjustment): the residual of a point against a stereo observation with
// its Jacobian, per-image Huber weights, libviso2's centre weight and the cross-product matrix.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "core/stereo/stereo_correspondence.h"
#include "core/stereo/stereo_geometry.h"

namespace sightline::stereo_internal {

// [v]x: Skew(v) * w == v.cross(w).
inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

// Residuals (left u, v; right u, v) of point y (camera frame) against `obs` and their derivative
// in y. False when y is not in front of the camera.
inline bool StereoResidual(const RectifiedStereoCamera& c, const Eigen::Vector3d& y,
                           const StereoObservation& obs, Eigen::Vector4d* r,
                           Eigen::Matrix<double, 4, 3>* dr_dy) {
  if (!(y.z() > 1e-3)) return false;
  const double iz = 1.0 / y.z();
  const double fx = c.f * iz;
  const double v = c.f * y.y() * iz + c.cy;
  *r << c.f * y.x() * iz + c.cx - obs.u_left, v - obs.v,
      c.f * (y.x() - c.baseline_m) * iz + c.cx - obs.u_right, v - obs.v;
  *dr_dy << fx, 0, -fx * y.x() * iz,             //
      0, fx, -fx * y.y() * iz,                   //
      fx, 0, -fx * (y.x() - c.baseline_m) * iz,  //
      0, fx, -fx * y.y() * iz;
  return true;
}

// Huber weights of the left and right image of a StereoResidual, as a diagonal.
inline Eigen::Vector4d StereoHuberWeights(const Eigen::Vector4d& r, double huber) {
  const double el = std::hypot(r(0), r(1)), er = std::hypot(r(2), r(3));
  const double wl = el <= huber ? 1.0 : huber / el, wr = er <= huber ? 1.0 : huber / er;
  return {wl, wl, wr, wr};
}

// libviso2's weight of an observation at left column u: 1 / (|u - cx| / cx + 0.05), favouring
// the image centre, where lens and rectification errors are smallest.
inline double CenterWeight(const RectifiedStereoCamera& c, double u) {
  return 1.0 / (std::abs(u - c.cx) / c.cx + 0.05);
}

}  // namespace sightline::stereo_internal
