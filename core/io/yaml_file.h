// yaml-cpp access for the readers' YAML files (camera.yaml, stereo calibration, hand_eye.yaml,
// the floor file, EuRoC sensor.yaml). Internal to sightline_io: yaml-cpp is a private dependency,
// so include this only from .cpp files of core/io, never from a public header.
//
// Messages name the file, the line when yaml-cpp knows it, and the key:
//   "rig.yaml line 7: key 'M1': focal length fx = -5 must be positive and finite".
#pragma once

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// Parses a YAML file whose top level is a map. The file is checked first (CheckReadableFile: a
// folder, a device, an empty or unreadable file each get their own message). An OpenCV
// "%YAML:1.0" first line, which yaml-cpp rejects, is blanked (line numbers in messages stay
// right). A key given twice in any map is a ParseError naming both lines.
StatusOr<YAML::Node> LoadYamlFile(const std::string& path);

// "path line N" when the node comes from the file, else "path".
std::string YamlWhere(const std::string& path, const YAML::Node& node);

// ParseError "<path> line N: key '<label>': <what>" (no line when `node` has none).
Status YamlKeyError(const std::string& path, const YAML::Node& node, const std::string& label,
                    const std::string& what);

// Rejects keys of `map` not in `known`; the message lists the known keys. `prefix` is put before
// key names in messages ("end_effector_from_camera.").
Status CheckKnownKeys(const YAML::Node& map, const std::set<std::string>& known,
                      const std::string& path, const std::string& prefix = "");

// The number under `key` of a map. ParseError naming file, line and key when absent, not a
// number or not finite. `label` names the key in messages (default: the key).
StatusOr<double> YamlNumber(const YAML::Node& map, const std::string& key, const std::string& path,
                            const std::string& label = "");

// A whole number under `key` (e.g. pixels): like YamlNumber, and it must have no fraction.
StatusOr<int> YamlWholeNumber(const YAML::Node& map, const std::string& key,
                              const std::string& path, const std::string& label = "");

// The numbers of the sequence under `key`. For an OpenCV matrix ({rows, cols, dt, data}) its
// data, after checking that rows x cols matches the data. ParseError naming file, line and key
// unless it holds between min_count and max_count finite numbers.
StatusOr<std::vector<double>> YamlNumbers(const YAML::Node& map, const std::string& key,
                                          const std::string& path, size_t min_count,
                                          size_t max_count, const std::string& label = "");

// The string under `key` (a scalar). ParseError naming file, line and key otherwise.
StatusOr<std::string> YamlString(const YAML::Node& map, const std::string& key,
                                 const std::string& path, const std::string& label = "");

}  // namespace sightline
