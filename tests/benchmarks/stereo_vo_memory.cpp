// The memory stereo visual odometry needs: streams a stereo dataset frame by frame through
// StereoOdometry (default options, the dataset's rig), as `sightline-cli run stereo-vo` does, in
// a program that links core/stereo and core/io's readers only, and prints the peak resident set
// (VmHWM) with its anonymous and file-backed parts. Compare with `/usr/bin/time -f %M
// sightline-cli run stereo-vo PATH --out DIR` (README, "Start-up and memory").
// Run: build/bin/measure_stereo_vo_memory [PATH]   (default: kitti_clip1 of the data folder)
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/io/dataset.h"
#include "core/stereo/stereo_odometry.h"

namespace sightline {

namespace {

// A field of /proc/self/status in KiB ("VmHWM", "RssAnon", ...), -1 when absent.
long StatusKib(const std::string& field) {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(field + ":", 0) == 0) return std::atol(line.c_str() + field.size() + 1);
  }
  return -1;
}

}  // namespace
}  // namespace sightline

int main(int argc, char** argv) {
  using namespace sightline;
  const char* env = std::getenv("SIGHTLINE_DATA_DIR");
  const std::string path =
      argc > 1 ? argv[1] : std::string(env ? env : SIGHTLINE_DEFAULT_DATA_DIR) + "/kitti_clip1";
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(path, SourceKind::kStereo);
  if (!source.ok() || !(*source)->info().stereo) {
    std::fprintf(stderr, "%s: %s\n", path.c_str(),
                 source.ok() ? "no stereo rig" : source.status().ToString().c_str());
    return 1;
  }
  StereoOdometry odometry;
  if (Status s = odometry.Configure(*(*source)->info().stereo); !s.ok()) {
    std::fprintf(stderr, "%s\n", s.ToString().c_str());
    return 1;
  }
  std::vector<Eigen::Isometry3d> trajectory;  // What the run keeps: a pose per frame.
  TimingStats timing;
  while ((*source)->Grab().ok()) {
    StatusOr<Frame> frame = (*source)->Retrieve();
    if (!frame.ok()) {
      std::fprintf(stderr, "%s\n", frame.status().ToString().c_str());
      return 1;
    }
    auto result = odometry.Process(std::get<StereoFrame>(*frame), &timing);
    if (!result.ok()) {
      std::fprintf(stderr, "%s\n", result.status().ToString().c_str());
      return 1;
    }
    trajectory.push_back((*result)->world_from_camera);
  }
  std::printf("stereo odometry on %s: %zu frames\n", path.c_str(), trajectory.size());
  std::printf("VmHWM %ld KiB (%.1f MiB), RssAnon %ld KiB, RssFile %ld KiB at the end\n",
              StatusKib("VmHWM"), StatusKib("VmHWM") / 1024.0, StatusKib("RssAnon"),
              StatusKib("RssFile"));
  return trajectory.empty() ? 1 : 0;
}
