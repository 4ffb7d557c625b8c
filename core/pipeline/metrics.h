// The one shape of metrics.json that every `sightline-cli run` writes.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/common/status.h"
#include "core/common/timing.h"
#include "core/options/option_set.h"

namespace sightline {

// What a run measured.
//
// {"pipeline": ..., "dataset": ..., "frames": N,
//  "timing_ms": {"<stage>": {"median": x, "p95": y, "mean": m, "max": M, "count": n}, ...,
//                "total": {...}},
//  "accuracy": {"ate_rmse_m": ..., ...},
//  "counts": {"<name>": n, ...},
//  "failure": "why the run achieved nothing" (only then),
//  "options": {"<key>": value, ...}}
struct RunMetrics {
  std::string pipeline;
  std::string dataset;
  int64_t frames = 0;
  std::vector<std::pair<std::string, TimingSummary>> timing_ms;  // In stage order; "total" last.
  std::vector<std::pair<std::string, double>> accuracy;
  std::vector<std::pair<std::string, double>> counts;
  OptionSet options;  // The effective options of the run.
  // Why the run achieved nothing (no frame tracked, never initialised, every frame gated);
  // empty for a run with results. Written as "failure" when set.
  std::string failure;
  // How the run ended: "complete" (its source ended or its frame limit), "cancelled" or
  // "error" (files written up to the frame it stopped at); `end_reason` says why when early.
  std::string ended = "complete";
  std::string end_reason;
  // Facts a reader should know (RunResult::notes, e.g. "no metric scale: no arm motion").
  // Written as "notes" when there are any.
  std::vector<std::string> notes;
};

// Summaries of every stage of `stats`, in the order the stages were first timed.
std::vector<std::pair<std::string, TimingSummary>> SummarizeTiming(const TimingStats& stats);

std::string MetricsToJson(const RunMetrics& metrics);
Status WriteMetricsJson(const RunMetrics& metrics, const std::string& path);
// A plain-text table of the timing, as the CLI prints it.
std::string FormatTimingTable(const std::vector<std::pair<std::string, TimingSummary>>& timing);

}  // namespace sightline
