// What sightline-cli prints before any command runs: the usage and the version line. Shared by
// the front binary (sightline-cli) and the full program (sightline-cli-full) so both say the same.
#pragma once

#include <optional>

namespace sightline::cli {

// The top-level usage text of `sightline-cli --help`.
extern const char kUsage[];

// Handles a command line without a command (usage to stderr, 2), --help or -h (usage, 0) and
// --version or -v (the version and git commit, 0). nullopt when argv[1] is a command.
std::optional<int> RunTopLevel(int argc, char** argv);

}  // namespace sightline::cli
