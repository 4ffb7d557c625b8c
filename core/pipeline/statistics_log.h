// Every frame's named statistics of a run, kept for frames.csv and the run's summaries.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/status.h"
#include "core/pipeline/pipeline.h"

namespace sightline {

// Collects the statistics of each processed frame in order and writes them as frames.csv,
// one column per statistic of the pipeline's table (named by the key without its module:
// "vo/inliers" -> "inliers"), after `frame` (sequence id) and `time_s` (sensor time), with
// the frame's status last. Values a frame did not publish are left empty.
//
//   StatisticsLog log;
//   log.Add(*result);                                   // After each Process.
//   log.WriteCsv(out_dir + "/frames.csv", Statistics());
//   double gated = log.Sum("vo/gated");
class StatisticsLog {
 public:
  void Add(const PipelineResult& result);
  void Clear() { rows_.clear(); }
  size_t size() const { return rows_.size(); }

  // The sum, mean or count of the frames that published statistic `key`.
  double Sum(const std::string& key) const;
  std::optional<double> Mean(const std::string& key) const;
  int64_t Count(const std::string& key) const;
  // Every frame's value of `key` (frames without it are skipped).
  std::vector<double> Values(const std::string& key) const;

  // Writes the CSV; an error names the file.
  Status WriteCsv(const std::string& path, const StatisticTable& table) const;

 private:
  struct Row {
    FrameStamp stamp;
    std::string status;  // Empty when the frame was fine.
    std::vector<std::pair<std::string, double>> stats;
  };
  std::vector<Row> rows_;
};

// The CSV column of a statistic: its key without the module ("vo/inliers" -> "inliers").
std::string StatisticColumn(const std::string& key);

}  // namespace sightline
