// One mono or stereo calibration from an input path, as the GUI's calibration dialog runs it in
// a worker thread: find the images (folder, stereo folder) or read a source (recording or live
// camera, opened by the caller's opener), detect the board, calibrate, and report.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/calib/calibration_report.h"

namespace sightline {

// What to calibrate.
struct CalibrationRequest {
  bool stereo = false;
  // Mono: an image folder (with `pattern`) or a source; stereo: a stereo folder (see
  // FindStereoImages) or a stereo source.
  std::string input;
  std::string pattern = "*";
  // Stereo: explicit left/right files (e.g. two folders); when set, `input` only names them.
  std::optional<StereoImageFiles> files;
  CalibrationSettings settings;
  int max_frames = 2000;  // Sources only.
};

// Opens a source by path or URI (front ends pass sensors' OpenSource; core/calib cannot).
using SourceOpener = std::function<StatusOr<std::unique_ptr<Source>>(const std::string&)>;

// A finished calibration.
struct CalibrationOutcome {
  CalibrationRequest request;
  Detections detections;
  std::optional<MonoCalibration> mono;      // Mono requests.
  std::optional<StereoCalibration> stereo;  // Stereo requests.
  std::string report;                       // MonoReport / StereoReport.
};

// Runs a request. The detection's or calibration's Status on failure (Cancelled when stopped).
StatusOr<CalibrationOutcome> RunCalibration(const CalibrationRequest& request,
                                            const SourceOpener& open_source,
                                            const DetectionCallbacks& callbacks = {});

// Saves the outcome (SaveMonoCalibration or SaveStereoCalibration).
Status SaveCalibration(const CalibrationOutcome& outcome, const std::string& path);

}  // namespace sightline
