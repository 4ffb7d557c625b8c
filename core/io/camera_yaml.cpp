#include "core/io/camera_yaml.h"

#include <fstream>
#include <iomanip>
#include <set>

#include "core/io/yaml_file.h"

namespace sightline {
namespace {

// Reads an optional positive number.
Status ReadOptional(const YAML::Node& root, const std::string& key, const std::string& path,
                    std::optional<double>* out) {
  if (!root[key]) return Status::Ok();
  StatusOr<double> v = YamlNumber(root, key, path);
  if (!v.ok()) return v.status();
  if (!(*v > 0)) return ParseError(path + ": key '" + key + "': must be positive");
  *out = *v;
  return Status::Ok();
}

}  // namespace

StatusOr<CameraFile> ReadCameraYaml(const std::string& path) {
  StatusOr<YAML::Node> root = LoadYamlFile(path);
  if (!root.ok()) return root.status();
  static const std::set<std::string> kKnown = {"model",       "width",       "height", "fx",
                                               "fy",          "cx",          "cy",     "distortion",
                                               "depth_scale", "max_depth_m", "rate_hz"};
  for (const auto& entry : *root) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
    if (kKnown.count(key) == 0) {
      return ParseError(path + ": unknown key '" + key +
                        "' (known: model width height fx fy cx cy distortion depth_scale "
                        "max_depth_m rate_hz)");
    }
  }
  if (const YAML::Node model_node = (*root)["model"]) {
    const std::string model = model_node.IsScalar() ? model_node.Scalar() : "?";
    if (model != "pinhole") {
      return ParseError(path + ": key 'model': '" + model + "' is not supported (pinhole)");
    }
  }
  CameraFile file;
  PinholeCamera& c = file.camera;
  struct Field {
    const char* key;
    double* value;
  };
  double width = 0, height = 0;
  for (const Field& f : {Field{"width", &width}, Field{"height", &height}, Field{"fx", &c.fx},
                         Field{"fy", &c.fy}, Field{"cx", &c.cx}, Field{"cy", &c.cy}}) {
    StatusOr<double> v = YamlNumber(*root, f.key, path);
    if (!v.ok()) return v.status();
    *f.value = *v;
  }
  if (width != static_cast<int>(width) || height != static_cast<int>(height)) {
    return ParseError(path + ": keys 'width'/'height' must be whole numbers of pixels");
  }
  c.width = static_cast<int>(width);
  c.height = static_cast<int>(height);
  if ((*root)["distortion"]) {
    StatusOr<std::vector<double>> d = YamlNumbers(*root, "distortion", path, 4, 5);
    if (!d.ok()) return d.status();
    for (size_t i = 0; i < d->size(); ++i) c.distortion[i] = (*d)[i];
  }
  SIGHTLINE_RETURN_IF_ERROR(ReadOptional(*root, "depth_scale", path, &file.depth_scale));
  SIGHTLINE_RETURN_IF_ERROR(ReadOptional(*root, "max_depth_m", path, &file.max_depth_m));
  SIGHTLINE_RETURN_IF_ERROR(ReadOptional(*root, "rate_hz", path, &file.rate_hz));
  Status valid = c.Validate();
  if (!valid.ok()) return ParseError(path + ": " + valid.message());
  return file;
}

Status WriteCameraYaml(const CameraFile& file, const std::string& path) {
  std::ofstream out(path);
  if (!out) return NotFound("cannot write " + path);
  const PinholeCamera& c = file.camera;
  out << std::setprecision(10);
  out << "# Sightline camera file (see core/io/camera_yaml.h)\n"
      << "model: pinhole\n"
      << "width: " << c.width << "\nheight: " << c.height << "\nfx: " << c.fx << "\nfy: " << c.fy
      << "\ncx: " << c.cx << "\ncy: " << c.cy << "\ndistortion: [";
  for (size_t i = 0; i < c.distortion.size(); ++i) {
    out << (i == 0 ? "" : ", ") << c.distortion[i];
  }
  out << "]\n";
  if (file.depth_scale) out << "depth_scale: " << *file.depth_scale << "\n";
  if (file.max_depth_m) out << "max_depth_m: " << *file.max_depth_m << "\n";
  if (file.rate_hz) out << "rate_hz: " << *file.rate_hz << "\n";
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

}  // namespace sightline
