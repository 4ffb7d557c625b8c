// Helpers for the dataset reader tests: build malformed or re-arranged copies of the recorded
// data in a temporary folder. The shared data itself is never modified.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline::testing {

// Copies one file (a real copy, so the test may change it).
inline void CopyFileTo(const std::string& from, const std::string& to) {
  std::filesystem::create_directories(std::filesystem::path(to).parent_path());
  std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
}

// Links `to` to `from` (file or folder): cheap stand-in for files the test does not change.
inline void LinkTo(const std::string& from, const std::string& to) {
  std::filesystem::create_directories(std::filesystem::path(to).parent_path());
  std::filesystem::create_symlink(from, to);
}

// Links every file of folder `from` into a new folder `to`, except `skip` (file names).
inline void LinkFolderFiles(const std::string& from, const std::string& to,
                            const std::vector<std::string>& skip = {}) {
  std::filesystem::create_directories(to);
  for (const auto& entry : std::filesystem::directory_iterator(from)) {
    const std::string name = entry.path().filename().string();
    if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
    std::filesystem::create_symlink(entry.path(), std::filesystem::path(to) / name);
  }
}

// Writes `text` to `path`, creating folders.
inline void WriteText(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// The lines of a text file.
inline std::vector<std::string> ReadLines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Writes lines joined by '\n'.
inline void WriteLines(const std::string& path, const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  WriteText(path, text);
}

// True when `text` contains `part`; for readable EXPECT_ messages use HasSubstr instead.
inline bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace sightline::testing
