// The hand-eye calibration of an eye-in-hand camera, read from a hand_eye.yaml file (the
// format the simulator writes, core/sim/README.md): end_effector_from_camera and, optionally,
// world_from_base.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "core/common/status.h"

namespace sightline {

struct HandEye {
  Eigen::Isometry3d end_effector_from_camera = Eigen::Isometry3d::Identity();
  std::optional<Eigen::Isometry3d> world_from_base;  // When the file has it.
};

// Reads `translation: [x, y, z]` and `quaternion_xyzw: [x, y, z, w]` under the keys
// `end_effector_from_camera:` (required) and `world_from_base:` (optional). NotFound for a
// missing file; ParseError naming the file and line for anything malformed.
StatusOr<HandEye> ReadHandEyeFile(const std::string& path);

}  // namespace sightline
