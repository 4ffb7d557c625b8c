// yaml-cpp access for the readers' YAML files (camera.yaml, EuRoC sensor.yaml).
// Internal to sightline_io: yaml-cpp is a private dependency, so include this only from .cpp files
// of core/io, never from a public header.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// Parses a YAML file. An OpenCV "%YAML:1.0" first line, which yaml-cpp rejects, is blanked
// (line numbers in messages stay right). NotFound when missing, ParseError naming file and line.
StatusOr<YAML::Node> LoadYamlFile(const std::string& path);

// The number under `key` of a map. ParseError naming file and key when absent or not a number.
StatusOr<double> YamlNumber(const YAML::Node& map, const std::string& key, const std::string& path);

// The numbers of the sequence under `key` (for a {rows, cols, data} matrix map, its data).
// ParseError naming file and key unless it holds between min_count and max_count numbers.
StatusOr<std::vector<double>> YamlNumbers(const YAML::Node& map, const std::string& key,
                                          const std::string& path, size_t min_count,
                                          size_t max_count);

}  // namespace sightline
