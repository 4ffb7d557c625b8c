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

namespace sightline {

// Called after each frame with frames done and the total (-1 if unknown).
using ProgressCallback = std::function<void(int64_t done, int64_t total)>;

// What a headless pipeline run gets.
struct RunContext {
  std::string dataset_path;
  std::string out_dir;            // Exists when the run starts.
  OptionSet options;              // Effective, validated options.
  TimingStats* timing = nullptr;  // Stages add their durations here, and "total" per frame.
  ProgressCallback progress;      // May be empty.
  const std::atomic<bool>* cancel = nullptr;  // Checked between frames; may be null.

  bool Cancelled() const { return cancel != nullptr && cancel->load(); }
};

// What a headless pipeline run returns besides its own output files.
struct RunResult {
  std::string dataset_format;  // As the source reported it.
  int64_t frames = 0;
  std::vector<std::pair<std::string, double>> accuracy;  // Keys as documented per pipeline.
  std::vector<std::pair<std::string, double>> counts;
  std::vector<std::string> outputs;  // Files written, relative to out_dir.
};

// One pipeline: its name, its options and its headless run.
struct PipelineInfo {
  std::string name;     // e.g. "mapping", "stereo-vo".
  std::string summary;  // One line for `--help`.
  std::function<Status(OptionSet*)> declare_options;
  std::function<StatusOr<RunResult>(const RunContext&)> run;
};

// A set of pipelines, built explicitly (no global registration).
class PipelineRegistry {
 public:
  Status Register(PipelineInfo info);
  const PipelineInfo* Find(const std::string& name) const;
  const std::vector<PipelineInfo>& pipelines() const { return pipelines_; }

 private:
  std::vector<PipelineInfo> pipelines_;
};

// Every pipeline Sightline has.
PipelineRegistry BuiltinPipelines();

// A request to run one pipeline headless.
struct RunRequest {
  std::string pipeline;
  std::string dataset_path;
  std::string out_dir;
  std::string profile_path;            // YAML profile, optional.
  std::vector<std::string> overrides;  // "key=value", applied after the profile.
  ProgressCallback progress;
  const std::atomic<bool>* cancel = nullptr;
};

// What RunPipeline did.
struct RunReport {
  RunResult result;
  RunMetrics metrics;
  std::string metrics_path;
};

// Declares options, loads the profile, applies overrides, creates out_dir, runs the pipeline
// and writes out_dir/metrics.json.
StatusOr<RunReport> RunPipeline(const PipelineRegistry& registry, const RunRequest& request);

}  // namespace sightline
