#include "tests/app/process.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sightline::testing {

ProcessResult RunProcess(const std::string& command) {
  ProcessResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string ReadTextFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::optional<double> JsonNumber(const std::string& json, const std::string& section,
                                 const std::string& key) {
  const size_t start = json.find("\"" + section + "\":");
  if (start == std::string::npos) return std::nullopt;
  const size_t end = json.find('}', json.find('{', start));
  const size_t at = json.find("\"" + key + "\":", start);
  if (at == std::string::npos || at > end) return std::nullopt;
  return std::strtod(json.c_str() + at + key.size() + 3, nullptr);
}

}  // namespace sightline::testing
