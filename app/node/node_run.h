// How sightline-node runs one pipeline: the arguments it takes and the run itself (the same
// RunPipeline/RunHeadless loop as `sightline-cli run`, with a per-frame hook that publishes).
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline::node {

// sightline-node's exit codes: those of `sightline-cli run` (0, 1, 3, 130) and 4: the ROS master
// went away during the run; the run went on to its end (already connected subscribers kept
// receiving, the results so far were written) but the node could not be reached anew.
constexpr int kExitMasterLost = 4;

struct NodeArgs {
  std::string pipeline;
  std::string source;             // Dataset, recording, sensor URI, sim:// or ros:// source.
  std::string profile;            // YAML options profile, optional.
  std::vector<std::string> sets;  // --set key=value, after the private parameters.
  bool recorded_rate = true;      // --rate recorded (default) or max.
  std::string out_dir;            // The run's files; default $ROS_HOME/sightline/PIPELINE.
  double linger_s =
      -1;  // After the source ends: serve latched topics this long; -1: until shutdown.
};

// Parses the arguments left after ros::init took the ROS remappings. Prints --help and returns
// a Cancelled status for it.
StatusOr<NodeArgs> ParseNodeArgs(const std::vector<std::string>& args);

// Runs the node (ros::init done): advertises, reads the private parameters, runs the pipeline,
// lingers, and returns the exit code. `cancel` is set by SIGINT/SIGTERM, and by the node when
// ROS shuts it down (rosnode kill).
int RunNode(const NodeArgs& args, std::atomic<bool>& cancel);

}  // namespace sightline::node
