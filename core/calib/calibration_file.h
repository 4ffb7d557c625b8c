// Saving calibrations as OpenCV YAML (cv::FileStorage) that Sightline's readers accept:
//
// - mono: a camera.yaml (core/io/camera_yaml.h: model, width, height, fx, fy, cx, cy,
//   distortion) written by cv::FileStorage, with the RMS, board and per-view errors as comments,
//   so the image-folder and TUM readers take it as it is and OpenCV reads it too;
// - stereo: OpenCV's stereo layout (image_width, image_height, M1 D1 M2 D2 R T E F R1 R2 P1 P2
//   Q, rms_left, rms_right, rms_stereo, baseline_m, board) plus one camera.yaml per camera
//   beside it (FILE_left.yaml, FILE_right.yaml).
#pragma once

#include <string>

#include "core/calib/hand_eye.h"
#include "core/calib/mono_calibration.h"
#include "core/calib/stereo_calibration.h"
#include "core/common/camera.h"
#include "core/common/status.h"

namespace sightline {

// Writes a mono calibration as a camera.yaml. Unavailable when the file cannot be written.
Status WriteMonoCalibration(const MonoCalibration& calibration, const ChessboardOptions& board,
                            const std::string& path);

// The camera files written beside a stereo file: "out/rig.yaml" -> "out/rig_left.yaml".
std::string StereoCameraFilePath(const std::string& stereo_path, const std::string& side);

// Writes a stereo calibration in OpenCV's layout plus the two camera.yaml files.
Status WriteStereoCalibration(const StereoCalibration& calibration, const ChessboardOptions& board,
                              const std::string& path);

// Reads an OpenCV stereo file (M1 D1 M2 D2 R T, image_width/height) into a rig. NotFound when
// missing; ParseError naming the file and the missing or malformed field.
StatusOr<StereoRig> ReadStereoCalibration(const std::string& path);

// Writes a hand-eye result in the layout of the simulator's hand_eye.yaml (end_effector_from_camera
// with translation [m] and quaternion_xyzw), plus the rotation matrix and the fit's figures.
Status WriteHandEyeCalibration(const HandEyeResult& result, const std::string& path);

// Reads end_effector_from_camera (translation + quaternion_xyzw) from a hand-eye file: the
// simulator's hand_eye.yaml or WriteHandEyeCalibration's. ParseError naming file and key.
StatusOr<Eigen::Isometry3d> ReadEndEffectorFromCamera(const std::string& path);

}  // namespace sightline
