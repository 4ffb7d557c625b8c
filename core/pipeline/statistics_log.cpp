#include "core/pipeline/statistics_log.h"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace sightline {

namespace {

std::optional<double> Find(const std::vector<std::pair<std::string, double>>& stats,
                           const std::string& key) {
  for (const auto& [name, value] : stats) {
    if (name == key) return value;
  }
  return std::nullopt;
}

// A value as the shortest text that reads back the same double (integers without a point).
std::string FormatValue(double value) {
  if (!std::isfinite(value)) return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
  char text[64];
  if (value == std::floor(value) && std::fabs(value) < 1e15) {
    std::snprintf(text, sizeof(text), "%.0f", value);
  } else {
    std::snprintf(text, sizeof(text), "%.6g", value);
  }
  return text;
}

}  // namespace

std::string StatisticColumn(const std::string& key) { return key.substr(key.find('/') + 1); }

void StatisticsLog::Add(const PipelineResult& result) {
  rows_.push_back({result.stamp, result.status.ok() ? "" : result.status.message(), result.stats});
}

double StatisticsLog::Sum(const std::string& key) const {
  double sum = 0;
  for (const Row& row : rows_) sum += Find(row.stats, key).value_or(0.0);
  return sum;
}

int64_t StatisticsLog::Count(const std::string& key) const {
  int64_t n = 0;
  for (const Row& row : rows_) n += Find(row.stats, key).has_value() ? 1 : 0;
  return n;
}

std::optional<double> StatisticsLog::Mean(const std::string& key) const {
  const int64_t n = Count(key);
  if (n == 0) return std::nullopt;
  return Sum(key) / static_cast<double>(n);
}

std::vector<double> StatisticsLog::Values(const std::string& key) const {
  std::vector<double> values;
  for (const Row& row : rows_) {
    if (std::optional<double> v = Find(row.stats, key)) values.push_back(*v);
  }
  return values;
}

Status StatisticsLog::WriteCsv(const std::string& path, const StatisticTable& table) const {
  std::ofstream csv(path);
  if (!csv) return NotFound("cannot write " + path);
  csv << "frame,time_s";
  for (const StatisticInfo& info : table) csv << ',' << StatisticColumn(info.key);
  csv << ",status\n";
  for (const Row& row : rows_) {
    char head[64];
    std::snprintf(head, sizeof(head), "%lld,%.6f", static_cast<long long>(row.stamp.sequence_id),
                  row.stamp.sensor_time_s);
    csv << head;
    for (const StatisticInfo& info : table) {
      csv << ',';
      if (std::optional<double> v = Find(row.stats, info.key)) csv << FormatValue(*v);
    }
    std::string status = row.status;
    for (char& c : status) {
      if (c == '"') c = '\'';
    }
    csv << ",\"" << status << "\"\n";
  }
  csv.flush();
  if (!csv) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

}  // namespace sightline
