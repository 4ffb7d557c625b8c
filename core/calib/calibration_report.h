// Calibration settings as one option group (keys "calib.*") and plain-text reports of results,
// shared by `sightline-cli calibrate` and the GUI's calibration dialog.
#pragma once

#include <string>

#include "core/calib/board_detection.h"
#include "core/calib/hand_eye.h"
#include "core/calib/stereo_calibration.h"
#include "core/options/option_set.h"

namespace sightline {

// Every calibration option.
struct CalibrationSettings {
  ChessboardOptions board;
  CoverageOptions coverage;
  MonoCalibrationOptions mono;
  StereoCalibrationOptions stereo;
  HandEyeOptions hand_eye;

  // Declares every "calib.*" key in `options`.
  static Status Declare(OptionSet* options);
  // The settings held by `options` (declared by Declare()).
  static CalibrationSettings Extract(const OptionSet& options);
  // The first invalid field's message, or "" when all are valid.
  std::string Check() const;
};

// Per-view errors, RMS, coverage and hints of a mono calibration, one fact per line.
std::string MonoReport(const MonoCalibration& calibration, const Detections& detections);
// Both cameras, the per-pair errors, the stereo RMS and the baseline.
std::string StereoReport(const StereoCalibration& calibration, const Detections& detections);
// The mount, its rotation and translation, and the consistency figures.
std::string HandEyeReport(const HandEyeResult& result);

}  // namespace sightline
