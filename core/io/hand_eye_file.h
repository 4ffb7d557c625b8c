// hand_eye.yaml: the mount of an eye-in-hand camera, as the simulator writes it for arm scenes
// and `sightline-cli calibrate handeye` writes it, and as the button and mono-slam pipelines read
// it (arm_poses.txt gives base_from_end_effector; base_from_camera = base_from_end_effector *
// end_effector_from_camera):
//
//   %YAML:1.0                        # optional
//   ---
//   end_effector_from_camera:        # required: the camera's optical frame (z forward, x right,
//     translation: [x, y, z]         #   y down) in the end-effector frame, metres
//     quaternion_xyzw: [x, y, z, w]
//   world_from_base:                 # optional: the arm's base in the map frame
//     translation: [x, y, z]
//     quaternion_xyzw: [x, y, z, w]
//   rotation: !!opencv-matrix        # optional: end_effector_from_camera's rotation matrix; must
//     ...                            #   agree with its quaternion within 1e-6
//   method: "tsai"                   # optional, all five or none: the calibration's figures
//   pairs: 12
//   max_rotation_deg: 40.1
//   board_rotation_rms_deg: 0.05
//   board_translation_rms_m: 0.0004
//
// Checks: no unknown or repeated keys, translations finite, quaternions of unit length within 1e-6
// (not re-normalised beyond that), pairs a positive whole number, the figures finite and >= 0.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "core/common/status.h"
#include "core/io/yaml_writer.h"

namespace sightline {

// How a calibrated mount was found (written by `calibrate handeye`).
struct HandEyeFit {
  std::string method;  // The solver, e.g. "tsai".
  int pairs = 0;       // Arm pose / board view pairs used.
  double max_rotation_deg = 0;
  double board_rotation_rms_deg = 0;
  double board_translation_rms_m = 0;
};

// What a hand_eye.yaml holds.
struct HandEye {
  Eigen::Isometry3d end_effector_from_camera = Eigen::Isometry3d::Identity();
  std::optional<Eigen::Isometry3d> world_from_base;  // When the file has it.
  std::optional<HandEyeFit> fit;                     // When the file has it.
};

// Reads and validates a hand_eye.yaml. NotFound when missing; other file problems as
// CheckReadableFile says; ParseError naming the file, the line and the key.
StatusOr<HandEye> ReadHandEyeFile(const std::string& path);

// Writes `hand_eye` in the format above with `comments`. InvalidArgument (nothing written) when
// the reader would reject a value; Unavailable when the file cannot be written.
Status WriteHandEyeFile(const HandEye& hand_eye, const std::string& path,
                        const FileComments& comments = {});

}  // namespace sightline
