#include "core/io/yaml_file.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/common/input_limits.h"
#include "core/common/text_file.h"
#include "core/io/calibration_checks.h"

namespace sightline {
namespace {

std::string LabelOr(const std::string& label, const std::string& key) {
  return label.empty() ? key : label;
}

StatusOr<double> ToNumber(const YAML::Node& node, const std::string& label,
                          const std::string& path) {
  if (!node.IsScalar()) return YamlKeyError(path, node, label, "expected a number");
  double value = 0;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    return YamlKeyError(path, node, label, "'" + node.Scalar() + "' is not a number");
  }
  if (!std::isfinite(value))
    return YamlKeyError(path, node, label, node.Scalar() + " is not finite");
  return value;
}

// Rejects a key given twice in any map of the tree.
Status CheckDuplicateKeys(const YAML::Node& node, const std::string& path,
                          const std::string& prefix) {
  if (node.IsSequence()) {
    for (const YAML::Node& item : node) {
      SIGHTLINE_RETURN_IF_ERROR(CheckDuplicateKeys(item, path, prefix));
    }
  }
  if (!node.IsMap()) return Status::Ok();
  std::map<std::string, int> first_line;
  for (const auto& entry : node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
    const int line = entry.first.Mark().line + 1;
    const auto [it, inserted] = first_line.emplace(key, line);
    if (!inserted) {
      return YamlKeyError(path, entry.first, prefix + key,
                          "given twice (first on line " + std::to_string(it->second) + ")");
    }
    SIGHTLINE_RETURN_IF_ERROR(CheckDuplicateKeys(entry.second, path, prefix + key + "."));
  }
  return Status::Ok();
}

StatusOr<std::string> ReadText(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Unavailable(path + " cannot be read");
  std::ostringstream text;
  std::string line;
  while (std::getline(in, line)) {
    // OpenCV writes "%YAML:1.0"; yaml-cpp only knows "%YAML 1.x". Keep the line count.
    if (line.rfind("%YAML", 0) == 0) line.clear();
    text << line << '\n';
  }
  if (in.bad()) return Unavailable(path + " cannot be read (input error)");
  return text.str();
}

}  // namespace

StatusOr<YAML::Node> LoadYamlFile(const std::string& path) {
  SIGHTLINE_RETURN_IF_ERROR(CheckReadableFile(path));
  SIGHTLINE_RETURN_IF_ERROR(CheckFileSize(path, kMaxCalibrationFileBytes, "calibration"));
  StatusOr<std::string> text = ReadText(path);
  if (!text.ok()) return text.status();
  YAML::Node root;
  try {
    root = YAML::Load(*text);
  } catch (const YAML::Exception& e) {
    return ParseError(path + " line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  if (root.IsNull()) return ParseError(path + " is empty (only blank lines or comments)");
  if (!root.IsMap()) return ParseError(path + ": expected a YAML map of keys");
  SIGHTLINE_RETURN_IF_ERROR(CheckDuplicateKeys(root, path, ""));
  return root;
}

std::string YamlWhere(const std::string& path, const YAML::Node& node) {
  if (!node.IsDefined() || node.Mark().is_null()) return path;
  return path + " line " + std::to_string(node.Mark().line + 1);
}

Status YamlKeyError(const std::string& path, const YAML::Node& node, const std::string& label,
                    const std::string& what) {
  return ParseError(YamlWhere(path, node) + ": key '" + label + "': " + what);
}

Status CheckKnownKeys(const YAML::Node& map, const std::set<std::string>& known,
                      const std::string& path, const std::string& prefix) {
  for (const auto& entry : map) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
    if (known.count(key) != 0) continue;
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : " ") + prefix + k;
    return ParseError(YamlWhere(path, entry.first) + ": unknown key '" + prefix + key +
                      "' (known: " + list + ")");
  }
  return Status::Ok();
}

StatusOr<double> YamlNumber(const YAML::Node& map, const std::string& key, const std::string& path,
                            const std::string& label) {
  const YAML::Node node = map[key];
  if (!node) return YamlKeyError(path, YAML::Node(), LabelOr(label, key), "missing");
  return ToNumber(node, LabelOr(label, key), path);
}

StatusOr<int> YamlWholeNumber(const YAML::Node& map, const std::string& key,
                              const std::string& path, const std::string& label) {
  StatusOr<double> value = YamlNumber(map, key, path, label);
  if (!value.ok()) return value.status();
  if (*value != std::round(*value) || std::abs(*value) > 1e9) {
    return YamlKeyError(path, map[key], LabelOr(label, key),
                        map[key].Scalar() + " is not a whole number");
  }
  return static_cast<int>(*value);
}

StatusOr<std::vector<double>> YamlNumbers(const YAML::Node& map, const std::string& key,
                                          const std::string& path, size_t min_count,
                                          size_t max_count, const std::string& label_in) {
  const std::string label = LabelOr(label_in, key);
  YAML::Node node = map[key];
  if (!node) return YamlKeyError(path, YAML::Node(), label, "missing");
  if (node.IsMap() && node["data"]) {
    const YAML::Node data = node["data"];
    if (node["rows"] && node["cols"] && data.IsSequence()) {
      StatusOr<int> rows = YamlWholeNumber(node, "rows", path, label + ".rows");
      StatusOr<int> cols = YamlWholeNumber(node, "cols", path, label + ".cols");
      if (!rows.ok()) return rows.status();
      if (!cols.ok()) return cols.status();
      if (static_cast<size_t>(*rows) * *cols != data.size()) {
        return YamlKeyError(path, node, label,
                            std::to_string(*rows) + " x " + std::to_string(*cols) + " matrix but " +
                                std::to_string(data.size()) + " numbers in data");
      }
    }
    node = data;
  }
  if (!node.IsSequence()) return YamlKeyError(path, node, label, "expected a list of numbers");
  if (node.size() < min_count || node.size() > max_count) {
    const std::string expected =
        min_count == max_count ? std::to_string(min_count)
                               : std::to_string(min_count) + " to " + std::to_string(max_count);
    return YamlKeyError(path, node, label,
                        "expected " + expected + " numbers, found " + std::to_string(node.size()));
  }
  std::vector<double> values;
  for (size_t i = 0; i < node.size(); ++i) {
    StatusOr<double> v = ToNumber(node[i], label, path);
    if (!v.ok()) return v.status();
    values.push_back(*v);
  }
  return values;
}

StatusOr<std::string> YamlString(const YAML::Node& map, const std::string& key,
                                 const std::string& path, const std::string& label) {
  const YAML::Node node = map[key];
  if (!node) return YamlKeyError(path, YAML::Node(), LabelOr(label, key), "missing");
  if (!node.IsScalar()) return YamlKeyError(path, node, LabelOr(label, key), "expected text");
  return node.Scalar();
}

}  // namespace sightline
