#include "core/sim/sensor_options.h"

#include <cmath>

namespace sightline::sim {
namespace {

PinholeCamera CenteredCamera(int width, int height, double focal) {
  PinholeCamera c;
  c.width = width;
  c.height = height;
  c.fx = c.fy = focal;
  c.cx = 0.5 * (width - 1);
  c.cy = 0.5 * (height - 1);
  return c;
}

bool CheckSize(int width, int height, const std::string& prefix, std::string* error) {
  if (width < 16 || width > 8192 || height < 16 || height > 8192) {
    if (error) {
      *error = prefix + ".width x height = " + std::to_string(width) + "x" +
               std::to_string(height) + ": each side must lie in [16, 8192] pixels";
    }
    return false;
  }
  return true;
}

bool CheckFocal(double focal, const std::string& prefix, std::string* error) {
  if (!(focal >= 10 && focal <= 20000)) {
    if (error)
      *error = prefix + ".focal_px = " + std::to_string(focal) + ": must lie in [10, 20000]";
    return false;
  }
  return true;
}

}  // namespace

PinholeCamera RgbdSensorOptions::Camera() const {
  const PinholeCamera full = CenteredCamera(640, 480, focal_px);
  return resolution == "320x240" ? full.Scaled(320, 240) : full;
}

bool RgbdSensorOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "sim.rgbd." + m;
    return false;
  };
  if (resolution != "640x480" && resolution != "320x240") {
    return fail("resolution = '" + resolution + "': must be 640x480 or 320x240 (Kinect v1)");
  }
  if (!CheckFocal(focal_px, "sim.rgbd", error)) return false;
  if (!(min_depth_m >= 0.05 && min_depth_m < max_depth_m)) {
    return fail("min_depth_m must lie in [0.05, max_depth_m)");
  }
  if (!(max_depth_m <= 13.0)) {
    return fail("max_depth_m must be <= 13 m (16-bit PNG depth at 5000 units per metre)");
  }
  if (!(max_incidence_deg > 0 && max_incidence_deg <= 90)) {
    return fail("max_incidence_deg must lie in (0, 90]");
  }
  return true;
}

OptionTable<RgbdSensorOptions> RgbdSensorOptions::Describe() {
  using O = RgbdSensorOptions;
  return OptionTable<O>("rgbd")
      .Choice("resolution", &O::resolution, {"640x480", "320x240"},
              "Image size; 320x240 is the size the Kinect mapping seed uses.")
      .Double("focal_px", &O::focal_px, "px", 10, 20000, 1, "fx = fy at 640x480.")
      .Double("min_depth_m", &O::min_depth_m, "m", 0.05, 13, 0.05, "Nearest depth reading.")
      .Double("max_depth_m", &O::max_depth_m, "m", 0.1, 13, 0.1, "Farthest depth reading.")
      .Double("max_incidence_deg", &O::max_incidence_deg, "deg", 1, 90, 1,
              "No depth where the ray meets the surface at a larger angle from its normal.");
}

StereoRig StereoSensorOptions::Rig() const {
  StereoRig rig;
  rig.left = rig.right = CenteredCamera(width, height, focal_px);
  rig.right_from_left = Eigen::Isometry3d::Identity();
  rig.right_from_left.translation() = Eigen::Vector3d(-baseline_m, 0, 0);
  rig.rectified = true;
  return rig;
}

bool StereoSensorOptions::IsValid(std::string* error) const {
  if (!CheckSize(width, height, "sim.stereo", error)) return false;
  if (!CheckFocal(focal_px, "sim.stereo", error)) return false;
  if (!(baseline_m > 0.001 && baseline_m <= 5)) {
    if (error) {
      *error = "sim.stereo.baseline_m = " + std::to_string(baseline_m) +
               ": must lie in (0.001, 5] m (the right camera sits at +baseline along x)";
    }
    return false;
  }
  return true;
}

OptionTable<StereoSensorOptions> StereoSensorOptions::Describe() {
  using O = StereoSensorOptions;
  return OptionTable<O>("stereo")
      .Int("width", &O::width, "px", 16, 8192, 1, "Image width (KITTI: 1241).")
      .Int("height", &O::height, "px", 16, 8192, 1, "Image height (KITTI: 376).")
      .Double("focal_px", &O::focal_px, "px", 10, 20000, 1, "fx = fy (KITTI: 718.856).")
      .Double("baseline_m", &O::baseline_m, "m", 0.001, 5, 0.01,
              "Distance between the optical centres (KITTI: 0.54).");
}

PinholeCamera MonoSensorOptions::Camera() const { return CenteredCamera(width, height, focal_px); }

bool MonoSensorOptions::IsValid(std::string* error) const {
  return CheckSize(width, height, "sim.mono", error) && CheckFocal(focal_px, "sim.mono", error);
}

OptionTable<MonoSensorOptions> MonoSensorOptions::Describe() {
  using O = MonoSensorOptions;
  return OptionTable<O>("mono")
      .Int("width", &O::width, "px", 16, 8192, 1, "Image width.")
      .Int("height", &O::height, "px", 16, 8192, 1, "Image height.")
      .Double("focal_px", &O::focal_px, "px", 10, 20000, 1, "fx = fy.");
}

NoiseModel NoiseOptions::Effective() const {
  NoiseModel m;
  m.ir_baseline_m = ir_baseline_m;
  if (profile == "none") return m;
  const double k = profile == "noisy" ? 2.0 : 1.0;
  m.depth_sigma_coeff = k * depth_sigma_coeff;
  m.disparity_step_px = disparity_step_px;
  m.color_sigma = k * color_sigma;
  m.grey_sigma = k * grey_sigma;
  return m;
}

bool NoiseOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "sim.noise." + m;
    return false;
  };
  if (profile != "none" && profile != "kinect" && profile != "noisy") {
    return fail("profile = '" + profile + "': must be none, kinect or noisy");
  }
  if (!(depth_sigma_coeff >= 0 && depth_sigma_coeff <= 0.1)) {
    return fail("depth_sigma_coeff must lie in [0, 0.1] 1/m");
  }
  if (!(disparity_step_px >= 0 && disparity_step_px <= 2)) {
    return fail("disparity_step_px must lie in [0, 2] px");
  }
  if (!(ir_baseline_m > 0.001 && ir_baseline_m <= 1))
    return fail("ir_baseline_m must lie in (0.001, 1] m");
  if (!(color_sigma >= 0 && color_sigma <= 50)) return fail("color_sigma must lie in [0, 50]");
  if (!(grey_sigma >= 0 && grey_sigma <= 50)) return fail("grey_sigma must lie in [0, 50]");
  return true;
}

OptionTable<NoiseOptions> NoiseOptions::Describe() {
  using O = NoiseOptions;
  return OptionTable<O>("noise")
      .Choice("profile", &O::profile, {"none", "kinect", "noisy"},
              "none: exact depth and clean images; kinect: the Kinect v1 model; noisy: twice "
              "the kinect sigmas.")
      .Double("depth_sigma_coeff", &O::depth_sigma_coeff, "1/m", 0, 0.1, 0.0001,
              "Depth noise sigma_z = coeff * z^2 (Khoshelham and Elberink 2012: 1.425e-3).")
      .Double("disparity_step_px", &O::disparity_step_px, "px", 0, 2, 0.005,
              "Disparity quantisation of the depth sensor (Kinect: 1/8 pixel); 0 = none.")
      .Double("ir_baseline_m", &O::ir_baseline_m, "m", 0.002, 1, 0.005,
              "Projector-camera baseline of the depth model (Kinect: 0.075 m).")
      .Double("color_sigma", &O::color_sigma, "", 0, 50, 0.5,
              "Gaussian noise of the colour image, grey levels.")
      .Double("grey_sigma", &O::grey_sigma, "", 0, 50, 0.5,
              "Gaussian noise of the stereo and mono images, grey levels.");
}

}  // namespace sightline::sim
