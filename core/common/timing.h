// Per-stage timing statistics (median, p95) under named keys, e.g. "occupancy", "total".
#pragma once

#include <chrono>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace sightline {

// Summary of one stage's samples in milliseconds.
struct TimingSummary {
  size_t count = 0;
  double median_ms = 0;
  double p95_ms = 0;
  double mean_ms = 0;
  double max_ms = 0;
};

// Collects durations per named stage. Thread-safe; stages keep their insertion order.
//
//   TimingStats stats;
//   { ScopedTimer t(&stats, "lines"); ExtractLines(...); }
//   TimingSummary s = stats.Summary("lines");
class TimingStats {
 public:
  void Add(const std::string& stage, double milliseconds);
  TimingSummary Summary(const std::string& stage) const;
  // Stage names in the order they were first added.
  std::vector<std::string> Stages() const;
  void Clear();

  // Median and 95th percentile (nearest rank) of a sample set; 0 when empty.
  static TimingSummary Summarize(std::vector<double> samples_ms);

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> order_;
  std::map<std::string, std::vector<double>> samples_;
};

// Adds the time between construction and destruction to a TimingStats stage.
class ScopedTimer {
 public:
  ScopedTimer(TimingStats* stats, std::string stage)
      : stats_(stats), stage_(std::move(stage)), start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() { stats_->Add(stage_, ElapsedMs()); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

  double ElapsedMs() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
        .count();
  }

 private:
  TimingStats* stats_;
  std::string stage_;
  std::chrono::steady_clock::time_point start_;
};

// Seconds on the host's steady clock, for FrameStamp::host_time_s.
double HostTimeS();

}  // namespace sightline
