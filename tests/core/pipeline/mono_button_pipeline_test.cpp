// The mono-slam and button pipelines as objects run headless through RunPipeline on the
// simulated panel approach (camera in the arm's hand, 12 cm sideways first): their files and
// figures, the operator's commands, and the button run in data time (a slow host gives the same
// targets).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "core/io/dataset.h"
#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/mono_slam_pipeline.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sim/simulate.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::map<std::string, double> Figures(const RunReport& report) {
  std::map<std::string, double> m;
  for (const auto& [key, value] : report.result.accuracy) m[key] = value;
  for (const auto& [key, value] : report.result.counts) m["counts." + key] = value;
  return m;
}

class MonoButtonPipelines : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(testing::TempDir("mono_button_pipelines"));
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
    options.arm.sideways_m = 0.12;
    ASSERT_TRUE(sim::Simulate(options, *dir_).ok());
  }
  static void TearDownTestSuite() { delete dir_; }

  // "button.run.tap=U,V@0" a few pixels off the true centre of the approached button (id 5).
  static std::string TapOnTarget() {
    StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(*dir_ + "/buttons.csv");
    EXPECT_TRUE(buttons.ok()) << buttons.status().ToString();
    for (const TrueButton& b : *buttons) {
      if (b.id != 5) continue;
      char tap[96];
      std::snprintf(tap, sizeof(tap), "button.run.tap=%.1f,%.1f@0", b.pixel[0].x() + 2,
                    b.pixel[0].y() - 2);
      return tap;
    }
    ADD_FAILURE() << "button 5 not in buttons.csv";
    return "button.run.tap=0,0";
  }

  static StatusOr<RunReport> Run(const PipelineRegistry& registry, const std::string& pipeline,
                                 const std::string& out, std::vector<std::string> overrides) {
    RunRequest request;
    request.pipeline = pipeline;
    request.dataset_path = *dir_;
    request.out_dir = out;
    request.overrides = std::move(overrides);
    return RunPipeline(registry, request);
  }

  static std::string* dir_;
};
std::string* MonoButtonPipelines::dir_ = nullptr;

TEST_F(MonoButtonPipelines, MonoSlamHeadlessWritesItsFilesWithTheFiguresOfRunMonoSlam) {
  const std::string out = testing::TempDir("mono_pipeline_run");
  StatusOr<RunReport> report = Run(BuiltinPipelines(), "mono-slam", out, {});
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  std::map<std::string, double> m = Figures(*report);
  for (const auto& [key, value] : m) std::printf("  %s = %g\n", key.c_str(), value);
  EXPECT_EQ(m["lost_frames"], 0);
  ASSERT_TRUE(m.count("ate_rmse_m"));
  EXPECT_LT(m["ate_rmse_m"], 0.01);
  ASSERT_TRUE(m.count("scale_error_pct_ml"));
  EXPECT_LT(m["scale_error_pct_ml"], 1.0);
  EXPECT_EQ(m["counts.metric_scale_from_arm"], 1);
  for (const char* file : {"trajectory.txt", "trajectory_map.txt", "map.ply", "keyframes.txt",
                           "scale.csv", "frames.csv", "metrics.json"}) {
    EXPECT_FALSE(ReadAll(out + "/" + file).empty()) << file;
  }
  const std::string json = ReadAll(report->metrics_path);
  for (const char* stage : {"\"features\"", "\"tracking\"", "\"mapping\"", "\"bundle_adjustment\""})
    EXPECT_NE(json.find(stage), std::string::npos) << stage;
  // The library call runs the same object: the same figures.
  StatusOr<MonoSlamRun> run = RunMonoSlam(*dir_, {}, {});
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  std::vector<std::string> notes;
  for (const auto& [key, value] : MonoSlamAccuracy(*run, 0.02, &notes)) {
    EXPECT_NEAR(m[key], value, 1e-9 * (1 + std::abs(value))) << key;
  }
}

TEST_F(MonoButtonPipelines, ButtonHeadlessLocatesTheTappedButtonWithinThreeMillimetres) {
  const std::string out = testing::TempDir("button_pipeline_run");
  StatusOr<RunReport> report = Run(BuiltinPipelines(), "button", out, {TapOnTarget()});
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  std::map<std::string, double> m = Figures(*report);
  for (const auto& [key, value] : m) std::printf("  %s = %g\n", key.c_str(), value);
  ASSERT_TRUE(m.count("final_error_mm"));
  EXPECT_LT(m["final_error_mm"], 3.0);
  EXPECT_GT(m["targets_sent"], 0);
  EXPECT_EQ(m["counts.true_button"], 5);
  EXPECT_LT(m["track_error_px_max"], 3.0);
  const std::string json = ReadAll(report->metrics_path);
  for (const char* stage : {"\"slam\"", "\"tracking\"", "\"total\""})
    EXPECT_NE(json.find(stage), std::string::npos) << stage;
  const std::string csv = ReadAll(out + "/button.csv");
  EXPECT_EQ(csv.rfind("frame,time_s,state,gate,", 0), 0u);
  EXPECT_NE(csv.find(",target_sent,send,"), std::string::npos);
}

// button.csv without its two host-time columns (tracking_ms, slam_ms).
std::string WithoutTimings(const std::string& csv) {
  std::stringstream in(csv);
  std::string line, out;
  while (std::getline(in, line)) {
    for (int i = 0; i < 2; ++i) line = line.substr(0, line.rfind(','));
    out += line + "\n";
  }
  return out;
}

TEST_F(MonoButtonPipelines, ButtonRunsInDataTimeSoASlowHostGivesTheSameTargets) {
  // A tight age limit: under a host clock every estimate would be stale on the slow host.
  const std::vector<std::string> overrides = {TapOnTarget(), "button.gate.max_age_ms=20"};
  PipelineRegistry slow;
  PipelineInfo info = ButtonPipelineInfo();
  info.create = [] {
    auto pipeline = std::make_unique<ButtonPipeline>();
    pipeline->SetHostDelayForTest(0.05);  // 50 ms of host time inside every frame.
    return std::unique_ptr<Pipeline>(std::move(pipeline));
  };
  ASSERT_TRUE(slow.Register(info).ok());
  const std::string fast_out = testing::TempDir("button_data_time_fast");
  const std::string slow_out = testing::TempDir("button_data_time_slow");
  StatusOr<RunReport> fast = Run(BuiltinPipelines(), "button", fast_out, overrides);
  ASSERT_TRUE(fast.ok()) << fast.status().ToString();
  StatusOr<RunReport> slowed = Run(slow, "button", slow_out, overrides);
  ASSERT_TRUE(slowed.ok()) << slowed.status().ToString();
  std::map<std::string, double> a = Figures(*fast), b = Figures(*slowed);
  EXPECT_GT(a["targets_sent"], 0);
  EXPECT_EQ(a["targets_sent"], b["targets_sent"]);
  EXPECT_EQ(a["final_error_mm"], b["final_error_mm"]);
  EXPECT_EQ(a["counts.tap_to_first_target_frames"], b["counts.tap_to_first_target_frames"]);
  const std::string csv_fast = WithoutTimings(ReadAll(fast_out + "/button.csv"));
  const std::string csv_slow = WithoutTimings(ReadAll(slow_out + "/button.csv"));
  EXPECT_GT(std::count(csv_fast.begin(), csv_fast.end(), '\n'), 50);
  EXPECT_EQ(csv_fast, csv_slow);
  EXPECT_EQ(csv_fast.find(",stale,"), std::string::npos);
}

TEST_F(MonoButtonPipelines, OperatorCommandsTapConfirmAndStopReachTheButtonObject) {
  auto commands = std::make_shared<ButtonCommands>();
  ButtonPipeline pipeline(commands);
  OptionSet options;
  ASSERT_TRUE(ButtonPipelineInfo().declare_options(&options).ok());
  ASSERT_TRUE(pipeline.Configure(options).ok());  // No tap needed: an operator is there.
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(*dir_, SourceKind::kMono);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  ASSERT_TRUE(pipeline.Open(PipelineSource::From(**source)).ok());
  StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(*dir_ + "/buttons.csv");
  ASSERT_TRUE(buttons.ok());
  const TrueButton* target = nullptr;
  for (const TrueButton& b : *buttons) target = b.id == 5 ? &b : target;
  ASSERT_NE(target, nullptr);
  const int64_t stop_at = (*source)->info().frame_count - 10;
  ASSERT_GT(stop_at, 50);
  int sent = 0, sent_after_stop = 0;
  PickerState last = PickerState::kIdle;
  for (int64_t i = 0; (*source)->Grab().ok(); ++i) {
    StatusOr<Frame> frame = (*source)->Retrieve();
    ASSERT_TRUE(frame.ok());
    if (i == 0) commands->Tap({target->pixel[0].x(), target->pixel[0].y()});
    if (i == 1) commands->Confirm();
    if (i == stop_at) commands->Stop();
    StatusOr<std::shared_ptr<const PipelineResult>> r = pipeline.Process(*frame);
    ASSERT_TRUE(r.ok()) << r.status().ToString();
    const auto* button = dynamic_cast<const ButtonFrameResult*>(r->get());
    ASSERT_NE(button, nullptr);
    if (i == 0) {
      EXPECT_TRUE(button->tap_answered && button->tap_status.ok());
      EXPECT_EQ(button->picker.state, PickerState::kConfirm);
    }
    sent += button->picker.target ? 1 : 0;
    if (i >= stop_at) sent_after_stop += button->picker.target ? 1 : 0;
    last = button->picker.state;
  }
  EXPECT_GT(sent, 0);
  EXPECT_EQ(sent_after_stop, 0);
  EXPECT_EQ(last, PickerState::kStopped);
}

}  // namespace
}  // namespace sightline
