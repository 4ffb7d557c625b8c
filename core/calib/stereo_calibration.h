// Stereo chessboard calibration: each camera on its own (mono_calibration.h), then the rig with
// cv::stereoCalibrate holding the intrinsics fixed, per-pair errors, the baseline and the
// rectification (cv::stereoRectify) that OpenCV's stereo files carry.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/calib/mono_calibration.h"

namespace sightline {

// How to calibrate a stereo rig. Keys "calib.stereo.*".
struct StereoCalibrationOptions {
  int min_pairs = 5;           // Fewer usable pairs is an error.
  bool fix_intrinsics = true;  // Keep each camera's own calibration; estimate only R and T.
  // A pair whose RMS error in either image exceeds this is dropped and the rig recalibrated
  // without it (0 = keep every pair), pixels.
  double max_pair_error_px = 2.0;
  // cv::stereoRectify's free scaling: -1 default, 0 valid pixels only, 1 all source pixels.
  double rectify_alpha = -1;

  bool IsValid(std::string* error) const;
  static OptionTable<StereoCalibrationOptions> Describe();
};

// The error of one stereo pair.
struct PairError {
  std::string name;
  double left_rms_px = 0, right_rms_px = 0;
  bool rejected = false;  // Dropped from the rig's calibration (as a mono outlier or a bad pair).
};

// A calibrated stereo rig.
struct StereoCalibration {
  MonoCalibration left, right;  // Each camera on its own, over every pair.
  StereoRig rig;      // right_from_left from cv::stereoCalibrate (x_right = R x_left + T).
  double rms_px = 0;  // stereoCalibrate's RMS over both images of the used pairs.
  std::vector<PairError> pairs;  // One per input pair.
  cv::Matx33d essential, fundamental;
  cv::Matx33d rect_left, rect_right;  // R1, R2 of cv::stereoRectify.
  cv::Matx34d proj_left, proj_right;  // P1, P2.
  cv::Matx44d disparity_to_depth;     // Q.

  double BaselineM() const { return rig.BaselineM(); }
  int used_pairs() const;
};

// Calibrates from paired views: left[i] and right[i] show the board at the same instant.
// InvalidArgument when the counts differ, too few pairs remain, or the image sizes differ.
StatusOr<StereoCalibration> CalibrateStereo(const std::vector<BoardView>& left,
                                            const std::vector<BoardView>& right,
                                            const ChessboardOptions& board,
                                            const MonoCalibrationOptions& mono = {},
                                            const StereoCalibrationOptions& options = {},
                                            const CoverageOptions& coverage = {});

}  // namespace sightline
