// The simulated sensors: a Kinect-v1-like RGB-D camera, a rectified stereo pair, a monocular
// camera, and the noise profiles that make them realistic.
#pragma once

#include <string>

#include "core/common/camera.h"
#include "core/options/option_table.h"

namespace sightline::sim {

// A Kinect v1 (registered colour and depth). Depth is z along the optical axis, as the Kinect
// reports it; readings outside [min_depth_m, max_depth_m] or at grazing incidence are dropped.
struct RgbdSensorOptions {
  std::string resolution = "640x480";  // "640x480" or "320x240" (the seed's mapping size).
  double focal_px = 525.0;             // fx = fy at 640x480 (scaled with the resolution).
  double min_depth_m = 0.5;            // Nearest reading, metres.
  double max_depth_m = 4.5;            // Farthest reading, metres.
  double max_incidence_deg = 75.0;     // No reading where the ray meets the surface flatter.

  // The colour (= depth) camera: principal point at the image centre.
  PinholeCamera Camera() const;
  bool IsValid(std::string* error) const;
  static OptionTable<RgbdSensorOptions> Describe();
};

// A rectified stereo pair with identical intrinsics; the right camera sits baseline_m along the
// left camera's x axis. EuRoC-like by default; KITTI: 1241x376, focal 718.856, baseline 0.54.
struct StereoSensorOptions {
  int width = 752;           // Pixels.
  int height = 480;          // Pixels.
  double focal_px = 458.0;   // fx = fy, pixels.
  double baseline_m = 0.11;  // Metres, > 0.

  // The rig (rectified, right_from_left = translation (-baseline, 0, 0)).
  StereoRig Rig() const;
  bool IsValid(std::string* error) const;
  static OptionTable<StereoSensorOptions> Describe();
};

// A monocular camera (the arm's PlayStation-Eye-like camera in seed 004).
struct MonoSensorOptions {
  int width = 640;          // Pixels.
  int height = 480;         // Pixels.
  double focal_px = 525.0;  // fx = fy, pixels.

  PinholeCamera Camera() const;
  bool IsValid(std::string* error) const;
  static OptionTable<MonoSensorOptions> Describe();
};

// The effective noise of one recording (after the profile is applied).
struct NoiseModel {
  double depth_sigma_coeff = 0;  // sigma_z = coeff * z^2 (1/m); 0 = exact depth.
  double disparity_step_px = 0;  // Kinect disparity quantisation; 0 = none.
  double ir_baseline_m = 0.075;  // Projector-camera baseline of the disparity model, metres.
  double color_sigma = 0;        // Colour image noise, grey levels (0-255).
  double grey_sigma = 0;         // Stereo and mono image noise, grey levels.
};

// Noise profiles: "none" (exact depth, clean images), "kinect" (the model below; default) and
// "noisy" (every sigma doubled). The Kinect depth model follows Khoshelham and Elberink (2012):
// disparity d = f b / z with Gaussian noise of coeff * f * b pixels (so sigma_z = coeff * z^2),
// quantised to 1/8 pixel as the Kinect does, then z = f b / d.
struct NoiseOptions {
  std::string profile = "kinect";       // "none", "kinect" or "noisy".
  double depth_sigma_coeff = 1.425e-3;  // 1/m, Khoshelham and Elberink (2012).
  double disparity_step_px = 0.125;     // Pixels (at 640x480).
  double ir_baseline_m = 0.075;         // Metres.
  double color_sigma = 2.0;             // Grey levels.
  double grey_sigma = 1.5;              // Grey levels.

  // The model the profile selects.
  NoiseModel Effective() const;
  bool IsValid(std::string* error) const;
  static OptionTable<NoiseOptions> Describe();
};

}  // namespace sightline::sim
