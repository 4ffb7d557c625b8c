#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <sstream>

#include "core/pipeline/pipeline_registry.h"
#include "core/sim/simulate.h"
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

// A short simulated RGB-D recording (terrain scene, `frames` frames) in its own folder.
std::string SimulatedRgbd(const std::string& name, int frames) {
  const std::string dir = testing::TempDir(name);
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("terrain");
  options.frames = frames;
  EXPECT_TRUE(sim::Simulate(options, dir).ok());
  return dir + "/rgbd";
}

int Lines(const std::string& path) {
  const std::string text = ReadAll(path);
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(RunPipeline, ACancelledRunStillWritesItsResultsSoFar) {
  const std::string dir = SimulatedRgbd("run_cancel_sim", 12);
  std::atomic<bool> cancel{false};
  RunRequest request;
  request.pipeline = "inspect";
  request.dataset_path = dir;
  request.out_dir = testing::TempDir("run_cancel") + "/out";
  request.cancel = &cancel;
  request.progress = [&cancel](int64_t done, int64_t) { cancel = done >= 4; };  // Ctrl-C.
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_EQ(report->result.ended_early.code(), StatusCode::kCancelled);
  EXPECT_EQ(report->metrics.frames, 4);
  EXPECT_EQ(Lines(request.out_dir + "/frames.csv"), 1 + 4);  // Header and the 4 frames done.
  const std::string json = ReadAll(report->metrics_path);
  EXPECT_NE(json.find("\"ended\": \"cancelled\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"end_reason\": \"cancelled: run cancelled after 4 frames\""),
            std::string::npos)
      << json;
}

TEST(RunPipeline, AnErrorMidRunWritesTheFramesBeforeItAndNamesTheFrame) {
  const std::string dir = SimulatedRgbd("run_error_sim", 10);
  std::ofstream(dir + "/depth/000006.png", std::ios::trunc) << "not a png";
  RunRequest request;
  request.pipeline = "inspect";
  request.dataset_path = dir;
  request.out_dir = testing::TempDir("run_error") + "/out";
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  const Status& stop = report->result.ended_early;
  EXPECT_FALSE(stop.ok());
  EXPECT_NE(stop.message().find("frame 6"), std::string::npos) << stop.ToString();
  EXPECT_NE(stop.message().find("depth/000006.png"), std::string::npos) << stop.ToString();
  EXPECT_EQ(report->metrics.frames, 6);
  EXPECT_EQ(Lines(request.out_dir + "/frames.csv"), 1 + 6);
  const std::string json = ReadAll(report->metrics_path);
  EXPECT_NE(json.find("\"ended\": \"error\""), std::string::npos) << json;
  EXPECT_NE(json.find("000006.png"), std::string::npos) << json;
}

TEST(RunPipeline, ARunThatRanThroughEndedComplete) {
  const std::string dir = SimulatedRgbd("run_complete_sim", 3);
  RunRequest request;
  request.pipeline = "inspect";
  request.dataset_path = dir;
  request.out_dir = testing::TempDir("run_complete") + "/out";
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_TRUE(report->result.ended_early.ok());
  EXPECT_EQ(report->metrics.frames, 3);
  EXPECT_NE(ReadAll(report->metrics_path).find("\"ended\": \"complete\""), std::string::npos);
}

TEST(RunPipeline, ACancelBeforeAnyFrameIsTheCancelItself) {
  const std::string dir = SimulatedRgbd("run_cancel0_sim", 3);
  std::atomic<bool> cancel{true};
  RunRequest request;
  request.pipeline = "inspect";
  request.dataset_path = dir;
  request.out_dir = testing::TempDir("run_cancel0") + "/out";
  request.cancel = &cancel;
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.status().code(), StatusCode::kCancelled);
}

}  // namespace
}  // namespace sightline
