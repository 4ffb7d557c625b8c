// Bundle adjustment of keyframe poses and map points on the reprojection error with a robust
// (Huber) loss. Ceres stays inside bundle_adjustment.cpp.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/common/camera.h"

namespace sightline {

// A bundle-adjustment problem copied out of the map, so the map need not stay locked while it
// is solved.
struct BundleProblem {
  struct Pose {
    int64_t keyframe = -1;
    Eigen::Isometry3d camera_from_map = Eigen::Isometry3d::Identity();
    bool fixed = false;
  };
  struct Point {
    int64_t id = -1;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
  };
  struct Observation {
    int pose = 0;   // Index into poses.
    int point = 0;  // Index into points.
    Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
    double level_scale = 1;
  };
  std::vector<Pose> poses;
  std::vector<Point> points;
  std::vector<Observation> observations;
};

// What the solver did.
struct BundleSummary {
  int iterations = 0;
  double initial_rms_px = 0;  // Over all observations, before.
  double final_rms_px = 0;    // After.
  bool usable = false;        // The solver produced a finite result.
  std::string message;        // The solver's own report, one line.
};

// Optimises the free poses and every point in place. `iterations` 0 leaves everything as it is.
// `should_stop` (optional) is asked after every iteration; true ends the solve there with the
// state reached (PTAM's mapper abandons idle-time adjustment when a keyframe arrives).
BundleSummary SolveBundle(const PinholeCamera& camera, BundleProblem* problem, int iterations,
                          double huber_px, const std::function<bool()>& should_stop = {});

// Reprojection error of one observation in the current state [px, unscaled]; infinity behind
// the camera.
double ReprojectionErrorPx(const PinholeCamera& camera, const BundleProblem& problem,
                           const BundleProblem::Observation& o);

}  // namespace sightline
