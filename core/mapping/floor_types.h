// The floor plane, its fit's options and result, and the calibration file that stores it: the
// data of a floor calibration without the fitting (core/mapping/floor_plane.h), for views and
// files.
//
// The plane is a x + b y + c z + d = 0 in the camera frame (x right, y down, z forward), with
// (a, b, c) a unit normal pointing up, towards the camera. Then a x + b y + c z + d is the height
// of a point above the floor and d is the camera's height. A point is floor when its height is
// within epsilon_floor of zero.
#pragma once

#include <Eigen/Core>
#include <string>

#include "core/common/status.h"
#include "core/options/option_table.h"

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
  // Checks that the normal is unit, points up (d > 0) and epsilon is positive.
  bool IsValid(std::string* error) const;
};

// Options of the floor plane RANSAC fit. Keys "mapping.floor.*".
struct FloorPlaneOptions {
  double epsilon_m = 0.035;          // epsilon_floor. Seed: 3.5 (relative units); read as 3.5 cm.
  double fit_threshold_m = 0.02;     // Point-to-plane distance of a RANSAC inlier [m].
  int max_iterations = 500;          // RANSAC hypotheses.
  double local_sample_size_m = 0.3;  // Half of the hypotheses draw their points from one voxel
                                     // of this size [m].
  double min_inlier_ratio = 0.03;    // Fraction of the sampled points the floor must hold.
  double max_tilt_deg = 60;          // Largest angle between the floor normal and the camera's up
                                     // axis (-y) [deg]; excludes walls.
  double min_camera_height_m = 0.1;  // Plausible camera heights [m].
  double max_camera_height_m = 3.0;
  double max_below_ratio = 0.03;  // The floor is the lowest plane: at most this fraction of the
                                  // points may lie more than 3 fit thresholds below it.
  double max_depth_m = 6.0;       // Points farther away are not used [m].
  int max_points = 20000;         // Points are subsampled evenly to at most this many.
  int seed = 1;                   // RNG seed (runs are deterministic).

  bool IsValid(std::string* error) const;
  static OptionTable<FloorPlaneOptions> Describe();
};

// What a floor fit found.
struct FloorFitResult {
  FloorPlane plane;
  int points = 0;           // Points the fit used (after subsampling).
  int inliers = 0;          // Within fit_threshold_m of the plane.
  double inlier_ratio = 0;  // inliers / points.
  double rms_m = 0;         // RMS distance of the inliers [m].
  double below_ratio = 0;   // Fraction of points clearly below the plane.
};

// What a calibration file holds.
struct FloorCalibration {
  FloorPlane plane;
  double inlier_ratio = 0;  // Of the fit that produced it, for people (0 = unknown).
  int frames = 0;           // Frames the fit used (0 = unknown).
  std::string source;       // Dataset the fit came from, for people.
};

// Writes "key: value" YAML: a, b, c, d, epsilon_m, camera_height_m, pitch_down_deg,
// inlier_ratio, frames, source.
Status WriteFloorCalibration(const FloorCalibration& calibration, const std::string& path);

// Reads a file written by WriteFloorCalibration. a, b, c, d are required (the normal is
// re-normalised); epsilon_m defaults to 0.035. Errors name the file and line.
StatusOr<FloorCalibration> ReadFloorCalibration(const std::string& path);

}  // namespace sightline
