// sightline-node's command line (what ros::init left of it).
#include <cstdio>
#include <cstdlib>

#include "app/cli/cli_args.h"
#include "app/node/node_run.h"

namespace sightline::node {

namespace {

const char kHelp[] =
    "usage: sightline-node --pipeline NAME --source URI_OR_PATH [--profile F]\n"
    "                      [--set key=value]... [--rate recorded|max] [--out DIR]\n"
    "                      [--linger S] [ROS remappings: name:=/other __ns:=/robot _key:=v]\n"
    "\n"
    "A ROS 1 node that runs one Sightline pipeline (the same loop as 'sightline-cli run') on a\n"
    "dataset, recording, sensor URI, sim:// or ros:// source and publishes its results stamped\n"
    "with each frame's sensor time (topics and frames: README \"ROS node\").\n"
    "Options: the profile first, then the private parameters (option mapping.ransac.threshold\n"
    "is ~mapping/ransac/threshold, e.g. _mapping/ransac/threshold:=0.05), then --set.\n"
    "--rate recorded (default) publishes at the recording's pace, max as fast as it runs.\n"
    "--out: the run's files and metrics.json (default $ROS_HOME/sightline/PIPELINE).\n"
    "--linger S: after the source ends, keep serving the latched topics S seconds (default:\n"
    "until Ctrl-C or rosnode kill).\n"
    "'sightline-node --version' prints the version and the git commit it was built from.\n"
    "\nExit codes: 0 results written; 1 an error (no master, bad option, source, data);\n"
    "3 the run achieved nothing; 4 the ROS master went away during the run (the run went on to\n"
    "its end and wrote its files; subscribers already connected kept receiving); 130 cancelled\n"
    "(Ctrl-C, SIGTERM, rosnode kill), results up to then written.\n";

std::string DefaultOutDir(const std::string& pipeline) {
  const char* ros_home = std::getenv("ROS_HOME");
  const char* home = std::getenv("HOME");
  const std::string base = ros_home != nullptr && *ros_home != '\0'
                               ? std::string(ros_home)
                               : std::string(home != nullptr ? home : ".") + "/.ros";
  return base + "/sightline/" + pipeline;
}

}  // namespace

StatusOr<NodeArgs> ParseNodeArgs(const std::vector<std::string>& args) {
  StatusOr<cli::CliArgs> parsed = cli::CliArgs::Parse(
      args, {"--pipeline", "--source", "--profile", "--set", "--rate", "--out", "--linger"},
      {"--help"});
  if (!parsed.ok()) return parsed.status();
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return Cancelled("help");
  }
  if (!parsed->positionals().empty()) {
    return InvalidArgument("unexpected argument '" + parsed->positionals()[0] + "' (see --help)");
  }
  NodeArgs out;
  out.pipeline = parsed->Value("--pipeline").value_or("");
  out.source = parsed->Value("--source").value_or("");
  if (out.pipeline.empty()) return InvalidArgument("--pipeline NAME is required (see --help)");
  if (out.source.empty()) return InvalidArgument("--source URI_OR_PATH is required (see --help)");
  out.profile = parsed->Value("--profile").value_or("");
  out.sets = parsed->Values("--set");
  const std::string rate = parsed->Value("--rate").value_or("recorded");
  if (rate != "recorded" && rate != "max") {
    return InvalidArgument("--rate takes recorded or max, got '" + rate + "'");
  }
  out.recorded_rate = rate == "recorded";
  out.out_dir = parsed->Value("--out").value_or(DefaultOutDir(out.pipeline));
  if (auto linger = parsed->Value("--linger")) {
    char* end = nullptr;
    out.linger_s = std::strtod(linger->c_str(), &end);
    if (end == linger->c_str() || *end != '\0') {
      return InvalidArgument("--linger takes seconds, got '" + *linger + "'");
    }
  }
  return out;
}

}  // namespace sightline::node
