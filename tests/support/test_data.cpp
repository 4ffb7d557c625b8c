#include "tests/support/test_data.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <vector>

namespace sightline::testing {

std::string DataDir() {
  if (const char* env = std::getenv("SIGHTLINE_DATA_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  return SIGHTLINE_DEFAULT_DATA_DIR;
}

std::string DataPath(const std::string& relative) {
  std::error_code ec;
  const std::filesystem::path path = std::filesystem::path(DataDir()) / relative;
  if (!std::filesystem::exists(path, ec)) return "";
  return std::filesystem::canonical(path, ec).string();
}

namespace {
std::mutex g_mutex;
std::vector<std::filesystem::path>* g_dirs = nullptr;
void RemoveAll() {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (g_dirs == nullptr) return;
  for (const auto& d : *g_dirs) {
    std::error_code ec;
    std::filesystem::remove_all(d, ec);
  }
}
}  // namespace

std::string TempDir(const std::string& name) {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (g_dirs == nullptr) {
    g_dirs = new std::vector<std::filesystem::path>();
    std::atexit(RemoveAll);
  }
  std::string pattern =
      (std::filesystem::temp_directory_path() / ("sightline_" + name + "_XXXXXX")).string();
  char* made = mkdtemp(pattern.data());
  if (made == nullptr) return "";
  g_dirs->push_back(made);
  return made;
}

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace sightline::testing
