#include "core/common/timing.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sightline {

void TimingStats::Add(const std::string& stage, double milliseconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto [it, inserted] = samples_.try_emplace(stage);
  if (inserted) order_.push_back(stage);
  it->second.push_back(milliseconds);
}

TimingSummary TimingStats::Summary(const std::string& stage) const {
  std::vector<double> copy;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = samples_.find(stage);
    if (it == samples_.end()) return {};
    copy = it->second;
  }
  return Summarize(std::move(copy));
}

std::vector<std::string> TimingStats::Stages() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return order_;
}

void TimingStats::Clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  order_.clear();
  samples_.clear();
}

TimingSummary TimingStats::Summarize(std::vector<double> samples) {
  TimingSummary s;
  s.count = samples.size();
  if (samples.empty()) return s;
  std::sort(samples.begin(), samples.end());
  const size_t n = samples.size();
  s.median_ms = n % 2 == 1 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
  // Nearest-rank percentile.
  const size_t rank = static_cast<size_t>(std::ceil(0.95 * static_cast<double>(n)));
  s.p95_ms = samples[std::clamp<size_t>(rank, 1, n) - 1];
  s.mean_ms = std::accumulate(samples.begin(), samples.end(), 0.0) / static_cast<double>(n);
  s.max_ms = samples.back();
  return s;
}

double HostTimeS() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace sightline
