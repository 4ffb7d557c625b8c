#include <cstdio>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "core/io/dataset.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sensors/driver_registry.h"

#ifdef SIGHTLINE_HAVE_ROS
#include "core/ros/bag_topics.h"
#endif

namespace sightline::cli {

int Fail(const std::string& message) {
  std::fprintf(stderr, "sightline-cli: %s\n", message.c_str());
  return 1;
}

namespace {

#ifdef SIGHTLINE_HAVE_ROS
// "pipelines:" lines of a bag: what each pipeline would read from it, and with which option
// when the automatic choice is another kind.
std::string BagPipelinesText(const BagSummary& bag, const RosBagOptions& options,
                             const Source* opened) {
  const std::vector<BagTopicChoice> possible = PossibleBagChoices(bag, options);
  std::string text = "pipelines:\n";
  const PipelineRegistry registry = BuiltinPipelines();
  for (const PipelineInfo& p : registry.pipelines()) {
    std::string line = "  " + p.name + ": ";
    const BagTopicChoice* use = nullptr;
    for (const BagTopicChoice& c : possible) {
      if (!p.Accepts(c.kind)) continue;
      if (use == nullptr || (opened != nullptr && c.kind == opened->info().kind)) use = &c;
    }
    if (use == nullptr) {
      std::string kinds;
      for (SourceKind k : p.accepts)
        kinds += (kinds.empty() ? "" : " or ") + std::string(SourceKindName(k));
      line += "no (needs " + (kinds.empty() ? std::string("frames") : kinds) + " frames)";
    } else {
      line += use->Describe();
      if (opened == nullptr || use->kind != opened->info().kind) {
        static const char* const kKindWords[] = {"rgbd", "stereo", "mono", "cloud"};
        line += std::string(" (with --set io.rosbag.kind=") +
                kKindWords[static_cast<int>(use->kind)] + ")";
      }
    }
    text += line + "\n";
  }
  return text;
}
#endif

// `info` of a .bag: its topics, then the source (when its frames can be read) and what each
// pipeline would use. Returns the exit code.
int BagInfo(const std::string& path, const OptionSet& options, bool json) {
#ifdef SIGHTLINE_HAVE_ROS
  StatusOr<BagSummary> bag = ReadBagSummary(path);
  if (!bag.ok()) return Fail(bag.status().ToString());
  StatusOr<std::unique_ptr<Source>> source = OpenSource(path, options);
  if (json) {
    if (!source.ok()) return Fail(source.status().ToString());
    std::fputs((DescribeSourceJson(**source) + "\n").c_str(), stdout);
    return 0;
  }
  std::string text = DescribeBagSummaryText(*bag);
  if (source.ok()) text += DescribeSourceText(**source);
  text += BagPipelinesText(*bag, options.Extract(RosBagOptions::Describe()),
                           source.ok() ? source->get() : nullptr);
  std::fputs(text.c_str(), stdout);
  if (!source.ok()) return Fail(source.status().ToString());
  return 0;
#else
  return Fail(path + ": ROS bags need a build with SIGHTLINE_WITH_ROS=ON");
#endif
}

}  // namespace

int InfoCommand(const std::vector<std::string>& args) {
  static const char kHelp[] =
      "usage: sightline-cli info PATH [--json] [--set key=value]...\n"
      "\n"
      "Detects the format of PATH (TUM RGB-D, EuRoC MAV, KITTI odometry, image folder, PCD file\n"
      "or folder, an OpenNI2 .oni file, a ROS .bag file, a recording with one sub-folder per\n"
      "sensor, or a sensor URI: openni2://, aravis://ID, v4l2://0) and prints its frames,\n"
      "resolution, calibration, ground truth and duration. --json prints the same as JSON.\n"
      "A .bag also lists its topics (type, messages), duration and compression, and what each\n"
      "pipeline would read from it; --set io.rosbag.image_topic=... (see 'sightline-cli options\n"
      "stereo-vo') chooses topics.\n";
  StatusOr<CliArgs> parsed = CliArgs::Parse(args, {"--set"}, {"--json", "--help"});
  if (!parsed.ok()) return Fail("info: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (parsed->positionals().size() != 1) return Fail("info: expected one PATH (see --help)");
  const std::string path = parsed->positionals()[0];
  OptionSet options;
  if (Status declared = DeclareSensorOptions(&options); !declared.ok()) {
    return Fail(declared.ToString());
  }
  for (const std::string& assignment : parsed->Values("--set")) {
    if (Status set = options.ApplyOverride(assignment); !set.ok()) {
      return Fail("info: " + set.ToString());
    }
  }
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".bag") == 0) {
    return BagInfo(path, options, parsed->Has("--json"));
  }
  StatusOr<std::unique_ptr<Source>> source = OpenSource(path, options);
  if (!source.ok()) return Fail(source.status().ToString());
  const std::string text =
      parsed->Has("--json") ? DescribeSourceJson(**source) : DescribeSourceText(**source);
  std::fputs(text.c_str(), stdout);
  if (!text.empty() && text.back() != '\n') std::fputc('\n', stdout);
  return 0;
}

}  // namespace sightline::cli
