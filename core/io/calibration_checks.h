// The checks every calibration file reader applies (camera.yaml, stereo calibration,
// hand_eye.yaml, the floor file), so that a value the estimators would choke on is rejected when
// the file is read, with a message naming the file and the field.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "core/common/camera.h"
#include "core/common/status.h"

namespace sightline {

// Largest accepted magnitude of a distortion coefficient (k1 k2 p1 p2 k3). Real lenses stay far
// below; larger values are a unit or field mix-up.
inline constexpr double kMaxDistortionMagnitude = 1e3;
// Accepted focal lengths [px]. Below one pixel a pinhole camera would see almost 180 degrees
// across a single pixel; above a million pixels its view is narrower than a thousandth of a
// degree. Values outside are unit mix-ups (metres for pixels) or corrupt files.
inline constexpr double kMinFocalLengthPx = 1;
inline constexpr double kMaxFocalLengthPx = 1e6;
// A rotation matrix R is accepted when every entry of R^T R - I is within this and det R is
// within it of +1; a quaternion when its length is within it of 1. Nothing is re-orthonormalised.
inline constexpr double kRotationTolerance = 1e-6;
// A floor normal (a, b, c) within this fraction of unit length is normalised; others are rejected.
inline constexpr double kFloorNormalTolerance = 0.01;

// A number for messages: up to 10 significant digits ("0.002001", "-5", "inf").
std::string NumberText(double value);

// Checks that `path` names a regular, readable, non-empty file. NotFound only when nothing is
// there; otherwise InvalidArgument "<path> is a folder" / "<path> is not a regular file" (a
// device, a pipe), Unavailable "<path> cannot be read: permission denied" (or the system's
// reason), ParseError "<path> is empty".
Status CheckReadableFile(const std::string& path);

// The keys a file stores a camera's values under, for messages.
struct CameraKeys {
  std::string width = "width";
  std::string height = "height";
  std::string fx = "fx", fy = "fy", cx = "cx", cy = "cy";
  std::string distortion = "distortion";
};

// A problem with one field: the key it is stored under and what is wrong.
struct FieldProblem {
  std::string key;
  std::string what;
};

// Image size positive; focal lengths finite in [kMinFocalLengthPx, kMaxFocalLengthPx]; principal
// point finite and inside the
// image ([0, width] x [0, height]); distortion finite with |k| < kMaxDistortionMagnitude.
std::optional<FieldProblem> CheckCameraValues(const PinholeCamera& camera, const CameraKeys& keys);

// Why `r` is not a rotation (orthonormal within kRotationTolerance, det +1), or nothing.
std::optional<std::string> CheckRotation(const Eigen::Matrix3d& r);

}  // namespace sightline
