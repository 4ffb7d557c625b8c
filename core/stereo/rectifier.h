// Stereo rectification: maps computed once from the calibration (cv::stereoRectify +
// initUndistortRectifyMap), then one remap per image; a pass-through for rigs whose images are
// already rectified (KITTI, the simulator).
#pragma once

#include <opencv2/core.hpp>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/options/option_table.h"
#include "core/stereo/stereo_geometry.h"

namespace sightline {

// How to rectify. Keys "stereo.rectify.*".
struct RectifierOptions {
  // cv::stereoRectify's alpha: 0 keeps only valid pixels (zoomed in), 1 keeps every source pixel.
  double alpha = 0.0;
  // Rectify even when the rig says its images are rectified (only useful for tests).
  bool force = false;

  bool IsValid(std::string* error) const;
  static OptionTable<RectifierOptions> Describe();
};

// Turns raw stereo frames into rectified grayscale pairs.
//
//   Rectifier rectifier(options.rectify);
//   SIGHTLINE_RETURN_IF_ERROR(rectifier.Configure(*source.info().stereo));
//   cv::Mat left, right;
//   SIGHTLINE_RETURN_IF_ERROR(rectifier.Rectify(frame, &left, &right));
class Rectifier {
 public:
  explicit Rectifier(RectifierOptions options = {}) : options_(options) {}

  // Computes the maps (or none for a rectified rig). Fails with a message naming the bad field
  // when the calibration is unusable (e.g. a baseline of the wrong sign).
  Status Configure(const StereoRig& rig);
  // The rectified camera the images of Rectify() obey. Valid after Configure().
  const RectifiedStereoCamera& camera() const { return camera_; }
  // True when Rectify() remaps (false: pass-through).
  bool remaps() const { return !map_left_x_.empty(); }

  // Rectified CV_8UC1 images. Fails when an image is empty or of the wrong size.
  Status Rectify(const StereoFrame& frame, cv::Mat* left, cv::Mat* right) const;

 private:
  RectifierOptions options_;
  StereoRig rig_;
  RectifiedStereoCamera camera_;
  cv::Mat map_left_x_, map_left_y_, map_right_x_, map_right_y_;
};

}  // namespace sightline
