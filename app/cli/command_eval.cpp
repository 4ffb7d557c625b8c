// sightline-cli eval: accuracy of an estimated trajectory against ground truth.
#include <cstdio>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "core/eval/error_report.h"
#include "core/eval/evaluation.h"
#include "core/eval/trajectory_file.h"
#include "core/eval/trajectory_plot.h"
#include "core/options/option_set.h"

namespace sightline::cli {

namespace {

const char kHelp[] =
    "usage: sightline-cli eval EST GT [--align se3|sim3|none] [--format auto|tum|kitti]\n"
    "                          [--associate time|index] [--max-dt S] [--set eval.KEY=VALUE]...\n"
    "                          [--json] [--plot DIR] [--plane auto|xz|xy]\n"
    "\n"
    "Compares the estimated trajectory EST with the ground truth GT and prints ATE (RMSE, mean,\n"
    "median, max), RPE (translation and rotation), KITTI segment errors, path-length error and\n"
    "end-point error. Files are TUM (t tx ty tz qx qy qz qw) or KITTI (12 numbers per line,\n"
    "10 Hz timestamps assumed); --format auto (default) decides per file.\n"
    "\n"
    "  --align      se3 (default), sim3 for monocular estimates (prints the scale applied to the\n"
    "               estimate: 0.5 when it is twice too large), none to compare as given\n"
    "  --associate  time (default, nearest timestamp within --max-dt, unmatched poses dropped)\n"
    "               or index (equal lengths required)\n"
    "  --max-dt S   association tolerance in seconds (default 0.02)\n"
    "  --set        any eval option, e.g. eval.rpe_delta_frames=10, eval.rpe_delta_m=1,\n"
    "               eval.segment_lengths_m=kitti, eval.segment_step_frames=10\n"
    "  --json       print the accuracy figures as the `accuracy` block of metrics.json\n"
    "  --plot DIR   write DIR/top_view.png and DIR/ate_over_time.png\n"
    "  --plane      top-view plane: xz for camera frames (KITTI), xy for z-up worlds, auto\n";

// The effective options: defaults, then --set, then the dedicated flags.
StatusOr<EvaluationOptions> OptionsFromArgs(const CliArgs& args) {
  OptionSet set;
  SIGHTLINE_RETURN_IF_ERROR(set.Declare(EvaluationOptions::Describe()));
  for (const std::string& assignment : args.Values("--set")) {
    SIGHTLINE_RETURN_IF_ERROR(set.ApplyOverride(assignment));
  }
  const std::pair<const char*, const char*> flags[] = {
      {"--align", "eval.align"},
      {"--associate", "eval.associate"},
      {"--max-dt", "eval.max_time_difference_s"},
  };
  for (const auto& [flag, key] : flags) {
    if (auto value = args.Value(flag)) {
      SIGHTLINE_RETURN_IF_ERROR(set.SetFromString(key, *value, flag));
    }
  }
  EvaluationOptions options = set.Extract(EvaluationOptions::Describe());
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  return options;
}

}  // namespace

int EvalCommand(const std::vector<std::string>& args) {
  StatusOr<CliArgs> parsed = CliArgs::Parse(
      args, {"--align", "--format", "--associate", "--max-dt", "--set", "--plot", "--plane"},
      {"--json", "--help"});
  if (!parsed.ok()) return Fail("eval: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (parsed->positionals().size() != 2) return Fail("eval: expected EST and GT (see --help)");
  const std::string& estimate_path = parsed->positionals()[0];
  const std::string& ground_truth_path = parsed->positionals()[1];

  StatusOr<EvaluationOptions> options = OptionsFromArgs(*parsed);
  if (!options.ok()) return Fail("eval: " + options.status().message());
  StatusOr<TrajectoryFormat> format =
      ParseTrajectoryFormat(parsed->Value("--format").value_or("auto"));
  if (!format.ok()) return Fail("eval: --format: " + format.status().message());
  StatusOr<PlotPlane> plane = ParsePlotPlane(parsed->Value("--plane").value_or("auto"));
  if (!plane.ok()) return Fail("eval: --plane: " + plane.status().message());

  StatusOr<Trajectory> estimate = ReadTrajectoryFile(estimate_path, *format);
  if (!estimate.ok()) return Fail("eval: " + estimate.status().ToString());
  StatusOr<Trajectory> ground_truth = ReadTrajectoryFile(ground_truth_path, *format);
  if (!ground_truth.ok()) return Fail("eval: " + ground_truth.status().ToString());

  StatusOr<TrajectoryErrors> errors = EvaluateTrajectory(*estimate, *ground_truth, *options);
  if (!errors.ok()) {
    return Fail("eval " + estimate_path + " against " + ground_truth_path + ": " +
                errors.status().ToString());
  }
  const bool json = parsed->Has("--json");
  if (json) {
    std::printf("%s\n", AccuracyToJson(AccuracyFigures(*errors)).c_str());
  } else {
    std::fputs(FormatErrorTable(*errors).c_str(), stdout);
  }
  if (const auto dir = parsed->Value("--plot")) {
    const Status written = WriteEvaluationPlots(*errors, *dir, *plane);
    if (!written.ok()) return Fail("eval: " + written.ToString());
    // Keep stdout pure JSON when --json is given.
    std::fprintf(json ? stderr : stdout, "wrote %s/top_view.png and %s/ate_over_time.png\n",
                 dir->c_str(), dir->c_str());
  }
  return 0;
}

}  // namespace sightline::cli
