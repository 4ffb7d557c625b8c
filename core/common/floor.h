// The floor plane model (seed 000, section 4.3.2) and a floor calibration, shared by the mapping
// estimators that fit and use it (core/mapping/floor_plane.h), the views that draw it and the
// floor file (core/io/floor_file.h) that stores it.
//
// The plane is a x + b y + c z + d = 0 in the camera frame (x right, y down, z forward), with
// (a, b, c) a unit normal pointing up, towards the camera. Then a x + b y + c z + d is the height
// of a point above the floor and d is the camera's height. A point is floor when its height is
// within epsilon_floor of zero.
#pragma once

#include <Eigen/Core>
#include <string>

namespace sightline {

// A calibrated floor plane in the camera frame.
struct FloorPlane {
  Eigen::Vector3d normal = Eigen::Vector3d(0, -1, 0);  // (a, b, c): unit, pointing up.
  double d = 0;              // Offset; equals the camera height above the floor [m].
  double epsilon_m = 0.035;  // epsilon_floor: floor tolerance on the height [m].

  // Height of a camera-frame point above the floor [m] (negative below it).
  double HeightOf(const Eigen::Vector3d& x_in_camera) const { return normal.dot(x_in_camera) + d; }
  // The camera's height above the floor [m].
  double CameraHeightM() const { return d; }
  // Angle between the camera's optical axis and the floor [deg]; positive = looking down.
  double PitchDownDeg() const;
  // The rotation base_from_camera of a base on this floor facing where the camera looks: its
  // rows are forward (the optical axis projected onto the floor), left and up. False when the
  // camera looks (almost) straight down and has no forward direction.
  bool BaseFromCameraRotation(Eigen::Matrix3d* base_from_camera) const;
  // Checks that the normal is unit, points up (d > 0) and epsilon is positive.
  bool IsValid(std::string* error) const;
};

// A calibrated floor: what a floor file holds (core/io/floor_file.h) and what a floor
// calibration (FloorCalibrator in core/mapping/floor_plane.h) produces.
struct FloorCalibration {
  FloorPlane plane;
  double inlier_ratio = 0;  // Of the fit that produced it, for people (0 = unknown).
  int frames = 0;           // Frames the fit used (0 = unknown).
  std::string source;       // Dataset the fit came from, for people.
};

// One line for a log: "calibrated from 5 frames: camera 0.800 m above the floor, pitched 10.0 deg
// down, 92 % inliers".
std::string DescribeFloorCalibration(const FloorCalibration& calibration);

}  // namespace sightline
