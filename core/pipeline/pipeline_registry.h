// The pipelines `sightline-cli run NAME` and the GUI know, and the one way to run them headless.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/status.h"
#include "core/common/timing.h"
#include "core/options/option_set.h"
#include "core/pipeline/metrics.h"
#include "core/pipeline/pipeline.h"

namespace sightline {

// Called after each frame with frames done and the total (-1 if unknown).
using ProgressCallback = std::function<void(int64_t done, int64_t total)>;
// Called on the loop's thread with each processed frame's result (`index`: its stream index)
// before the next frame is read: a front end that publishes results (sightline-node) hooks into
// the one headless loop here. It may block (e.g. to pace a recording at its recorded rate).
using ResultCallback =
    std::function<void(const std::shared_ptr<const PipelineResult>& result, int64_t index)>;

// Opens a run's source in place of OpenSource/OpenDataset, for a source a front end opens
// itself (sightline-node's live ros:// topics, which need its ROS node).
using SourceOpener = std::function<StatusOr<std::unique_ptr<Source>>(const std::string& path)>;

// What a headless pipeline run gets.
struct RunContext {
  std::string dataset_path;
  std::string out_dir;            // Exists when the run starts.
  OptionSet options;              // Effective, validated options.
  TimingStats* timing = nullptr;  // Stages add their durations here, and "total" per frame.
  ProgressCallback progress;      // May be empty.
  const std::atomic<bool>* cancel = nullptr;  // Checked between frames; may be null.
  ResultCallback on_result;                   // May be empty.
  SourceOpener open_source;                   // May be empty: OpenSource/OpenDataset.

  bool Cancelled() const { return cancel != nullptr && cancel->load(); }
};

// One pipeline: its name, its options, the kinds of source it takes and its object. Every
// front end (CLI, GUI, node) takes pipelines from the registry and runs `create()`'s object.
struct PipelineInfo {
  std::string name;     // e.g. "mapping", "stereo-vo": the CLI's word and the profiles' name.
  std::string title;    // English title for menus, e.g. "Indoor mapping".
  std::string summary;  // One line for `--help`: what it does.
  // Kinds of source it runs on, the preferred first (a recording with several sensors opens
  // the first of these it has). Empty: any kind.
  std::vector<SourceKind> accepts;
  std::function<Status(OptionSet*)> declare_options;
  // The pipeline object, run by RunHeadless and by the GUI's worker.
  std::function<std::unique_ptr<Pipeline>()> create;
  // A headless run of its own, for a pipeline not yet an object (`create` is preferred).
  std::function<StatusOr<RunResult>(const RunContext&)> run;

  // Whether it runs on sources of this kind.
  bool Accepts(SourceKind kind) const;
};

// The one headless loop: opens context.dataset_path (a dataset or a sensor URI) as the kind the
// pipeline prefers, configures and opens the pipeline, feeds it every wanted frame, adds the
// per-frame "read" and "total" timing and every "ms" statistic to context.timing, and calls
// Finish(context.out_dir). Stops at the end of the source, at options' frame limits applied by
// the pipeline, on cancel, or on an error reading or processing a frame. A run that stops early
// after at least one frame calls the pipeline's Abort (live outputs are told at once), then
// still writes its files so far and returns them with RunResult::ended_early set to the cancel
// or the error; before any frame, the cancel or error itself is returned.
StatusOr<RunResult> RunHeadless(const PipelineInfo& info, const RunContext& context);

// A set of pipelines, built explicitly (no global registration).
class PipelineRegistry {
 public:
  Status Register(PipelineInfo info);
  const PipelineInfo* Find(const std::string& name) const;
  const std::vector<PipelineInfo>& pipelines() const { return pipelines_; }

 private:
  std::vector<PipelineInfo> pipelines_;
};

// Every pipeline Sightline has (builtin_pipelines.cpp, in sightline_pipeline).
PipelineRegistry BuiltinPipelines();

// The stereo-vo pipeline alone, as BuiltinPipelines() registers it (stereo_pipelines.cpp, in
// both libraries): what sightline_pipeline_stereo's programs run.
PipelineRegistry StereoPipelines();

// A request to run one pipeline headless.
struct RunRequest {
  std::string pipeline;
  std::string dataset_path;
  std::string out_dir;
  std::string profile_path;            // YAML profile, optional.
  std::vector<std::string> overrides;  // "key=value", applied after the profile.
  ProgressCallback progress;
  const std::atomic<bool>* cancel = nullptr;
  ResultCallback on_result;  // Each frame's result, as RunContext::on_result.
  SourceOpener open_source;  // As RunContext::open_source.
};

// Adds one processed frame's timing to `timing`: every statistic of unit "ms" under its stage
// name ("vo/rectify_ms" -> "rectify"), and `total_ms` (the caller's time around Process) under
// "total" unless the pipeline published its own "<module>/total_ms". CLI and GUI runs alike.
void AddFrameTiming(const StatisticTable& table, const PipelineResult& result, double total_ms,
                    TimingStats* timing);

// The metrics.json of a run: its figures, per-stage timing summaries ("total" last, or the
// wall time per frame when no stage timed "total"), wall time and frame rate, and options.
RunMetrics MakeRunMetrics(const std::string& pipeline, const std::string& dataset,
                          const RunResult& result, const TimingStats& timing, double wall_s,
                          const OptionSet& options);

// What a run wrote.
struct RunReport {
  RunResult result;
  RunMetrics metrics;
  std::string metrics_path;
};

// Writes the files of a run so far, as `sightline-cli run` writes them: creates out_dir, calls
// the pipeline's Finish and writes metrics.json. The GUI's File > Save results.
StatusOr<RunReport> SaveRun(Pipeline& pipeline, const std::string& name, const std::string& dataset,
                            const TimingStats& timing, double wall_s, const OptionSet& options,
                            const std::string& out_dir);

// Declares options, loads the profile, applies overrides, creates out_dir, runs the pipeline
// and writes out_dir/metrics.json.
StatusOr<RunReport> RunPipeline(const PipelineRegistry& registry, const RunRequest& request);

}  // namespace sightline
