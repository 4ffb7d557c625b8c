// Runs a command line and captures its output and exit code, for CLI tests.
#pragma once

#include <string>

namespace sightline::testing {

struct ProcessResult {
  int exit_code = -1;
  std::string out;  // stdout and stderr together.
};

// Runs `command` through /bin/sh with stderr merged into stdout.
ProcessResult RunProcess(const std::string& command);

}  // namespace sightline::testing
