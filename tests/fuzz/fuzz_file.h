// Helpers for the libFuzzer targets: the readers take paths, so each input is written to a
// file in a folder of its own (one per fuzzing process) and the real reader reads it.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace sightline::fuzz {

// A folder for this process's files, made on first use under $TMPDIR (or /tmp).
inline const std::string& ScratchDir() {
  static const std::string dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp != nullptr ? tmp : "/tmp") + "/sightline-fuzz-XXXXXX";
    if (mkdtemp(pattern.data()) == nullptr) std::abort();
    return pattern;
  }();
  return dir;
}

// Writes `size` bytes to `relative` (folders created) inside ScratchDir(); returns the path.
inline std::string WriteInput(const std::string& relative, const uint8_t* data, size_t size) {
  const std::filesystem::path path = std::filesystem::path(ScratchDir()) / relative;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path.string();
}

// The input as a string (for parsers of text).
inline std::string AsText(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace sightline::fuzz
