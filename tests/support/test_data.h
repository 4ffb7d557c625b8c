// Where tests find the real recorded data (../shared/data by default, or $SIGHTLINE_DATA_DIR).
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace sightline::testing {

// The data folder, without checking that it exists.
std::string DataDir();

// Full path of `relative` inside the data folder, or "" when it is absent.
std::string DataPath(const std::string& relative);

// A fresh empty temporary folder for one test, removed at process exit.
std::string TempDir(const std::string& name);

// The whole content of a file, byte for byte ("" when it cannot be read).
std::string ReadAll(const std::string& path);

}  // namespace sightline::testing

// Skips the current test, saying which data is missing and how to provide it.
#define SIGHTLINE_REQUIRE_DATA(var, relative)                                         \
  const std::string var = ::sightline::testing::DataPath(relative);                   \
  if (var.empty()) {                                                                  \
    GTEST_SKIP() << "recorded data '" << (relative) << "' not found in "              \
                 << ::sightline::testing::DataDir()                                   \
                 << " (set SIGHTLINE_DATA_DIR to the folder holding ../shared/data)"; \
  }
