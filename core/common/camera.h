// Camera models: pinhole with radial-tangential distortion, stereo rigs, RGB-D calibration.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>

#include "core/common/status.h"

namespace sightline {

// A pinhole camera with OpenCV's 5-parameter radial-tangential distortion (k1 k2 p1 p2 k3).
struct PinholeCamera {
  int width = 0;                                    // Pixels.
  int height = 0;                                   // Pixels.
  double fx = 0, fy = 0;                            // Focal lengths in pixels.
  double cx = 0, cy = 0;                            // Principal point in pixels.
  std::array<double, 5> distortion{0, 0, 0, 0, 0};  // k1 k2 p1 p2 k3; all zero = none.

  bool HasDistortion() const;
  // Checks sizes, focal lengths and principal point; names the bad field.
  Status Validate() const;
  // The 3x3 intrinsic matrix.
  Eigen::Matrix3d K() const;
  // Projects a point in the camera frame (z forward) to pixels, ignoring distortion.
  Eigen::Vector2d Project(const Eigen::Vector3d& x_in_camera) const;
  // The point at the given depth (metres along z) seen at pixel (u, v), ignoring distortion.
  Eigen::Vector3d Unproject(double u, double v, double depth_m) const;
  // A copy scaled to another resolution (e.g. 640x480 -> 320x240).
  PinholeCamera Scaled(int new_width, int new_height) const;
};

// Two cameras and the transform between them.
struct StereoRig {
  PinholeCamera left;
  PinholeCamera right;
  Eigen::Isometry3d right_from_left = Eigen::Isometry3d::Identity();
  bool rectified = false;  // True when images are already rectified (KITTI, simulator).

  // Distance between the optical centres in metres.
  double BaselineM() const { return right_from_left.translation().norm(); }
  Status Validate() const;
};

// Calibration of a registered RGB-D sensor.
struct RgbdCalibration {
  PinholeCamera color;        // Depth is registered to this camera.
  double depth_scale = 1000;  // Raw depth units per metre (TUM PNG: 5000, OpenNI: 1000).
  double max_depth_m = 10;    // Readings beyond this are treated as invalid.
};

}  // namespace sightline
