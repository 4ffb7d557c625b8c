// sightline-cli simulate: writes a simulated recording that `info` and every `run` read.
#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "app/cli/progress.h"
#include "app/cli/simulate_bag.h"
#include "core/options/option_set.h"
#include "core/sim/simulate.h"

namespace sightline::cli {

namespace {

const char kHelp[] =
    "usage: sightline-cli simulate SCENE --out DIR [--frames N] [--seed S] [--noise PROFILE]\n"
    "                              [--sensors rgbd,stereo,mono] [--profile F]\n"
    "                              [--set sim.KEY=VALUE]... [--format folders|bag]\n"
    "                              [--options] [--quiet]\n"
    "\n"
    "Renders a simulated recording of SCENE into DIR, deterministically for a given seed:\n"
    "  corridor  office corridor loop with doors, posters, boxes, bins and walking people;\n"
    "            a robot drives it (Kinect at 0.8 m, wheel odometry) [rgbd,stereo]\n"
    "  terrain   floor with a ramp, a step, a rough patch, boxes and a wall, every region's\n"
    "            slope and roughness known [rgbd]\n"
    "  panel     wall with an elevator button panel approached by an arm camera [mono]\n"
    "\n"
    "DIR gets one folder per sensor (rgbd/ TUM RGB-D, stereo/ KITTI, mono/ image folder) and the\n"
    "ground truth: body_groundtruth.txt, odometry.txt or arm_poses.txt + hand_eye.yaml,\n"
    "walls.csv, regions.csv, buttons.csv, people.csv and scene.yaml (see core/sim/README.md).\n"
    "'sightline-cli info DIR' and 'sightline-cli run PIPELINE DIR' pick the sensor they need.\n"
    "\n"
    "  --frames N      frames per sensor (corridor 300, terrain 60, panel 150)\n"
    "  --seed S        seed of everything random (default 1); equal seeds write equal bytes\n"
    "  --noise P       none | kinect (default) | noisy\n"
    "  --sensors L     sensors to render, e.g. rgbd,stereo,mono (default: the scene's)\n"
    "  --profile F     YAML profile of sim.* options\n"
    "  --set K=V       any sim.* option, e.g. sim.rgbd.resolution=320x240,\n"
    "                  sim.terrain.ramp_slope_deg=30, sim.stereo.baseline_m=0.54\n"
    "  --format bag    write DIR/SCENE.bag instead: a ROS bag of the sensors' images and\n"
    "                  camera_info, the cameras' true poses on /tf, wheel odometry on /odom and\n"
    "                  an arm's poses on /tf (stamps = simulator times + 1 s); read it with\n"
    "                  'sightline-cli info|run ... DIR/SCENE.bag'\n"
    "  --options       list every sim.* option with its default and range, then exit\n"
    "  --quiet         print nothing on success\n";

std::atomic<bool> g_interrupted{false};
void OnInterrupt(int) { g_interrupted = true; }

// The effective options: the scene's defaults, then the profile, --set and the flags.
StatusOr<sim::SimulationOptions> OptionsFromArgs(const std::string& scene, const CliArgs& args,
                                                 OptionSet* set) {
  const auto table = sim::SimulationOptions::Describe();
  SIGHTLINE_RETURN_IF_ERROR(set->Declare(table, sim::SimulationOptions::ForScene(scene)));
  SIGHTLINE_RETURN_IF_ERROR(set->SetFromString("sim.scene", scene, "SCENE"));
  if (auto profile = args.Value("--profile")) SIGHTLINE_RETURN_IF_ERROR(set->LoadYaml(*profile));
  for (const std::string& assignment : args.Values("--set")) {
    SIGHTLINE_RETURN_IF_ERROR(set->ApplyOverride(assignment));
  }
  const std::pair<const char*, const char*> flags[] = {
      {"--frames", "sim.frames"},
      {"--seed", "sim.seed"},
      {"--noise", "sim.noise.profile"},
      {"--sensors", "sim.sensors"},
  };
  for (const auto& [flag, key] : flags) {
    if (auto value = args.Value(flag))
      SIGHTLINE_RETURN_IF_ERROR(set->SetFromString(key, *value, flag));
  }
  sim::SimulationOptions options = set->Extract(table, sim::SimulationOptions::ForScene(scene));
  if (options.scene != scene) {
    return InvalidArgument("sim.scene = '" + options.scene + "' contradicts SCENE '" + scene + "'");
  }
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  return options;
}

void PrintOptions(const OptionSet& set) {
  for (const OptionSpec& spec : set.specs()) {
    std::string range;
    if (spec.type == OptionType::kInt || spec.type == OptionType::kDouble) {
      range = "[";
      range += FormatOptionValue(spec.min) + ", " + FormatOptionValue(spec.max) + "]";
    } else if (spec.type == OptionType::kChoice) {
      for (const auto& c : spec.choices) range += (range.empty() ? "{" : "|") + c;
      range += "}";
    }
    auto value = set.Get(spec.key);
    std::printf("%-36s %-10s %-20s %-9s %s\n", spec.key.c_str(),
                value.ok() ? FormatOptionValue(*value).c_str() : "?", range.c_str(),
                spec.unit.c_str(), spec.description.c_str());
  }
}

}  // namespace

int SimulateCommand(const std::vector<std::string>& args) {
  StatusOr<CliArgs> parsed = CliArgs::Parse(
      args,
      {"--out", "--frames", "--seed", "--noise", "--sensors", "--profile", "--set", "--format"},
      {"--help", "--quiet", "--options"});
  if (!parsed.ok()) return Fail("simulate: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (parsed->positionals().size() != 1) {
    return Fail("simulate: expected one SCENE (corridor, terrain or panel; see --help)");
  }
  const std::string scene = parsed->positionals()[0];
  const auto& names = sim::SceneNames();
  if (std::find(names.begin(), names.end(), scene) == names.end()) {
    return Fail("simulate: unknown scene '" + scene + "' (corridor, terrain or panel)");
  }
  OptionSet set;
  StatusOr<sim::SimulationOptions> options = OptionsFromArgs(scene, *parsed, &set);
  if (!options.ok()) return Fail("simulate: " + options.status().ToString());
  if (parsed->Has("--options")) {
    PrintOptions(set);
    return 0;
  }
  if (!parsed->Value("--out")) return Fail("simulate: --out DIR is required");
  const std::string out = *parsed->Value("--out");

  const std::string format = parsed->Value("--format").value_or("folders");
  if (format != "folders" && format != "bag") {
    return Fail("simulate: --format is folders or bag, not '" + format + "'");
  }
  ProgressLine progress("simulate " + scene);
  if (format == "bag") {
    std::signal(SIGINT, OnInterrupt);
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) return Fail("simulate: cannot create output folder " + out + ": " + ec.message());
    StatusOr<SimulatedBag> bag = SimulateToBag(
        *options, out + "/" + scene + ".bag",
        [&progress](int64_t done, int64_t total) { progress.Update(done, total); }, &g_interrupted);
    progress.Finish();
    if (!bag.ok()) return Fail("simulate " + scene + ": " + bag.status().ToString());
    if (!parsed->Has("--quiet")) {
      std::printf("wrote %s: %d frames, %lld messages\n", bag->path.c_str(), bag->frames,
                  static_cast<long long>(bag->messages));
    }
    return 0;
  }
  sim::SimulationCallbacks callbacks;
  callbacks.progress = [&progress](int64_t done, int64_t total) { progress.Update(done, total); };
  callbacks.cancel = &g_interrupted;
  std::signal(SIGINT, OnInterrupt);
  StatusOr<sim::SimulationSummary> summary = sim::Simulate(*options, out, callbacks);
  progress.Finish();
  if (!summary.ok()) return Fail("simulate " + scene + ": " + summary.status().ToString());
  if (parsed->Has("--quiet")) return 0;

  const sim::SimulationSummary& s = *summary;
  std::string sensors;
  for (const std::string& sensor : s.sensors) sensors += (sensors.empty() ? "" : ", ") + sensor;
  std::printf("simulated %s (%s motion, seed %d, noise %s): %d frames of %s\n", s.scene.c_str(),
              s.motion.c_str(), options->seed, options->noise.profile.c_str(), s.frames,
              sensors.c_str());
  std::printf("wrote %s: %lld images and\n", s.dir.c_str(), static_cast<long long>(s.images));
  for (const std::string& file : s.files) std::printf("  %s\n", file.c_str());
  const double ms_per_frame = s.frames > 0 ? 1000.0 * s.render_s / s.frames : 0;
  std::printf(
      "rendered %.1f frames/s (%.1f ms per frame, all sensors); %.2f s in total with "
      "writing\n",
      s.render_fps, ms_per_frame, s.total_s);
  return 0;
}

}  // namespace sightline::cli
