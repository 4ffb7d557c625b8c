// Saving calibration results in the calibration file formats of core/io, which every reader of
// the project and OpenCV's cv::FileStorage read:
//
// - mono: a camera.yaml (core/io/camera_yaml.h) with the RMS, board, coverage and per-view
//   errors as comments;
// - stereo: the stereo calibration file (core/io/stereo_calibration_file.h) with E F R1 R2 P1 P2
//   Q, rms_left, rms_right, rms_stereo, baseline_m and the board, plus one camera.yaml per camera
//   beside it (FILE_left.yaml, FILE_right.yaml);
// - hand-eye: a hand_eye.yaml (core/io/hand_eye_file.h) with the fit's figures.
//
// Reading them back is core/io's: ReadCameraYaml, ReadStereoCalibration, ReadHandEyeFile.
#pragma once

#include <string>

#include "core/calib/hand_eye.h"
#include "core/calib/mono_calibration.h"
#include "core/calib/stereo_calibration.h"
#include "core/common/status.h"

namespace sightline {

// Saves a mono calibration as a camera.yaml. Unavailable when the file cannot be written.
Status SaveMonoCalibration(const MonoCalibration& calibration, const ChessboardOptions& board,
                           const std::string& path);

// The camera files written beside a stereo file: "out/rig.yaml" -> "out/rig_left.yaml".
std::string StereoCameraFilePath(const std::string& stereo_path, const std::string& side);

// Saves a stereo calibration as a stereo calibration file plus the two camera.yaml files.
Status SaveStereoCalibration(const StereoCalibration& calibration, const ChessboardOptions& board,
                             const std::string& path);

// Saves a hand-eye result as a hand_eye.yaml (end_effector_from_camera and the fit's figures).
Status SaveHandEyeCalibration(const HandEyeResult& result, const std::string& path);

}  // namespace sightline
