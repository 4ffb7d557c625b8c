// The mono-slam and button pipelines as objects run headless through RunPipeline on the
// simulated panel approach (camera in the arm's hand, 12 cm sideways first): their files and
// figures, the operator's commands, and the button run in data time (a slow host gives the same
// targets).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "core/button/arm_client.h"
#include "core/io/dataset.h"
#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/mono_slam_pipeline.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sim/simulate.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using testing::ReadAll;

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

// The operator's tap is for the frame on screen: the tap below names frame 0 (already
// processed) and is taken with frame 1; a tap naming no processed frame, or one older than
// button.gui.max_tap_age_s, is refused and never applied later.
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
  FrameStamp first;
  for (int64_t i = 0; (*source)->Grab().ok(); ++i) {
    StatusOr<Frame> frame = (*source)->Retrieve();
    ASSERT_TRUE(frame.ok());
    if (i == 0) {
      first = StampOf(*frame);
      ButtonTapRequest unseen;  // No frame shown yet.
      unseen.x = target->pixel[0].x();
      unseen.y = target->pixel[0].y();
      commands->Tap(unseen);
    }
    if (i == 1) {
      ButtonTapRequest tap;
      tap.x = target->pixel[0].x();
      tap.y = target->pixel[0].y();
      tap.frame = first.sequence_id;
      tap.stamp_s = first.sensor_time_s;
      commands->Tap(tap);
    }
    if (i == 2) commands->Confirm();
    if (i == stop_at) commands->Stop();
    StatusOr<std::shared_ptr<const PipelineResult>> r = pipeline.Process(*frame);
    ASSERT_TRUE(r.ok()) << r.status().ToString();
    const auto* button = dynamic_cast<const ButtonFrameResult*>(r->get());
    ASSERT_NE(button, nullptr);
    if (i == 0) {
      EXPECT_TRUE(button->tap_answered);
      EXPECT_EQ(button->tap_refused, TapRefusal::kNoPicture);
      EXPECT_EQ(button->picker.state, PickerState::kIdle);
    }
    if (i == 1) {
      EXPECT_TRUE(button->tap_answered && button->tap_status.ok()) << button->tap_status.ToString();
      EXPECT_EQ(button->tap_refused, TapRefusal::kNone);
      EXPECT_EQ(button->picker.state, PickerState::kConfirm);
    }
    if (i > 1) EXPECT_FALSE(button->tap_answered) << "frame " << i;  // Nothing kept for later.
    sent += button->picker.target ? 1 : 0;
    if (i >= stop_at) sent_after_stop += button->picker.target ? 1 : 0;
    EXPECT_EQ(button->stopped, i >= stop_at);
    last = button->picker.state;
  }
  EXPECT_GT(sent, 0);
  EXPECT_EQ(sent_after_stop, 0);
  EXPECT_EQ(last, PickerState::kStopped);
}

// A button pipeline with an operator (ButtonCommands) on the simulated approach, frame by frame,
// serving on a free loopback port when button.gui.serve is set.
class OperatorRun {
 public:
  Status Start(const std::string& dir) {
    {  // A free loopback port.
      ArmServerOptions probe_options;
      probe_options.port = 0;
      StatusOr<std::unique_ptr<ArmServer>> probe = ArmServer::Start(probe_options);
      if (!probe.ok()) return probe.status();
      port_ = (*probe)->port();
    }
    SIGHTLINE_RETURN_IF_ERROR(ButtonPipelineInfo().declare_options(&options_));
    SIGHTLINE_RETURN_IF_ERROR(options_.ApplyOverride("button.arm.port=" + std::to_string(port_)));
    SIGHTLINE_RETURN_IF_ERROR(pipeline_.Configure(options_));
    StatusOr<std::unique_ptr<Source>> source = OpenDataset(dir, SourceKind::kMono);
    if (!source.ok()) return source.status();
    source_ = std::move(*source);
    SIGHTLINE_RETURN_IF_ERROR(pipeline_.Open(PipelineSource::From(*source_)));
    StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(dir + "/buttons.csv");
    if (!buttons.ok()) return buttons.status();
    for (const TrueButton& b : *buttons) target_ = b.id == 5 ? b : target_;
    return target_.id == 5 ? Status::Ok() : NotFound("button 5");
  }

  // Processes the next frame (null at the end or on an error).
  const ButtonFrameResult* Next() {
    if (!source_->Grab().ok()) return nullptr;
    StatusOr<Frame> frame = source_->Retrieve();
    if (!frame.ok()) return nullptr;
    StatusOr<std::shared_ptr<const PipelineResult>> r = pipeline_.Process(*frame);
    if (!r.ok()) return nullptr;
    results_.push_back(std::dynamic_pointer_cast<const ButtonFrameResult>(*r));
    return results_.back().get();
  }
  Status SetServe(bool on) {
    SIGHTLINE_RETURN_IF_ERROR(
        options_.ApplyOverride(std::string("button.gui.serve=") + (on ? "true" : "false")));
    return pipeline_.Configure(options_);
  }
  // The operator's tap on the approached button of the last frame processed (the one shown).
  ButtonTapRequest TapOnLast() const {
    const ButtonFrameResult& shown = *results_.back();
    const size_t index = results_.size() - 1;
    ButtonTapRequest tap;
    tap.x = target_.pixel.at(index).x();
    tap.y = target_.pixel.at(index).y();
    tap.frame = shown.stamp.sequence_id;
    tap.stamp_s = shown.stamp.sensor_time_s;
    return tap;
  }
  double MapPoints() const { return results_.back()->Stat("mono/map_points").value_or(-1); }
  bool Tracked() const { return results_.back()->Stat("mono/tracked").value_or(0) == 1; }

  ButtonCommands& commands() { return *commands_; }
  const ButtonFrameResult& last() const { return *results_.back(); }
  int port() const { return port_; }

 private:
  std::shared_ptr<ButtonCommands> commands_ = std::make_shared<ButtonCommands>();
  ButtonPipeline pipeline_{commands_};
  OptionSet options_;
  std::unique_ptr<Source> source_;
  TrueButton target_;
  int port_ = 0;
  std::vector<std::shared_ptr<const ButtonFrameResult>> results_;
};

// Reads lines until the server closes the connection; whether a stop came, and no target after
// it.
bool StopThenClosed(ArmClient* client) {
  bool stop_seen = false;
  for (int i = 0; i < 5000; ++i) {
    StatusOr<std::string> line = client->ReadLine(5000);
    if (!line.ok()) return stop_seen && line.status().code() == StatusCode::kUnavailable;
    if (stop_seen && line->find("\"type\":\"target\"") != std::string::npos) return false;
    if (line->find("\"type\":\"stop\"") != std::string::npos) stop_seen = true;
  }
  return false;
}

// Serving switched on and off during a run, with a real arm client on loopback: the run goes on
// (the SLAM map is kept: a new run would start with an empty map and an untracked frame),
// serving off sends the client a stop line, a latched STOP survives new options and a new server
// (no target until Restart), a hold (the picture paused) publishes nothing, and an old tap is
// refused.
TEST_F(MonoButtonPipelines, ServingIsARuntimeSwitchAndStopStaysLatched) {
  OperatorRun run;
  const Status started = run.Start(*dir_);
  ASSERT_TRUE(started.ok()) << started.ToString();
  for (int i = 0; i < 40; ++i) ASSERT_NE(run.Next(), nullptr);
  const double points_before = run.MapPoints();
  ASSERT_GT(points_before, 0);
  ASSERT_TRUE(run.SetServe(true).ok());
  StatusOr<ArmClient> client = ArmClient::Connect("127.0.0.1", run.port(), "", 5000);
  ASSERT_TRUE(client.ok()) << client.status().ToString();
  ASSERT_NE(run.Next(), nullptr);
  EXPECT_TRUE(run.last().serving);
  EXPECT_GT(run.MapPoints(), 0.5 * points_before) << "serving on started the run again";
  EXPECT_TRUE(run.Tracked());

  // The tap on the frame shown, Yes, and frames until a target goes out.
  const ButtonTapRequest tap = run.TapOnLast();
  run.commands().Tap(tap);
  ASSERT_NE(run.Next(), nullptr);
  ASSERT_TRUE(run.last().tap_status.ok()) << run.last().tap_status.ToString();
  run.commands().Confirm();
  for (int i = 0; i < 60 && !run.last().target_published; ++i) ASSERT_NE(run.Next(), nullptr);
  ASSERT_TRUE(run.last().target_published);

  // Held (the picture paused): nothing is published, the gate's target is not counted as sent.
  run.commands().SetHold(true);
  for (int i = 0; i < 3; ++i) {
    ASSERT_NE(run.Next(), nullptr);
    EXPECT_TRUE(run.last().held);
    EXPECT_FALSE(run.last().target_published);
    EXPECT_FALSE(run.last().picker.target.has_value());
  }
  run.commands().SetHold(false);

  // A tap on a frame older than button.gui.max_tap_age_s (0.5 s, 15 frames) is refused.
  for (int i = 0; i < 16; ++i) ASSERT_NE(run.Next(), nullptr);
  ASSERT_GT(run.last().stamp.sensor_time_s - tap.stamp_s, 0.5);
  run.commands().Tap(tap);
  ASSERT_NE(run.Next(), nullptr);
  EXPECT_EQ(run.last().tap_refused, TapRefusal::kTooOld);

  // STOP, then serving off and on: the client hears "stop" and is closed; the new server stays
  // stopped and nothing is published until Restart.
  run.commands().Stop("operator");
  ASSERT_TRUE(run.SetServe(false).ok());
  EXPECT_TRUE(StopThenClosed(&*client));
  const double points_at_stop = run.MapPoints();
  ASSERT_TRUE(run.SetServe(true).ok());
  for (int i = 0; i < 5; ++i) {
    ASSERT_NE(run.Next(), nullptr);
    EXPECT_TRUE(run.last().stopped);
    EXPECT_TRUE(run.last().serving);
    EXPECT_FALSE(run.last().target_published);
    EXPECT_EQ(run.last().picker.state, PickerState::kStopped);
  }
  EXPECT_GT(run.MapPoints(), 0.5 * points_at_stop);
  EXPECT_TRUE(run.Tracked());
  run.commands().Restart();
  EXPECT_FALSE(run.commands().stopped());
}

}  // namespace
}  // namespace sightline
