#include "core/common/floor.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace sightline {
namespace {

bool Invalid(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

}  // namespace

double FloorPlane::PitchDownDeg() const {
  return std::asin(std::clamp(-normal.z(), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

bool FloorPlane::BaseFromCameraRotation(Eigen::Matrix3d* base_from_camera) const {
  const Eigen::Vector3d optical_axis(0, 0, 1);
  Eigen::Vector3d forward = optical_axis - optical_axis.dot(normal) * normal;
  if (forward.norm() < 0.1) return false;
  forward.normalize();
  base_from_camera->row(0) = forward.transpose();
  base_from_camera->row(1) = normal.cross(forward).transpose();
  base_from_camera->row(2) = normal.transpose();
  return true;
}

bool FloorPlane::IsValid(std::string* error) const {
  if (!normal.allFinite() || std::abs(normal.norm() - 1.0) > 1e-6) {
    return Invalid(error, "floor plane normal (a, b, c) must be a finite unit vector");
  }
  if (!(d > 0) || !std::isfinite(d)) {
    return Invalid(error,
                   "floor plane d (camera height) must be positive, with (a, b, c) "
                   "pointing up towards the camera");
  }
  if (!(epsilon_m > 0) || !std::isfinite(epsilon_m)) {
    return Invalid(error, "floor plane epsilon_m must be positive and finite");
  }
  return true;
}

std::string DescribeFloorCalibration(const FloorCalibration& calibration) {
  char text[160];
  std::snprintf(text, sizeof(text),
                "calibrated from %d frames: camera %.3f m above the floor, pitched %.1f deg "
                "down, %.0f %% inliers",
                calibration.frames, calibration.plane.CameraHeightM(),
                calibration.plane.PitchDownDeg(), 100 * calibration.inlier_ratio);
  return text;
}

}  // namespace sightline
