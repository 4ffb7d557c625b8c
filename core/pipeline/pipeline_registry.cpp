#include "core/pipeline/pipeline_registry.h"

#include <filesystem>
#include <optional>

#include "core/io/dataset.h"
#include "core/pipeline/run_sources.h"

namespace sightline {

bool PipelineInfo::Accepts(SourceKind kind) const {
  if (accepts.empty()) return true;
  for (SourceKind k : accepts) {
    if (k == kind) return true;
  }
  return false;
}

namespace {

// The timing stage of an "ms" statistic: "vo/rectify_ms" -> "rectify".
std::string TimingStage(const std::string& key) {
  std::string stage = key.substr(key.find('/') + 1);
  if (stage.size() > 3 && stage.compare(stage.size() - 3, 3, "_ms") == 0) {
    stage.resize(stage.size() - 3);
  }
  return stage;
}

// Opens `path` as the first kind `info` accepts that the recording has.
StatusOr<std::unique_ptr<Source>> OpenForPipeline(const PipelineInfo& info, const std::string& path,
                                                  const OptionSet& options) {
  if (IsRunSourceLive(path)) return OpenLiveRunSource(path, options);
  if (info.accepts.empty()) return OpenAnyRunSource(path, options);
  std::optional<Status> first_error;
  for (SourceKind kind : info.accepts) {
    StatusOr<std::unique_ptr<Source>> opened = OpenDataset(path, kind);
    if (opened.ok()) return opened;
    if (!first_error) first_error = opened.status();
  }
  return *first_error;
}

}  // namespace

namespace {

// How feeding a source ended: the frames processed and, when it stopped early, why.
struct FeedOutcome {
  int64_t processed = 0;
  Status stop;  // Ok: the source ended (or the frame limit); else the cancel or the error.
};

// Feeds every wanted frame of `source` to `pipeline` until the source ends, a cancel or an error.
FeedOutcome FeedFrames(Pipeline& pipeline, Source& source, const RunContext& context) {
  const StatisticTable& table = pipeline.Statistics();
  int64_t total = source.info().frame_count;
  const int64_t limit = pipeline.FrameLimit();
  if (limit > 0 && (total < 0 || total > limit)) total = limit;
  FeedOutcome out;
  for (int64_t index = 0; total < 0 || index < total; ++index) {
    if (context.Cancelled()) {
      out.stop = Cancelled("run cancelled after " + std::to_string(index) + " frames");
      return out;
    }
    const double read_start = HostTimeS();
    const Status grabbed = source.Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) break;
    if (!grabbed.ok()) {
      out.stop = grabbed.WithContext("frame " + std::to_string(index));
      return out;
    }
    if (!pipeline.Wants(index)) continue;  // Grabbed but not decoded.
    StatusOr<Frame> frame = source.Retrieve();
    if (!frame.ok()) {
      out.stop = frame.status().WithContext("frame " + std::to_string(index));
      return out;
    }
    const double process_start = HostTimeS();
    StatusOr<std::shared_ptr<const PipelineResult>> result = pipeline.Process(*frame);
    const double end = HostTimeS();
    if (!result.ok()) {
      out.stop = result.status();
      return out;
    }
    ++out.processed;
    if (context.timing != nullptr) {
      context.timing->Add("read", (process_start - read_start) * 1000.0);
      AddFrameTiming(table, **result, (end - process_start) * 1000.0, context.timing);
    }
    if (context.on_result) context.on_result(*result, index);
    if (context.progress) context.progress(index + 1, total);
  }
  if (out.processed == 0) out.stop = OutOfRange(context.dataset_path + " gave no frame to process");
  return out;
}

// The reason live outputs are given when a run ends early.
std::string AbortReason(const Status& status) {
  return status.code() == StatusCode::kCancelled ? "cancelled" : "error";
}

}  // namespace

StatusOr<RunResult> RunHeadless(const PipelineInfo& info, const RunContext& context) {
  if (!info.create) return Internal("pipeline '" + info.name + "' has no object to run");
  StatusOr<std::unique_ptr<Source>> opened =
      context.open_source ? context.open_source(context.dataset_path)
                          : OpenForPipeline(info, context.dataset_path, context.options);
  if (!opened.ok()) return opened.status();
  Source& source = **opened;
  if (!info.Accepts(source.info().kind)) {
    return InvalidArgument(context.dataset_path + " is a " + SourceKindName(source.info().kind) +
                           " source; " + info.name + " does not run on it");
  }
  std::unique_ptr<Pipeline> pipeline = info.create();
  SIGHTLINE_RETURN_IF_ERROR(pipeline->Configure(context.options));
  SIGHTLINE_RETURN_IF_ERROR(pipeline->Open(PipelineSource::From(source)));
  const FeedOutcome fed = FeedFrames(*pipeline, source, context);
  // A run that stops early tells its live outputs at once (an arm gets its stop line before
  // any file is written), then writes what it has: a live run has no other end.
  if (!fed.stop.ok()) pipeline->Abort(AbortReason(fed.stop));
  if (fed.processed == 0) return fed.stop;
  StatusOr<RunResult> result = pipeline->Finish(context.out_dir);
  if (!result.ok()) {
    if (!fed.stop.ok()) return fed.stop;
    pipeline->Abort(AbortReason(result.status()));
    return result.status();
  }
  if (result->dataset_format.empty()) result->dataset_format = source.info().format;
  result->ended_early = fed.stop;
  return result;
}

void AddFrameTiming(const StatisticTable& table, const PipelineResult& result, double total_ms,
                    TimingStats* timing) {
  bool own_total = false;
  for (const auto& [key, value] : result.stats) {
    const StatisticInfo* stat = FindStatistic(table, key);
    if (stat == nullptr || stat->unit != "ms") continue;
    const std::string stage = TimingStage(key);
    own_total = own_total || stage == "total";
    timing->Add(stage, value);
  }
  // A pipeline that times its whole frame itself ("vo/total_ms") is believed; otherwise the
  // caller's time around Process is the frame's total.
  if (!own_total) timing->Add("total", total_ms);
}

RunMetrics MakeRunMetrics(const std::string& pipeline, const std::string& dataset,
                          const RunResult& result, const TimingStats& timing, double wall_s,
                          const OptionSet& options) {
  RunMetrics metrics;
  metrics.pipeline = pipeline;
  metrics.dataset = dataset;
  metrics.frames = result.frames;
  // Pipelines time "total" per frame; it is listed last.
  for (auto& [stage, summary] : SummarizeTiming(timing)) {
    if (stage != "total") metrics.timing_ms.emplace_back(stage, summary);
  }
  TimingSummary total = timing.Summary("total");
  if (total.count == 0) total = TimingStats::Summarize({wall_s * 1000.0});
  metrics.timing_ms.emplace_back("total", total);
  metrics.accuracy = result.accuracy;
  metrics.counts = result.counts;
  metrics.counts.emplace_back("wall_time_s", wall_s);
  if (wall_s > 0) metrics.counts.emplace_back("frames_per_second", result.frames / wall_s);
  metrics.options = options;
  // The arm server's token is a secret: metrics.json only says that one was set.
  if (StatusOr<OptionValue> token = metrics.options.Get("button.arm.token");
      token.ok() && !FormatOptionValue(*token).empty()) {
    (void)metrics.options.Set("button.arm.token", std::string("(set, not shown)"), "redacted");
  }
  metrics.failure = result.nothing_achieved;
  if (!result.ended_early.ok()) {
    metrics.ended = result.ended_early.code() == StatusCode::kCancelled ? "cancelled" : "error";
    metrics.end_reason = result.ended_early.ToString();
  }
  metrics.notes = result.notes;
  return metrics;
}

namespace {

Status CreateOutputFolder(const std::string& out_dir) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir)) {
    return NotFound("cannot create output folder " + out_dir + (ec ? ": " + ec.message() : ""));
  }
  return Status::Ok();
}

}  // namespace

StatusOr<RunReport> SaveRun(Pipeline& pipeline, const std::string& name, const std::string& dataset,
                            const TimingStats& timing, double wall_s, const OptionSet& options,
                            const std::string& out_dir) {
  SIGHTLINE_RETURN_IF_ERROR(CreateOutputFolder(out_dir));
  RunReport report;
  StatusOr<RunResult> result = pipeline.Finish(out_dir);
  if (!result.ok()) return result.status();
  report.result = std::move(*result);
  report.metrics = MakeRunMetrics(name, dataset, report.result, timing, wall_s, options);
  report.metrics_path = (std::filesystem::path(out_dir) / "metrics.json").string();
  SIGHTLINE_RETURN_IF_ERROR(WriteMetricsJson(report.metrics, report.metrics_path));
  report.result.outputs.push_back("metrics.json");
  return report;
}

Status PipelineRegistry::Register(PipelineInfo info) {
  if (info.name.empty() || (!info.run && !info.create)) {
    return InvalidArgument("a pipeline needs a name and an object or a run");
  }
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
  // A file a driver reads (a .bag) takes that driver's options too (io.rosbag.*).
  SIGHTLINE_RETURN_IF_ERROR(DeclareRunSourceOptions(request.dataset_path, &context.options));
  if (!request.profile_path.empty()) {
    SIGHTLINE_RETURN_IF_ERROR(context.options.LoadYaml(request.profile_path));
  }
  for (const std::string& assignment : request.overrides) {
    SIGHTLINE_RETURN_IF_ERROR(context.options.ApplyOverride(assignment));
  }
  SIGHTLINE_RETURN_IF_ERROR(CreateOutputFolder(request.out_dir));
  SIGHTLINE_RETURN_IF_ERROR(
      PrepareRunSource(request.dataset_path, request.out_dir, &context.options));
  TimingStats timing;
  context.timing = &timing;
  context.progress = request.progress;
  context.cancel = request.cancel;
  context.on_result = request.on_result;
  context.open_source = request.open_source;

  RunReport report;
  const double start_s = HostTimeS();
  StatusOr<RunResult> result =
      pipeline->create ? RunHeadless(*pipeline, context) : pipeline->run(context);
  if (!result.ok()) return result.status();
  report.result = std::move(*result);
  const double wall_s = HostTimeS() - start_s;
  report.metrics = MakeRunMetrics(pipeline->name, request.dataset_path, report.result, timing,
                                  wall_s, context.options);
  report.metrics_path = (std::filesystem::path(request.out_dir) / "metrics.json").string();
  SIGHTLINE_RETURN_IF_ERROR(WriteMetricsJson(report.metrics, report.metrics_path));
  return report;
}

}  // namespace sightline
