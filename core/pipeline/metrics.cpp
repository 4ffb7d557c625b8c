#include "core/pipeline/metrics.h"

#include <cstdio>
#include <fstream>

#include "core/common/json_writer.h"

namespace sightline {

std::vector<std::pair<std::string, TimingSummary>> SummarizeTiming(const TimingStats& stats) {
  std::vector<std::pair<std::string, TimingSummary>> out;
  for (const std::string& stage : stats.Stages()) out.emplace_back(stage, stats.Summary(stage));
  return out;
}

std::string MetricsToJson(const RunMetrics& m) {
  JsonWriter w;
  w.BeginObject();
  w.Key("pipeline").String(m.pipeline);
  w.Key("dataset").String(m.dataset);
  w.Key("frames").Int(m.frames);
  w.Key("timing_ms").BeginObject();
  for (const auto& [stage, s] : m.timing_ms) {
    w.Key(stage).BeginObject();
    w.Key("median").Double(s.median_ms);
    w.Key("p95").Double(s.p95_ms);
    w.Key("mean").Double(s.mean_ms);
    w.Key("max").Double(s.max_ms);
    w.Key("count").Int(static_cast<long long>(s.count));
    w.EndObject();
  }
  w.EndObject();
  w.Key("accuracy").BeginObject();
  for (const auto& [key, value] : m.accuracy) w.Key(key).Double(value);
  w.EndObject();
  w.Key("counts").BeginObject();
  for (const auto& [key, value] : m.counts) w.Key(key).Double(value);
  w.EndObject();
  if (!m.failure.empty()) w.Key("failure").String(m.failure);
  w.Key("ended").String(m.ended);
  if (!m.end_reason.empty()) w.Key("end_reason").String(m.end_reason);
  if (!m.notes.empty()) {
    w.Key("notes").BeginArray();
    for (const std::string& note : m.notes) w.String(note);
    w.EndArray();
  }
  w.Key("options");
  m.options.WriteJson(&w);
  w.EndObject();
  return w.str() + "\n";
}

Status WriteMetricsJson(const RunMetrics& metrics, const std::string& path) {
  std::ofstream out(path);
  if (!out) return NotFound("cannot write " + path);
  out << MetricsToJson(metrics);
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

std::string FormatTimingTable(const std::vector<std::pair<std::string, TimingSummary>>& timing) {
  std::string text = "stage                      median ms     p95 ms   count\n";
  char line[160];
  for (const auto& [stage, s] : timing) {
    std::snprintf(line, sizeof(line), "%-24s %11.3f %10.3f %7zu\n", stage.c_str(), s.median_ms,
                  s.p95_ms, s.count);
    text += line;
  }
  return text;
}

}  // namespace sightline
