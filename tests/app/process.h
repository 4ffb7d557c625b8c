// Runs a command line and captures its output and exit code, for CLI tests.
#pragma once

#include <optional>
#include <string>

namespace sightline::testing {

struct ProcessResult {
  int exit_code = -1;
  std::string out;  // stdout and stderr together.
};

// Runs `command` through /bin/sh with stderr merged into stdout.
ProcessResult RunProcess(const std::string& command);

// A whole text file ("" when it cannot be read).
std::string ReadTextFile(const std::string& path);

// The number after "key": inside the JSON object that follows "section": (a flat search, enough
// for metrics.json's fixed shape); nullopt when either is absent.
std::optional<double> JsonNumber(const std::string& json, const std::string& section,
                                 const std::string& key);

}  // namespace sightline::testing
