#include "core/io/yaml_file.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/common/text_file.h"

namespace sightline {
namespace {

Status KeyError(const std::string& path, const std::string& key, const std::string& what) {
  return ParseError(path + ": key '" + key + "': " + what);
}

StatusOr<double> ToNumber(const YAML::Node& node, const std::string& key, const std::string& path) {
  if (!node.IsScalar()) return KeyError(path, key, "expected a number");
  double value = 0;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    return KeyError(path, key, "'" + node.Scalar() + "' is not a number");
  }
  if (!std::isfinite(value)) return KeyError(path, key, node.Scalar() + " is not finite");
  return value;
}

}  // namespace

StatusOr<YAML::Node> LoadYamlFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    if (!FileExists(path)) return NotFound(path + ": no such file");
    return NotFound(path + ": cannot be opened for reading");
  }
  std::ostringstream text;
  std::string line;
  while (std::getline(in, line)) {
    // OpenCV writes "%YAML:1.0"; yaml-cpp only knows "%YAML 1.x". Keep the line count.
    if (line.rfind("%YAML", 0) == 0) line.clear();
    text << line << '\n';
  }
  try {
    YAML::Node root = YAML::Load(text.str());
    if (!root.IsMap()) return ParseError(path + ": expected a YAML map of keys");
    return root;
  } catch (const YAML::Exception& e) {
    return ParseError(path + " line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
}

StatusOr<double> YamlNumber(const YAML::Node& map, const std::string& key,
                            const std::string& path) {
  const YAML::Node node = map[key];
  if (!node) return KeyError(path, key, "missing");
  return ToNumber(node, key, path);
}

StatusOr<std::vector<double>> YamlNumbers(const YAML::Node& map, const std::string& key,
                                          const std::string& path, size_t min_count,
                                          size_t max_count) {
  YAML::Node node = map[key];
  if (!node) return KeyError(path, key, "missing");
  if (node.IsMap() && node["data"]) node = node["data"];
  if (!node.IsSequence()) return KeyError(path, key, "expected a list of numbers");
  if (node.size() < min_count || node.size() > max_count) {
    const std::string expected =
        min_count == max_count ? std::to_string(min_count)
                               : std::to_string(min_count) + " to " + std::to_string(max_count);
    return KeyError(path, key,
                    "expected " + expected + " numbers, found " + std::to_string(node.size()));
  }
  std::vector<double> values;
  for (size_t i = 0; i < node.size(); ++i) {
    StatusOr<double> v = ToNumber(node[i], key, path);
    if (!v.ok()) return v.status();
    values.push_back(*v);
  }
  return values;
}

}  // namespace sightline
