#include "core/io/camera_yaml.h"

#include <cmath>
#include <set>

#include "core/io/calibration_checks.h"
#include "core/io/yaml_file.h"

namespace sightline {
namespace {

// Reads an optional positive number.
Status ReadOptional(const YAML::Node& root, const std::string& key, const std::string& path,
                    std::optional<double>* out) {
  if (!root[key]) return Status::Ok();
  StatusOr<double> v = YamlNumber(root, key, path);
  if (!v.ok()) return v.status();
  if (!(*v > 0)) return YamlKeyError(path, root[key], key, "must be positive");
  *out = *v;
  return Status::Ok();
}

Status CheckModel(const YAML::Node& root, const std::string& path) {
  const YAML::Node model_node = root["model"];
  if (!model_node) return Status::Ok();
  const std::string model = model_node.IsScalar() ? model_node.Scalar() : "?";
  if (model != "pinhole") {
    return YamlKeyError(path, model_node, "model", "'" + model + "' is not supported (pinhole)");
  }
  return Status::Ok();
}

Status ReadIntrinsics(const YAML::Node& root, const std::string& path, PinholeCamera* c) {
  StatusOr<int> width = YamlWholeNumber(root, "width", path);
  if (!width.ok()) return width.status();
  StatusOr<int> height = YamlWholeNumber(root, "height", path);
  if (!height.ok()) return height.status();
  c->width = *width;
  c->height = *height;
  for (auto [key, value] : {std::pair<const char*, double*>{"fx", &c->fx},
                            {"fy", &c->fy},
                            {"cx", &c->cx},
                            {"cy", &c->cy}}) {
    StatusOr<double> v = YamlNumber(root, key, path);
    if (!v.ok()) return v.status();
    *value = *v;
  }
  if (root["distortion"]) {
    StatusOr<std::vector<double>> d = YamlNumbers(root, "distortion", path, 4, 5);
    if (!d.ok()) return d.status();
    for (size_t i = 0; i < d->size(); ++i) c->distortion[i] = (*d)[i];
  }
  if (std::optional<FieldProblem> problem = CheckCameraValues(*c, CameraKeys{})) {
    return YamlKeyError(path, root[problem->key], problem->key, problem->what);
  }
  return Status::Ok();
}

}  // namespace

StatusOr<CameraFile> ReadCameraYaml(const std::string& path) {
  StatusOr<YAML::Node> root = LoadYamlFile(path);
  if (!root.ok()) return root.status();
  static const std::set<std::string> kKnown = {"model",       "width",       "height", "fx",
                                               "fy",          "cx",          "cy",     "distortion",
                                               "depth_scale", "max_depth_m", "rate_hz"};
  SIGHTLINE_RETURN_IF_ERROR(CheckKnownKeys(*root, kKnown, path));
  SIGHTLINE_RETURN_IF_ERROR(CheckModel(*root, path));
  CameraFile file;
  SIGHTLINE_RETURN_IF_ERROR(ReadIntrinsics(*root, path, &file.camera));
  SIGHTLINE_RETURN_IF_ERROR(ReadOptional(*root, "depth_scale", path, &file.depth_scale));
  SIGHTLINE_RETURN_IF_ERROR(ReadOptional(*root, "max_depth_m", path, &file.max_depth_m));
  SIGHTLINE_RETURN_IF_ERROR(ReadOptional(*root, "rate_hz", path, &file.rate_hz));
  return file;
}

Status WriteCameraYaml(const CameraFile& file, const std::string& path,
                       const FileComments& comments) {
  const PinholeCamera& c = file.camera;
  if (std::optional<FieldProblem> problem = CheckCameraValues(c, CameraKeys{})) {
    return InvalidArgument("camera file " + path + " not written: '" + problem->key +
                           "': " + problem->what);
  }
  YamlWriter out(/*opencv_header=*/true);
  out.Comments(comments.header.empty()
                   ? std::vector<std::string>{"Sightline camera file (see core/io/camera_yaml.h)"}
                   : comments.header);
  out.Text("model", "pinhole");
  out.Integer("width", c.width);
  out.Integer("height", c.height);
  out.Number("fx", c.fx);
  out.Number("fy", c.fy);
  out.Number("cx", c.cx);
  out.Number("cy", c.cy);
  out.List("distortion", std::vector<double>(c.distortion.begin(), c.distortion.end()));
  for (auto [key, value] :
       {std::pair<const char*, const std::optional<double>*>{"depth_scale", &file.depth_scale},
        {"max_depth_m", &file.max_depth_m},
        {"rate_hz", &file.rate_hz}}) {
    if (!value->has_value()) continue;
    if (!(std::isfinite(**value) && **value > 0)) {
      return InvalidArgument("camera file " + path + " not written: '" + key +
                             "' must be positive and finite");
    }
    out.Number(key, **value);
  }
  out.Comments(comments.footer);
  return out.WriteTo(path);
}

}  // namespace sightline
