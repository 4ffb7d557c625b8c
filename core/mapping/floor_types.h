// The floor fit's options and result: the data of a floor calibration without the fitting
// (core/mapping/floor_plane.h), for views. The plane and the calibration themselves are
// core/common/floor.h (the floor file that stores them is core/io/floor_file.h).
#pragma once

#include <string>

#include "core/common/floor.h"
#include "core/options/option_table.h"

namespace sightline {

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

}  // namespace sightline
