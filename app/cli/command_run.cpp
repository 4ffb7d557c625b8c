#include <signal.h>

#include <atomic>
#include <csignal>
#include <cstdio>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "app/cli/program_pipelines.h"
#include "app/cli/progress.h"
#include "app/cli/run_outputs.h"
#include "app/cli/stereo_program.h"
#include "core/pipeline/pipeline_registry.h"

namespace sightline::cli {

namespace {

// Set by SIGINT/SIGTERM (lock-free, so async-signal-safe); the pipeline checks it between
// frames, and the button pipeline then sends its arm clients a stop line before it returns.
std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);
void OnInterrupt(int) { g_interrupted.store(true); }

// SA_RESETHAND: a second Ctrl-C ends a run that does not stop by itself.
void InstallInterruptHandlers() {
  struct sigaction action {};
  action.sa_handler = OnInterrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

int RunCommand(const std::vector<std::string>& args) {
  const PipelineRegistry registry = ProgramPipelines();
  std::string help =
      "usage: sightline-cli run PIPELINE PATH --out DIR [--profile F] [--set key=value]...\n"
      "\n"
      "Runs PIPELINE on the dataset at PATH without a GUI and writes its outputs and\n"
      "DIR/metrics.json (frames, per-stage timing median/p95 in ms, accuracy when the dataset\n"
      "has ground truth, and the effective options). --profile loads a YAML options profile;\n"
      "--set overrides one option (see 'sightline-cli options PIPELINE'). Ctrl-C or SIGTERM\n"
      "stops the run (with --serve the arm clients get a stop line first) and writes its\n"
      "results up to then, as does an error at a frame; metrics.json says how it \"ended\".\n"
      "stereo-vo: --subsample K (= --set stereo.subsample=K) processes every K-th frame;\n"
      "--format kitti (= --set stereo.output_format=kitti) writes trajectory.txt as KITTI poses.\n"
      "button: --tap X,Y[@FRAME] (= --set button.run.tap=X,Y@FRAME) is the operator's tap,\n"
      "confirmed at once; --serve HOST:PORT publishes the targets (arm-target protocol; a HOST\n"
      "other than 127.x.x.x needs --set button.arm.token=...).\n"
      "PATH sim://panel?seed=N&fps=F is a live simulated camera in the hand of an arm (run\n"
      "'sightline-cli arm-sim' against --serve); there --tap button:K taps true button K.\n"
      "\nExit codes: 0 results written; 1 an error (the line on stderr says which file,\n"
      "field or option); 3 the run completed but achieved nothing (no frame tracked, never\n"
      "initialised, every frame gated): its first line says why and metrics.json has\n"
      "\"failure\"; 130 cancelled by Ctrl-C or SIGTERM, results up to then written.\n"
      "\nPipelines:\n";
  for (const PipelineInfo& p : registry.pipelines())
    help += "  " + p.name + "  " + p.summary + "\n";

  StatusOr<CliArgs> parsed = CliArgs::Parse(args, RunValueFlags(), RunSwitches());
  if (!parsed.ok()) return Fail("run: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(help.c_str(), stdout);
    // `run PIPELINE --help`: that pipeline's options too, as `options PIPELINE` lists them.
    if (!parsed->positionals().empty() && registry.Find(parsed->positionals()[0]) != nullptr) {
      const std::string& name = parsed->positionals()[0];
      std::printf("\nFiles %s writes into --out DIR:\n%s", name.c_str(),
                  RunOutputsHelp(name).c_str());
      std::printf("\nOptions of %s (key, type, default, range, unit, meaning):\n", name.c_str());
      std::fflush(stdout);
      return OptionsCommand({parsed->positionals()[0]});
    }
    return 0;
  }
  if (parsed->positionals().size() != 2)
    return Fail("run: expected PIPELINE and PATH (see --help)");
  if (!parsed->Value("--out")) return Fail("run: --out DIR is required");

  RunRequest request;
  request.pipeline = parsed->positionals()[0];
  request.dataset_path = parsed->positionals()[1];
  request.out_dir = *parsed->Value("--out");
  request.profile_path = parsed->Value("--profile").value_or("");
  request.overrides = parsed->Values("--set");
  // Aliases of stereo-vo options.
  if (auto k = parsed->Value("--subsample")) request.overrides.push_back("stereo.subsample=" + *k);
  if (auto f = parsed->Value("--format")) request.overrides.push_back("stereo.output_format=" + *f);
  // Aliases of button options.
  if (auto t = parsed->Value("--tap")) request.overrides.push_back("button.run.tap=" + *t);
  if (auto a = parsed->Value("--serve")) {
    const size_t colon = a->rfind(':');
    if (colon == std::string::npos || colon == 0)
      return Fail("run: --serve expects HOST:PORT, got '" + *a + "'");
    request.overrides.push_back("button.run.serve=true");
    request.overrides.push_back("button.arm.bind_address=" + a->substr(0, colon));
    request.overrides.push_back("button.arm.port=" + a->substr(colon + 1));
  }
  ProgressLine progress(request.pipeline);
  request.progress = [&progress](int64_t done, int64_t total) { progress.Update(done, total); };
  request.cancel = &g_interrupted;
  request.open_source = ProgramSourceOpener(request.dataset_path, &g_interrupted);
  InstallInterruptHandlers();

  StatusOr<RunReport> report = RunPipeline(registry, request);
  progress.Finish();
  if (!report.ok()) {
    Fail("run " + request.pipeline + ": " + report.status().ToString());
    return report.status().code() == StatusCode::kCancelled ? kExitCancelled : kExitError;
  }

  const RunMetrics& m = report->metrics;
  const Status& stop = report->result.ended_early;
  if (!stop.ok()) {
    // Stopped early (a cancel, or an error at a frame): the files so far are written.
    std::fprintf(stderr, "sightline-cli: run %s %s: %s; the results up to then are in %s\n",
                 request.pipeline.c_str(), m.ended.c_str(), stop.message().c_str(),
                 request.out_dir.c_str());
  } else if (!report->result.nothing_achieved.empty()) {
    std::fprintf(stderr, "sightline-cli: run %s achieved nothing: %s (files in %s)\n",
                 request.pipeline.c_str(), report->result.nothing_achieved.c_str(),
                 request.out_dir.c_str());
  }
  if (!parsed->Has("--quiet")) {
    std::printf("%s on %s (%s): %lld frames\n", m.pipeline.c_str(), m.dataset.c_str(),
                report->result.dataset_format.c_str(), static_cast<long long>(m.frames));
    std::fputs(FormatTimingTable(m.timing_ms).c_str(), stdout);
    for (const auto& [key, value] : m.accuracy)
      std::printf("accuracy.%s = %.6g\n", key.c_str(), value);
    for (const std::string& note : report->result.notes) std::printf("note: %s\n", note.c_str());
    PrintWrittenFiles(request.out_dir, report->result.outputs);  // Every file, one line each.
  }
  if (!stop.ok()) return stop.code() == StatusCode::kCancelled ? kExitCancelled : kExitError;
  return report->result.nothing_achieved.empty() ? 0 : kExitNothingAchieved;
}

}  // namespace sightline::cli
