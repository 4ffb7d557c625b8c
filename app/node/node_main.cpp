// sightline-node: a ROS 1 node that runs one Sightline pipeline on any source and publishes its
// results (README "ROS node").
#include <ros/init.h>
#include <signal.h>

#include <atomic>
#include <cstdio>
#include <cstring>

#include "app/node/node_run.h"
#include "sightline_version.h"

namespace {

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);
void OnInterrupt(int) { g_interrupted.store(true); }

// SA_RESETHAND: a second Ctrl-C ends a node that does not stop by itself.
void InstallInterruptHandlers() {
  struct sigaction action {};
  action.sa_handler = OnInterrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && (std::strcmp(argv[1], "--version") == 0 || std::strcmp(argv[1], "-v") == 0)) {
    std::printf("sightline-node %s (commit %s)\n", SIGHTLINE_VERSION, SIGHTLINE_GIT_COMMIT);
    return 0;
  }
  // ros::init takes the remappings (topic:=/other, __name:=, __ns:=, _param:=value) out of argv.
  ros::init(argc, argv, "sightline", ros::init_options::NoSigintHandler);
  const std::vector<std::string> args(argv + 1, argv + argc);
  sightline::StatusOr<sightline::node::NodeArgs> parsed = sightline::node::ParseNodeArgs(args);
  if (!parsed.ok()) {
    if (parsed.status().code() == sightline::StatusCode::kCancelled) return 0;  // --help.
    std::fprintf(stderr, "sightline-node: %s\n", parsed.status().message().c_str());
    return 1;
  }
  InstallInterruptHandlers();
  return sightline::node::RunNode(*parsed, g_interrupted);
}
