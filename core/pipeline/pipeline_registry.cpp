#include "core/pipeline/pipeline_registry.h"

#include <filesystem>

#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/inspect_pipeline.h"
#include "core/pipeline/mapping_pipeline.h"
#include "core/pipeline/mobility_pipeline.h"
#include "core/pipeline/mono_slam_pipeline.h"
#include "core/pipeline/stereo_vo_pipeline.h"

namespace sightline {

Status PipelineRegistry::Register(PipelineInfo info) {
  if (info.name.empty() || !info.run) return InvalidArgument("a pipeline needs a name and a run");
  if (Find(info.name) != nullptr) {
    return InvalidArgument("pipeline '" + info.name + "' is registered twice");
  }
  pipelines_.push_back(std::move(info));
  return Status::Ok();
}

const PipelineInfo* PipelineRegistry::Find(const std::string& name) const {
  for (const PipelineInfo& p : pipelines_) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

PipelineRegistry BuiltinPipelines() {
  PipelineRegistry registry;
  Status s = registry.Register(InspectPipeline());
  s = registry.Register(MappingPipeline());
  s = registry.Register(StereoVoPipeline());
  s = registry.Register(MobilityPipeline());
  s = registry.Register(MonoSlamPipeline());
  s = registry.Register(ButtonPipeline());
  (void)s;  // Built-in names are distinct; a clash is a programming error caught by tests.
  return registry;
}

StatusOr<RunReport> RunPipeline(const PipelineRegistry& registry, const RunRequest& request) {
  const PipelineInfo* pipeline = registry.Find(request.pipeline);
  if (pipeline == nullptr) {
    std::string names;
    for (const auto& p : registry.pipelines()) names += (names.empty() ? "" : ", ") + p.name;
    return NotFound("unknown pipeline '" + request.pipeline + "' (known: " + names + ")");
  }
  RunContext context;
  context.dataset_path = request.dataset_path;
  context.out_dir = request.out_dir;
  if (pipeline->declare_options)
    SIGHTLINE_RETURN_IF_ERROR(pipeline->declare_options(&context.options));
  if (!request.profile_path.empty()) {
    SIGHTLINE_RETURN_IF_ERROR(context.options.LoadYaml(request.profile_path));
  }
  for (const std::string& assignment : request.overrides) {
    SIGHTLINE_RETURN_IF_ERROR(context.options.ApplyOverride(assignment));
  }
  std::error_code ec;
  std::filesystem::create_directories(request.out_dir, ec);
  if (ec || !std::filesystem::is_directory(request.out_dir)) {
    return NotFound("cannot create output folder " + request.out_dir +
                    (ec ? ": " + ec.message() : ""));
  }
  TimingStats timing;
  context.timing = &timing;
  context.progress = request.progress;
  context.cancel = request.cancel;

  RunReport report;
  const double start_s = HostTimeS();
  StatusOr<RunResult> result = pipeline->run(context);
  if (!result.ok()) return result.status();
  report.result = std::move(*result);
  const double wall_s = HostTimeS() - start_s;
  report.metrics.pipeline = pipeline->name;
  report.metrics.dataset = request.dataset_path;
  report.metrics.frames = report.result.frames;
  // Pipelines time "total" per frame; it is listed last.
  for (auto& [stage, summary] : SummarizeTiming(timing)) {
    if (stage != "total") report.metrics.timing_ms.emplace_back(stage, summary);
  }
  TimingSummary total = timing.Summary("total");
  if (total.count == 0) total = TimingStats::Summarize({wall_s * 1000.0});
  report.metrics.timing_ms.emplace_back("total", total);
  report.metrics.accuracy = report.result.accuracy;
  report.metrics.counts = report.result.counts;
  report.metrics.counts.emplace_back("wall_time_s", wall_s);
  if (wall_s > 0) {
    report.metrics.counts.emplace_back("frames_per_second", report.result.frames / wall_s);
  }
  report.metrics.options = context.options;
  // The arm server's token is a secret: metrics.json only says that one was set.
  if (StatusOr<OptionValue> token = report.metrics.options.Get("button.arm.token");
      token.ok() && !FormatOptionValue(*token).empty()) {
    (void)report.metrics.options.Set("button.arm.token", std::string("(set, not shown)"),
                                     "redacted");
  }
  report.metrics_path = (std::filesystem::path(request.out_dir) / "metrics.json").string();
  SIGHTLINE_RETURN_IF_ERROR(WriteMetricsJson(report.metrics, report.metrics_path));
  return report;
}

}  // namespace sightline
