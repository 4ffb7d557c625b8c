#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/pipeline/pipeline_registry.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using testing::ReadAll;

TEST(RunPipeline, InspectOnTumWritesMetricsInTheCommonShape) {
  SIGHTLINE_REQUIRE_DATA(dir, "tum_fr1_desk");
  RunRequest request;
  request.pipeline = "inspect";
  request.dataset_path = dir;
  request.out_dir = testing::TempDir("run") + "/out";
  request.overrides = {"inspect.max_depth_m=5"};
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_EQ(report->metrics.frames, 9);
  const std::string json = ReadAll(report->metrics_path);
  EXPECT_NE(json.find("\"pipeline\": \"inspect\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"frames\": 9"), std::string::npos);
  EXPECT_NE(json.find("\"read\": {"), std::string::npos);
  EXPECT_NE(json.find("\"total\": {"), std::string::npos);
  EXPECT_NE(json.find("\"median\""), std::string::npos);
  EXPECT_NE(json.find("\"p95\""), std::string::npos);
  EXPECT_NE(json.find("\"gt_coverage\": 1"), std::string::npos) << json;
  EXPECT_NE(json.find("\"inspect.max_depth_m\": 5"), std::string::npos) << json;
  // "total" is per frame: one sample per frame.
  const auto& timing = report->metrics.timing_ms;
  ASSERT_EQ(timing.back().first, "total");
  EXPECT_EQ(timing.back().second.count, 9u);
  // frames.csv has a header and one row per frame.
  const std::string csv = ReadAll(request.out_dir + "/frames.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 10);
}

TEST(RunPipeline, FrameTimingTakesStagesInMsAndThePipelinesOwnTotal) {
  const StatisticTable table = {{"vo/rectify_ms", "ms", "rectify"},
                                {"vo/total_ms", "ms", "whole frame"},
                                {"vo/tracked", "count", "not a time"}};
  PipelineResult own;
  own.stats = {{"vo/rectify_ms", 2.0}, {"vo/total_ms", 7.0}, {"vo/tracked", 300.0}};
  TimingStats timing;
  AddFrameTiming(table, own, 99.0, &timing);
  EXPECT_EQ(timing.Summary("rectify").count, 1u);
  EXPECT_DOUBLE_EQ(timing.Summary("rectify").median_ms, 2.0);
  // The pipeline's own total is the frame's total; the caller's 99 ms is not added beside it.
  EXPECT_EQ(timing.Summary("total").count, 1u);
  EXPECT_DOUBLE_EQ(timing.Summary("total").median_ms, 7.0);
  EXPECT_EQ(timing.Summary("tracked").count, 0u);

  // Without one, the caller's time around Process is the total.
  PipelineResult stages_only;
  stages_only.stats = {{"vo/rectify_ms", 3.0}};
  AddFrameTiming(table, stages_only, 11.0, &timing);
  EXPECT_EQ(timing.Summary("total").count, 2u);
  EXPECT_DOUBLE_EQ(timing.Summary("total").max_ms, 11.0);
}

TEST(RunPipeline, UnknownPipelineListsKnownOnes) {
  RunRequest request;
  request.pipeline = "mapingg";
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("inspect"), std::string::npos);
}

TEST(RunPipeline, BadOverrideAndBadProfileFailBeforeRunning) {
  RunRequest request;
  request.pipeline = "inspect";
  request.dataset_path = "/nonexistent";
  request.out_dir = testing::TempDir("run") + "/out";
  request.overrides = {"inspect.max_depth_m=-1"};
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("inspect.max_depth_m"), std::string::npos);

  const std::string profile = testing::TempDir("run") + "/p.yaml";
  std::ofstream(profile) << "inspect:\n  max_frame: 3\n";
  request.overrides.clear();
  request.profile_path = profile;
  report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find(profile + " line 2"), std::string::npos)
      << report.status().message();
}

TEST(RunPipeline, MissingDatasetNamesThePath) {
  RunRequest request;
  request.pipeline = "inspect";
  request.dataset_path = "/nonexistent/dataset";
  request.out_dir = testing::TempDir("run") + "/out";
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("/nonexistent/dataset"), std::string::npos);
}

}  // namespace
}  // namespace sightline
