#include "app/cli/run_outputs.h"

#include <cstdio>
#include <filesystem>
#include <map>

namespace sightline::cli {

namespace {

constexpr size_t kMaxListed = 20;

const std::map<std::string, std::string>& OutputTable() {
  static const std::map<std::string, std::string> table = {
      {"inspect",
       "  frames.csv          every frame read: index, time, decoding figure, ground truth or "
       "not\n"},
      {"mapping",
       "  trajectory.txt      the robot's path (TUM format)\n"
       "  map.pgm, map.yaml   the stitched occupancy map (ROS map_server format), map.png\n"
       "  floor.yaml          the fitted floor plane (reusable with --set mapping.run.floor_file)\n"
       "  lines.csv           the wall lines found in every frame\n"
       "  mapping_log.txt     the run's log: floor fit and a line per frame\n"},
      {"mobility",
       "  NNNNNN_projection.png, NNNNNN_topview.png   the mobility map of every frame\n"
       "  segments.csv        the scored segments of every frame (slope, roughness, scores)\n"
       "  mobility_log.txt    the run's notes\n"},
      {"stereo-vo",
       "  trajectory.txt      the camera's path (TUM, or KITTI poses with --format kitti)\n"
       "  frames.csv          per frame: tracks, inliers, residual, gating, timing\n"
       "  stereo_vo_notes.txt the run's notes (when there are any)\n"},
      {"mono-slam",
       "  trajectory.txt      the camera's path in metres (TUM format)\n"
       "  trajectory_map.txt  the same path in the map's own scale\n"
       "  map.ply             the map points; keyframes.txt the keyframe poses\n"
       "  scale.csv           the metric scale estimates over the run\n"
       "  frames.csv          per frame: tracked features, inliers, state\n"
       "  mono_slam_notes.txt the run's notes\n"},
      {"button",
       "  button.csv          per frame: the tracked button, its 3D position, what was sent\n"
       "  button_notes.txt    the run's notes: tap, hand-eye, targets sent or why not\n"},
  };
  return table;
}

}  // namespace

std::string RunOutputsHelp(const std::string& pipeline) {
  const auto it = OutputTable().find(pipeline);
  const std::string files = it == OutputTable().end() ? std::string() : it->second;
  return files +
         "  metrics.json        frames, per-stage timing, accuracy, the effective options\n";
}

void PrintWrittenFiles(const std::string& out_dir, const std::vector<std::string>& outputs) {
  bool metrics_listed = false;
  for (size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i] == "metrics.json") metrics_listed = true;
    if (i < kMaxListed || outputs[i] == "metrics.json") {
      std::printf("wrote %s\n", (std::filesystem::path(out_dir) / outputs[i]).string().c_str());
    }
  }
  if (outputs.size() > kMaxListed) {
    std::printf("wrote %zu more files in %s\n",
                outputs.size() - kMaxListed - (metrics_listed ? 1 : 0), out_dir.c_str());
  }
  if (!metrics_listed) {
    std::printf("wrote %s\n", (std::filesystem::path(out_dir) / "metrics.json").string().c_str());
  }
}

}  // namespace sightline::cli
