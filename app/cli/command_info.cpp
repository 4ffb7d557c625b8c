#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "app/cli/info_output.h"
#include "core/common/json_writer.h"
#include "core/io/dataset.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sensors/driver_registry.h"

#ifdef SIGHTLINE_HAVE_ROS
#include "core/ros/bag_topics.h"
#endif

namespace sightline::cli {

namespace {

#ifdef SIGHTLINE_HAVE_ROS
// What one pipeline would read from a bag.
struct BagPipelineUse {
  std::string pipeline;
  std::optional<BagTopicChoice> choice;  // None when the bag has no frames it takes.
  std::string kind_word;                 // "stereo" when it needs --set io.rosbag.kind=stereo.
  std::string needs;                     // "stereo frames" when there is no choice.
};

// For each pipeline, the frames it would read from the bag (the opened source's kind when it
// takes that), and with which option when the automatic choice is another kind.
std::vector<BagPipelineUse> BagPipelineUses(const BagSummary& bag, const RosBagOptions& options,
                                            const Source* opened) {
  static const char* const kKindWords[] = {"rgbd", "stereo", "mono", "cloud"};
  const std::vector<BagTopicChoice> possible = PossibleBagChoices(bag, options);
  std::vector<BagPipelineUse> uses;
  const PipelineRegistry registry = BuiltinPipelines();
  for (const PipelineInfo& p : registry.pipelines()) {
    BagPipelineUse use;
    use.pipeline = p.name;
    for (const BagTopicChoice& c : possible) {
      if (!p.Accepts(c.kind)) continue;
      if (!use.choice || (opened != nullptr && c.kind == opened->info().kind)) use.choice = c;
    }
    if (!use.choice) {
      std::string kinds;
      for (SourceKind k : p.accepts)
        kinds += (kinds.empty() ? "" : " or ") + std::string(SourceKindName(k));
      use.needs = (kinds.empty() ? std::string("frames") : kinds) + " frames";
    } else if (opened == nullptr || use.choice->kind != opened->info().kind) {
      use.kind_word = kKindWords[static_cast<int>(use.choice->kind)];
    }
    uses.push_back(std::move(use));
  }
  return uses;
}

// "pipelines:" lines of `info`.
std::string BagPipelinesText(const std::vector<BagPipelineUse>& uses) {
  std::string text = "pipelines:\n";
  for (const BagPipelineUse& use : uses) {
    text += "  " + use.pipeline + ": ";
    if (!use.choice) {
      text += "no (needs " + use.needs + ")\n";
      continue;
    }
    text += use.choice->Describe();
    if (!use.kind_word.empty()) text += " (with --set io.rosbag.kind=" + use.kind_word + ")";
    text += "\n";
  }
  return text;
}

// `info --json`'s "pipelines": {"mapping": {"reads": "...", "set": "io.rosbag.kind=mono" or
// null, "needs": null}, "stereo-vo": {"reads": null, "set": null, "needs": "stereo frames"}}.
std::string BagPipelinesJson(const std::vector<BagPipelineUse>& uses) {
  JsonWriter w;
  w.BeginObject();
  for (const BagPipelineUse& use : uses) {
    w.Key(use.pipeline).BeginObject();
    w.Key("reads");
    use.choice ? w.String(use.choice->Describe()) : w.Null();
    w.Key("set");
    use.kind_word.empty() ? w.Null() : w.String("io.rosbag.kind=" + use.kind_word);
    w.Key("needs");
    use.needs.empty() ? w.Null() : w.String(use.needs);
    w.EndObject();
  }
  w.EndObject();
  return w.str();
}

// `info --json` of a bag: the source's object (or the path and the error when its frames
// cannot be read) with "bag" and "pipelines" added.
std::string BagInfoJson(const std::string& path, const BagSummary& bag,
                        const StatusOr<std::unique_ptr<Source>>& source,
                        const std::vector<BagPipelineUse>& uses) {
  std::string head;
  if (source.ok()) {
    head = DescribeSourceJson(**source);
    head.erase(head.find_last_of('}'));  // Reopen the object to add the bag's keys.
    while (!head.empty() && (head.back() == '\n' || head.back() == ' ')) head.pop_back();
    head += ",\n";
  } else {
    head = "{\n  \"path\": \"" + JsonWriter::Escape(path) + "\",\n  \"error\": \"" +
           JsonWriter::Escape(source.status().ToString()) + "\",\n";
  }
  const auto indented = [](std::string json) {  // One level deeper than the top object.
    for (size_t i = json.find('\n'); i != std::string::npos; i = json.find('\n', i + 3)) {
      json.insert(i + 1, "  ");
    }
    return json;
  };
  return head + "  \"bag\": " + indented(DescribeBagSummaryJson(bag)) +
         ",\n  \"pipelines\": " + indented(BagPipelinesJson(uses)) + "\n}\n";
}
#endif

// `info` of a .bag: its topics, then the source (when its frames can be read) and what each
// pipeline would use. Returns the exit code.
int BagInfo(const std::string& path, const OptionSet& options, bool json) {
#ifdef SIGHTLINE_HAVE_ROS
  StatusOr<BagSummary> bag = ReadBagSummary(path);
  if (!bag.ok()) return Fail(bag.status().ToString());
  StatusOr<std::unique_ptr<Source>> source = OpenSource(path, options);
  const std::vector<BagPipelineUse> uses = BagPipelineUses(
      *bag, options.Extract(RosBagOptions::Describe()), source.ok() ? source->get() : nullptr);
  if (json) {
    std::fputs(BagInfoJson(path, *bag, source, uses).c_str(), stdout);
    return source.ok() ? 0 : Fail(source.status().ToString());
  }
  std::string text = DescribeBagSummaryText(*bag);
  if (source.ok()) text += DescribeSourceText(**source);
  text += BagPipelinesText(uses);
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
      "stereo-vo') chooses topics. With --json a .bag adds \"bag\" (topics) and \"pipelines\".\n";
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
  return PrintSourceInfo(**source, parsed->Has("--json"));
}

}  // namespace sightline::cli
