// Gives a test process its own settings, cache and data folders (XDG_CONFIG_HOME,
// XDG_CACHE_HOME, XDG_DATA_HOME), so a GUI test never reads or writes the user's recent
// files, window layout or demo cache. Call before QApplication exists.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace sightline::testing {

// Makes the folders, sets the variables and SIGHTLINE_GUI_TEST_HOME; removes them again when
// the returned object goes away.
class IsolatedHome {
 public:
  IsolatedHome() {
    std::string home =
        (std::filesystem::temp_directory_path() / "sightline-gui-test-XXXXXX").string();
    if (mkdtemp(home.data()) == nullptr) return;
    path_ = home;
    for (const char* name : {"XDG_CONFIG_HOME", "XDG_CACHE_HOME", "XDG_DATA_HOME"}) {
      const std::string folder = home + "/" + name;
      std::filesystem::create_directories(folder);
      setenv(name, folder.c_str(), 1);
    }
    setenv("SIGHTLINE_GUI_TEST_HOME", home.c_str(), 1);
  }
  ~IsolatedHome() {
    std::error_code ignored;
    if (!path_.empty()) std::filesystem::remove_all(path_, ignored);
  }
  IsolatedHome(const IsolatedHome&) = delete;
  IsolatedHome& operator=(const IsolatedHome&) = delete;

  // Empty when the folder could not be made.
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace sightline::testing
