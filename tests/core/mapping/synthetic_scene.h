// A tiny ray caster for mapping tests: a flat floor (z = 0) and vertical wall segments seen by a
// pinhole depth camera, with optional Gaussian depth noise. Independent of core/sim, so the
// algorithmic tests check the mapping code against geometry they construct themselves.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/camera.h"
#include "core/common/floor.h"

namespace sightline::testing {

// A vertical wall between two floor points, from z = 0 up to height_m.
struct SyntheticWall {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  double height_m = 2.5;
};

// A depth camera on a robot: position on the floor, heading, height and downward pitch.
struct SyntheticView {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // World x, y [m].
  double heading_rad = 0;                              // CCW from world x.
  double height_m = 0.8;                               // Camera above the floor [m].
  double pitch_down_rad = 0.1;                         // Optical axis below horizontal.
  double roll_rad = 0;                                 // About the optical axis.
};

// A 640 x 480 Kinect-like camera (fx = fy = 525), scaled to width x height.
PinholeCamera KinectCamera(int width = 320, int height = 240);

// world_from_camera rotation of a view (camera x right, y down, z forward).
Eigen::Matrix3d WorldFromCameraRotation(const SyntheticView& view);

// The floor plane (z = 0) in the camera frame of a view.
FloorPlane FloorPlaneOf(const SyntheticView& view);

// Renders metric depth (CV_32FC1, NaN where nothing within max_depth_m is hit). `noise_sigma_m`
// adds depth noise sigma(z) = noise_sigma_m * z^2 (Kinect-like), seeded by `seed`.
cv::Mat RenderDepth(const PinholeCamera& camera, const SyntheticView& view,
                    const std::vector<SyntheticWall>& walls, bool with_floor = true,
                    double max_depth_m = 8.0, double noise_sigma_m = 0.0, unsigned seed = 1);

// Walls of a straight corridor along x from x0 to x1, `width_m` wide, centred on y = 0, closed at
// x1 by an end wall.
std::vector<SyntheticWall> Corridor(double x0, double x1, double width_m);

}  // namespace sightline::testing
