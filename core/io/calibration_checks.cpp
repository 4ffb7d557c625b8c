#include "core/io/calibration_checks.h"

#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <tuple>

#include "core/common/input_limits.h"
#include "core/common/text_file.h"
#include "core/common/trajectory.h"

namespace sightline {
namespace {

std::optional<FieldProblem> CheckSize(const PinholeCamera& c, const CameraKeys& keys) {
  if (c.width <= 0)
    return FieldProblem{keys.width, "image width " + NumberText(c.width) + " must be positive"};
  if (c.height <= 0) {
    return FieldProblem{keys.height, "image height " + NumberText(c.height) + " must be positive"};
  }
  if (c.width > kMaxImageSidePx) {
    return FieldProblem{keys.width, "image width " + NumberText(c.width) +
                                        " is above the limit of " + NumberText(kMaxImageSidePx) +
                                        " px"};
  }
  if (c.height > kMaxImageSidePx) {
    return FieldProblem{keys.height, "image height " + NumberText(c.height) +
                                         " is above the limit of " + NumberText(kMaxImageSidePx) +
                                         " px"};
  }
  return std::nullopt;
}

std::optional<FieldProblem> CheckFocalAndCentre(const PinholeCamera& c, const CameraKeys& keys) {
  for (const auto& [value, key, name] : {std::tuple{c.fx, keys.fx, "fx"}, {c.fy, keys.fy, "fy"}}) {
    if (!(value > 0) || !std::isfinite(value)) {
      return FieldProblem{key, std::string("focal length ") + name + " = " + NumberText(value) +
                                   " must be positive and finite"};
    }
    if (!(value >= kMinFocalLengthPx && value <= kMaxFocalLengthPx)) {
      return FieldProblem{
          key, std::string("focal length ") + name + " = " + NumberText(value) +
                   " px is not plausible (accepted: " + NumberText(kMinFocalLengthPx) + " to " +
                   NumberText(kMaxFocalLengthPx) + " px)"};
    }
  }
  if (!(c.cx >= 0 && c.cx <= c.width)) {
    return FieldProblem{keys.cx, "principal point cx = " + NumberText(c.cx) +
                                     " must lie inside the image [0, " + NumberText(c.width) + "]"};
  }
  if (!(c.cy >= 0 && c.cy <= c.height)) {
    return FieldProblem{keys.cy, "principal point cy = " + NumberText(c.cy) +
                                     " must lie inside the image [0, " + NumberText(c.height) +
                                     "]"};
  }
  return std::nullopt;
}

}  // namespace

std::string NumberText(double value) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.10g", value);
  return text;
}

Status CheckReadableFile(const std::string& path) {
  SIGHTLINE_RETURN_IF_ERROR(CheckRegularFile(path, path));
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) == 0 && !ec) return ParseError(path + " is empty");
  return Status::Ok();
}

std::optional<FieldProblem> CheckCameraValues(const PinholeCamera& c, const CameraKeys& keys) {
  if (auto problem = CheckSize(c, keys)) return problem;
  if (auto problem = CheckFocalAndCentre(c, keys)) return problem;
  static const char* kNames[5] = {"k1", "k2", "p1", "p2", "k3"};
  for (size_t i = 0; i < c.distortion.size(); ++i) {
    const double k = c.distortion[i];
    if (!std::isfinite(k) || !(std::abs(k) < kMaxDistortionMagnitude)) {
      return FieldProblem{keys.distortion, std::string("distortion ") + kNames[i] + " = " +
                                               NumberText(k) +
                                               " must be finite with magnitude below " +
                                               NumberText(kMaxDistortionMagnitude)};
    }
  }
  return std::nullopt;
}

std::optional<std::string> CheckRotation(const Eigen::Matrix3d& r) {
  return RotationProblem(r, kRotationTolerance);
}

}  // namespace sightline
