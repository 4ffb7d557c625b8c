#include "core/io/calibration_checks.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <Eigen/LU>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace sightline {
namespace {

// strerror's text with a lower-case first letter: "permission denied".
std::string Reason(int error) {
  std::string text = std::strerror(error);
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

std::optional<FieldProblem> CheckSize(const PinholeCamera& c, const CameraKeys& keys) {
  if (c.width <= 0)
    return FieldProblem{keys.width, "image width " + NumberText(c.width) + " must be positive"};
  if (c.height <= 0) {
    return FieldProblem{keys.height, "image height " + NumberText(c.height) + " must be positive"};
  }
  return std::nullopt;
}

std::optional<FieldProblem> CheckFocalAndCentre(const PinholeCamera& c, const CameraKeys& keys) {
  if (!(c.fx > 0) || !std::isfinite(c.fx)) {
    return FieldProblem{keys.fx,
                        "focal length fx = " + NumberText(c.fx) + " must be positive and finite"};
  }
  if (!(c.fy > 0) || !std::isfinite(c.fy)) {
    return FieldProblem{keys.fy,
                        "focal length fy = " + NumberText(c.fy) + " must be positive and finite"};
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
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    if (errno == ENOENT || errno == ENOTDIR) return NotFound(path + ": no such file");
    return Unavailable(path + " cannot be read: " + Reason(errno));
  }
  if (S_ISDIR(info.st_mode)) return InvalidArgument(path + " is a folder, not a file");
  if (!S_ISREG(info.st_mode)) {
    return InvalidArgument(path + " is not a regular file (a device, pipe or socket)");
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return Unavailable(path + " cannot be read: " + Reason(errno));
  ::close(fd);
  if (info.st_size == 0) return ParseError(path + " is empty");
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
  if (!r.allFinite()) return "is not a rotation: it holds a value that is not finite";
  const double off = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(off <= kRotationTolerance)) {
    return "is not a rotation: R^T R differs from the identity by " + NumberText(off) + " (limit " +
           NumberText(kRotationTolerance) + ")";
  }
  const double det = r.determinant();
  if (!(std::abs(det - 1) <= kRotationTolerance)) {
    return "is not a rotation: its determinant is " + NumberText(det) + ", not +1" +
           (det < 0 ? " (a reflection)" : "");
  }
  return std::nullopt;
}

}  // namespace sightline
