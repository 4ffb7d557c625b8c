// A plain folder of frames, as a user's video frames or photos without an arm: the simulator's
// mono images and camera.yaml only (no times.txt, no ground truth, no arm poses, no buttons).
#pragma once

#include <filesystem>
#include <string>

namespace sightline::testing {

// Copies `sim_dir`/mono/*.png and camera.yaml into `plain_dir` (created); the number of images.
inline int MakePlainFrameFolder(const std::string& sim_dir, const std::string& plain_dir) {
  namespace fs = std::filesystem;
  fs::create_directories(plain_dir);
  int images = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(fs::path(sim_dir) / "mono")) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() == ".png" || name == "camera.yaml") {
      fs::copy_file(e.path(), fs::path(plain_dir) / name, fs::copy_options::overwrite_existing);
      images += e.path().extension() == ".png" ? 1 : 0;
    }
  }
  return images;
}

}  // namespace sightline::testing
