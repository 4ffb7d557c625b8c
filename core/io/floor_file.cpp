#include "core/io/floor_file.h"

#include <cmath>
#include <set>

#include "core/io/calibration_checks.h"
#include "core/io/yaml_file.h"
#include "core/io/yaml_writer.h"

namespace sightline {
namespace {

// The normal (a, b, c) and d: the normal within 1 % of unit length is normalised with d.
Status ReadPlane(const YAML::Node& root, const std::string& path, FloorPlane* plane) {
  double v[4] = {0, 0, 0, 0};
  const char* keys[4] = {"a", "b", "c", "d"};
  for (int i = 0; i < 4; ++i) {
    StatusOr<double> value = YamlNumber(root, keys[i], path);
    if (!value.ok()) return value.status();
    v[i] = *value;
  }
  const Eigen::Vector3d n(v[0], v[1], v[2]);
  const double length = n.norm();
  if (!(std::abs(length - 1) <= kFloorNormalTolerance)) {
    return YamlKeyError(
        path, root["a"], "a, b, c",
        "the normal has length " + NumberText(length) + ": it must be of unit length within 1 %");
  }
  const double d = v[3] / length;
  if (!(d > 0)) {
    return YamlKeyError(path, root["d"], "d",
                        "the camera height " + NumberText(d) +
                            " m must be positive, with (a, b, c) pointing up towards the camera");
  }
  plane->normal = n / length;
  plane->d = d;
  return Status::Ok();
}

Status ReadOptionalFigures(const YAML::Node& root, const std::string& path, FloorCalibration* out) {
  if (root["epsilon_m"]) {
    StatusOr<double> e = YamlNumber(root, "epsilon_m", path);
    if (!e.ok()) return e.status();
    if (!(*e > 0)) return YamlKeyError(path, root["epsilon_m"], "epsilon_m", "must be positive");
    out->plane.epsilon_m = *e;
  }
  for (const char* derived : {"camera_height_m", "pitch_down_deg"}) {
    if (!root[derived]) continue;
    StatusOr<double> v = YamlNumber(root, derived, path);
    if (!v.ok()) return v.status();
  }
  if (root["inlier_ratio"]) {
    StatusOr<double> r = YamlNumber(root, "inlier_ratio", path);
    if (!r.ok()) return r.status();
    if (!(*r >= 0 && *r <= 1)) {
      return YamlKeyError(path, root["inlier_ratio"], "inlier_ratio", "must lie in [0, 1]");
    }
    out->inlier_ratio = *r;
  }
  if (root["frames"]) {
    StatusOr<int> frames = YamlWholeNumber(root, "frames", path);
    if (!frames.ok()) return frames.status();
    if (*frames < 0) return YamlKeyError(path, root["frames"], "frames", "must not be negative");
    out->frames = *frames;
  }
  if (root["source"]) {
    StatusOr<std::string> source = YamlString(root, "source", path);
    if (!source.ok()) return source.status();
    out->source = *source;
  }
  return Status::Ok();
}

}  // namespace

StatusOr<FloorCalibration> ReadFloorCalibration(const std::string& path) {
  StatusOr<YAML::Node> root = LoadYamlFile(path);
  if (!root.ok()) return root.status();
  static const std::set<std::string> kKnown = {
      "a",      "b",     "c", "d", "epsilon_m", "camera_height_m", "pitch_down_deg", "inlier_ratio",
      "frames", "source"};
  SIGHTLINE_RETURN_IF_ERROR(CheckKnownKeys(*root, kKnown, path));
  FloorCalibration calibration;
  SIGHTLINE_RETURN_IF_ERROR(ReadPlane(*root, path, &calibration.plane));
  SIGHTLINE_RETURN_IF_ERROR(ReadOptionalFigures(*root, path, &calibration));
  return calibration;
}

Status WriteFloorCalibration(const FloorCalibration& calibration, const std::string& path) {
  std::string error;
  if (!calibration.plane.IsValid(&error)) {
    return InvalidArgument("floor file " + path + " not written: " + error);
  }
  if (!(calibration.inlier_ratio >= 0 && calibration.inlier_ratio <= 1) || calibration.frames < 0) {
    return InvalidArgument("floor file " + path +
                           " not written: inlier_ratio must lie in [0, 1] and frames be >= 0");
  }
  const FloorPlane& p = calibration.plane;
  YamlWriter out(/*opencv_header=*/false);
  out.Comments({"Sightline floor plane: a x + b y + c z + d = 0 in the camera frame (x right,",
                "y down, z forward, metres); (a, b, c) is the unit normal pointing up, so d is",
                "the camera height. A point is floor when |a x + b y + c z + d| <= epsilon_m."});
  out.Number("a", p.normal.x());
  out.Number("b", p.normal.y());
  out.Number("c", p.normal.z());
  out.Number("d", p.d);
  out.Number("epsilon_m", p.epsilon_m);
  out.Number("camera_height_m", p.CameraHeightM());
  out.Number("pitch_down_deg", p.PitchDownDeg());
  out.Number("inlier_ratio", calibration.inlier_ratio);
  out.Integer("frames", calibration.frames);
  out.Text("source", calibration.source);
  return out.WriteTo(path);
}

}  // namespace sightline
