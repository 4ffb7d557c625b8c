#include "app/cli/full_program.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "app/cli/commands.h"

namespace sightline::cli {
namespace {

constexpr char kFullProgram[] = "sightline-cli-full";

// The folder of this executable, "" when /proc/self/exe cannot be read.
std::string OwnFolder() {
  std::string path(4096, '\0');
  const ssize_t n = readlink("/proc/self/exe", path.data(), path.size());
  if (n <= 0 || static_cast<size_t>(n) >= path.size()) return "";
  path.resize(static_cast<size_t>(n));
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash);
}

}  // namespace

std::vector<std::string> ProgramCandidates(const std::string& name) {
  const std::string folder = OwnFolder();
  if (folder.empty()) return {};
  return {folder + "/" + name, folder + "/" + SIGHTLINE_FULL_CLI_FROM_BIN + "/" + name};
}

std::vector<std::string> FullProgramCandidates() { return ProgramCandidates(kFullProgram); }

bool HandOverToProgram(const std::string& name, char** argv) {
  for (const std::string& path : ProgramCandidates(name)) {
    if (access(path.c_str(), X_OK) == 0) {
      execv(path.c_str(), argv);
      return false;
    }
  }
  return false;
}

int HandOverToFullProgram(char** argv) {
  const std::vector<std::string> candidates = FullProgramCandidates();
  if (candidates.empty()) {
    return Fail(std::string("cannot find sightline-cli-full: /proc/self/exe is unreadable (") +
                std::strerror(errno) + ")");
  }
  std::string looked;
  for (const std::string& path : candidates) {
    if (access(path.c_str(), F_OK) != 0) {
      looked += (looked.empty() ? "" : ", ") + path;
      continue;
    }
    execv(path.c_str(), argv);
    return Fail("cannot run " + path + ": " + std::strerror(errno));
  }
  return Fail("'" + std::string(argv[1]) + "' needs " + kFullProgram +
              ", the program with every command, which is missing (looked for " + looked +
              "); reinstall Sightline");
}

}  // namespace sightline::cli
