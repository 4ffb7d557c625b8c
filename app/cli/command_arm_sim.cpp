// sightline-cli arm-sim: a simulated arm that connects to Sightline's arm-target server, streams
// its pose, flies the panel approach's plan and then presses the button Sightline targets
// (core/button/arm_simulator.h). Closes the operator loop with a sim://panel camera.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "core/button/arm_client.h"
#include "core/button/arm_sim_session.h"
#include "core/options/option_set.h"

namespace sightline::cli {

namespace {

const char kHelp[] =
    "usage: sightline-cli arm-sim HOST:PORT [--token T] [--seed N] [--log FILE]\n"
    "                             [--set armsim.KEY=VALUE]...\n"
    "\n"
    "A simulated arm holding the camera of the panel scene of seed N (default 4). It connects\n"
    "to Sightline's arm-target server (core/button/PROTOCOL.md), sends its pose as arm_pose\n"
    "lines every control period (wall-clock stamps), holds still at the start pose, makes the\n"
    "sideways moves the metric scale needs and approaches the panel; then it moves to the\n"
    "targets it receives at a bounded speed: to a standoff in front of the target, then along\n"
    "the approach onto it. A stop line stops it at once; no line for 3 heartbeat periods holds\n"
    "it. Every event is printed with its time (and written to --log). At the end it prints its\n"
    "end-effector position in the base frame, the distance to the nearest true button centre\n"
    "and the angle between its tool axis and the panel normal.\n"
    "\n"
    "  --token T   present this token first (button.arm.token of the server)\n"
    "  --seed N    the panel scene (as sim://panel?seed=N of the camera)\n"
    "  --log FILE  also write the events there\n"
    "  --set K=V   an armsim.* option (speeds, standoff, plan timing; see below)\n"
    "\n"
    "Exits 0 when it reached a target and held it for armsim.settle_s, or when the server\n"
    "closed the connection after a stop; 1 otherwise.\n"
    "\n"
    "Options:\n";

void PrintOptions() {
  for (const OptionSpec& spec : ArmSimOptions::Describe().Specs(ArmSimOptions())) {
    const std::string value = FormatOptionValue(spec.default_value) + " " + spec.unit;
    std::printf("  %-31s %-10s %s\n", spec.key.c_str(), value.c_str(), spec.description.c_str());
  }
}

StatusOr<ArmSimOptions> ParseOptions(const CliArgs& args) {
  OptionSet set;
  SIGHTLINE_RETURN_IF_ERROR(set.Declare(ArmSimOptions::Describe()));
  for (const std::string& assignment : args.Values("--set")) {
    SIGHTLINE_RETURN_IF_ERROR(set.ApplyOverride(assignment));
  }
  ArmSimOptions options = set.Extract(ArmSimOptions::Describe());
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  return options;
}

void PrintOutcome(const ArmSimSessionResult& result, const ArmSimulator& arm) {
  const ArmSimOutcome& o = result.outcome;
  std::printf("end: %s after %lld poses\n", result.end_reason.c_str(),
              static_cast<long long>(result.poses_sent));
  std::printf("end effector (base frame): [%.4f, %.4f, %.4f] m\n", o.position.x(), o.position.y(),
              o.position.z());
  const ArmSimButton* b = arm.world().FindButton(o.nearest_button);
  std::printf("nearest true button: %d (label %s), distance to its centre %.2f mm\n",
              o.nearest_button, b ? b->label.c_str() : "?", o.distance_mm);
  std::printf("  across the panel %.2f mm, along the push %+.2f mm (+ = beyond the face)\n",
              o.lateral_mm, o.depth_mm);
  std::printf("tool axis to the panel normal: %.2f deg\n", o.approach_error_deg);
  for (const auto& [key, count] : arm.counts()) {
    std::printf("%s: %lld\n", key.c_str(), static_cast<long long>(count));
  }
  for (const auto& [reason, count] : arm.malformed()) {
    std::printf("malformed x%lld: %s\n", static_cast<long long>(count), reason.c_str());
  }
}

}  // namespace

int ArmSimCommand(const std::vector<std::string>& argv) {
  auto parsed = CliArgs::Parse(argv, {"--token", "--seed", "--log", "--set"}, {"--help"});
  if (!parsed.ok()) return Fail("arm-sim: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    PrintOptions();
    return 0;
  }
  if (parsed->positionals().size() != 1) return Fail("arm-sim: expected HOST:PORT (see --help)");
  std::string host;
  int port = 0;
  const Status address = ArmClient::ParseAddress(parsed->positionals()[0], &host, &port);
  if (!address.ok()) return Fail("arm-sim: " + address.message());
  int seed = 4;
  if (auto v = parsed->Value("--seed")) {
    char* end = nullptr;
    seed = static_cast<int>(std::strtol(v->c_str(), &end, 10));
    if (v->empty() || *end != '\0' || seed < 0) return Fail("arm-sim: --seed must be >= 0");
  }
  StatusOr<ArmSimOptions> options = ParseOptions(*parsed);
  if (!options.ok()) return Fail("arm-sim: " + options.status().message());
  StatusOr<ArmSimWorld> world = BuildArmSimWorld(seed, *options);
  if (!world.ok()) return Fail("arm-sim: " + world.status().message());
  std::ofstream log;
  if (auto path = parsed->Value("--log")) {
    log.open(*path);
    if (!log) return Fail("arm-sim: cannot write --log " + *path);
  }
  ArmSimulator arm(*options, std::move(*world));
  double first = NAN;
  arm.set_event_sink([&](const ArmSimEvent& e) {
    if (std::isnan(first)) first = e.time_s;
    char line[512];
    std::snprintf(line, sizeof(line), "%.6f +%8.3f s  %s\n", e.time_s, e.time_s - first,
                  e.what.c_str());
    std::fputs(line, stdout);
    std::fflush(stdout);
    if (log) log << line << std::flush;
  });
  StatusOr<ArmSimSessionResult> result =
      RunArmSimSession(host, port, parsed->Value("--token").value_or(""), &arm);
  if (!result.ok()) return Fail("arm-sim: " + result.status().message());
  PrintOutcome(*result, arm);
  const bool stopped_and_closed = result->end_reason == "closed" && arm.stopped();
  return result->end_reason == "finished" || stopped_and_closed ? 0 : 1;
}

}  // namespace sightline::cli
