#include "core/common/timing.h"

#include <gtest/gtest.h>

namespace sightline {
namespace {

TEST(TimingStats, MedianAndP95ByNearestRank) {
  std::vector<double> samples;
  for (int i = 1; i <= 100; ++i) samples.push_back(i);
  const TimingSummary s = TimingStats::Summarize(samples);
  EXPECT_EQ(s.count, 100u);
  EXPECT_DOUBLE_EQ(s.median_ms, 50.5);
  EXPECT_DOUBLE_EQ(s.p95_ms, 95);
  EXPECT_DOUBLE_EQ(s.max_ms, 100);
  EXPECT_DOUBLE_EQ(s.mean_ms, 50.5);
}

TEST(TimingStats, KeepsStageOrder) {
  TimingStats stats;
  stats.Add("scan", 1);
  stats.Add("lines", 3);
  stats.Add("scan", 2);
  EXPECT_EQ(stats.Stages(), (std::vector<std::string>{"scan", "lines"}));
  EXPECT_DOUBLE_EQ(stats.Summary("scan").median_ms, 1.5);
  EXPECT_EQ(stats.Summary("unknown").count, 0u);
}

}  // namespace
}  // namespace sightline
