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

// Serving switched on and off during a run, with a real arm client on loopback: the run goes on
// (the SLAM map keeps growing from where it was), serving off sends the client a stop line, a
// latched STOP survives new options and a new server (no target until Restart), a hold (the
// picture paused) publishes nothing, and an old tap is refused.
TEST_F(MonoButtonPipelines, ServingIsARuntimeSwitchAndStopStaysLatched) {
  auto commands = std::make_shared<ButtonCommands>();
  ButtonPipeline pipeline(commands);
  OptionSet options;
  ASSERT_TRUE(ButtonPipelineInfo().declare_options(&options).ok());
  int port = 0;
  {  // A free loopback port.
    ArmServerOptions probe_options;
    probe_options.port = 0;
    auto probe = ArmServer::Start(probe_options);
    ASSERT_TRUE(probe.ok());
    port = (*probe)->port();
  }
  ASSERT_TRUE(options.ApplyOverride("button.arm.port=" + std::to_string(port)).ok());
  ASSERT_TRUE(pipeline.Configure(options).ok());
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(*dir_, SourceKind::kMono);
  ASSERT_TRUE(source.ok());
  ASSERT_TRUE(pipeline.Open(PipelineSource::From(**source)).ok());
  StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(*dir_ + "/buttons.csv");
  ASSERT_TRUE(buttons.ok());
  const TrueButton* target = nullptr;
  for (const TrueButton& b : *buttons) target = b.id == 5 ? &b : target;
  ASSERT_NE(target, nullptr);

  std::vector<std::shared_ptr<const ButtonFrameResult>> results;
  auto next = [&]() -> const ButtonFrameResult* {
    if (!(*source)->Grab().ok()) return nullptr;
    StatusOr<Frame> frame = (*source)->Retrieve();
    if (!frame.ok()) return nullptr;
    StatusOr<std::shared_ptr<const PipelineResult>> r = pipeline.Process(*frame);
    if (!r.ok()) return nullptr;
    results.push_back(std::dynamic_pointer_cast<const ButtonFrameResult>(*r));
    return results.back().get();
  };
  auto set_serve = [&](bool on) {
    EXPECT_TRUE(
        options.ApplyOverride(std::string("button.gui.serve=") + (on ? "true" : "false")).ok());
    const Status configured = pipeline.Configure(options);
    EXPECT_TRUE(configured.ok()) << configured.ToString();
  };
  auto map_points = [&] { return results.back()->Stat("mono/map_points").value_or(-1); };

  for (int i = 0; i < 40; ++i) ASSERT_NE(next(), nullptr);
  const double points_before = map_points();
  ASSERT_GT(points_before, 0);
  set_serve(true);
  StatusOr<ArmClient> client = ArmClient::Connect("127.0.0.1", port, "", 5000);
  ASSERT_TRUE(client.ok()) << client.status().ToString();
  ASSERT_NE(next(), nullptr);
  EXPECT_TRUE(results.back()->serving);
  // A new run would start with an empty map and an untracked frame.
  EXPECT_GT(map_points(), 0.5 * points_before) << "serving on started the run again";
  EXPECT_EQ(results.back()->Stat("mono/tracked").value_or(0), 1);

  // The tap on the frame shown, Yes, and frames until a target goes out.
  const ButtonFrameResult* shown = results.back().get();
  const int64_t shown_index = static_cast<int64_t>(results.size()) - 1;
  ButtonTapRequest tap;
  tap.x = target->pixel.at(shown_index).x();
  tap.y = target->pixel.at(shown_index).y();
  tap.frame = shown->stamp.sequence_id;
  tap.stamp_s = shown->stamp.sensor_time_s;
  commands->Tap(tap);
  const ButtonFrameResult* tapped = next();
  ASSERT_NE(tapped, nullptr);
  ASSERT_TRUE(tapped->tap_status.ok()) << tapped->tap_status.ToString();
  commands->Confirm();
  bool published = false;
  for (int i = 0; i < 60 && !published; ++i) {
    const ButtonFrameResult* r = next();
    ASSERT_NE(r, nullptr);
    published = r->target_published;
  }
  ASSERT_TRUE(published);

  // Held (the picture paused): nothing is published, the gate's target is not counted as sent.
  commands->SetHold(true);
  for (int i = 0; i < 3; ++i) {
    const ButtonFrameResult* r = next();
    ASSERT_NE(r, nullptr);
    EXPECT_TRUE(r->held);
    EXPECT_FALSE(r->target_published);
    EXPECT_FALSE(r->picker.target.has_value());
  }
  commands->SetHold(false);

  // A tap on a frame older than button.gui.max_tap_age_s (0.5 s, 15 frames) is refused.
  for (int i = 0; i < 16; ++i) ASSERT_NE(next(), nullptr);
  ASSERT_GT(results.back()->stamp.sensor_time_s - tap.stamp_s, 0.5);
  ButtonTapRequest old = tap;
  commands->Tap(old);
  const ButtonFrameResult* refused = next();
  ASSERT_NE(refused, nullptr);
  EXPECT_EQ(refused->tap_refused, TapRefusal::kTooOld);

  // STOP, then serving off and on: the client hears "stop" (STOP, then serving off), the new
  // server stays stopped and nothing is published until Restart.
  commands->Stop("operator");
  set_serve(false);
  bool stop_seen = false, closed = false;
  for (int i = 0; i < 2000 && !closed; ++i) {
    StatusOr<std::string> line = client->ReadLine(5000);
    if (!line.ok()) {
      closed = line.status().code() == StatusCode::kUnavailable;
      if (!closed) break;
      continue;
    }
    if (stop_seen) EXPECT_EQ(line->find("\"type\":\"target\""), std::string::npos) << *line;
    if (line->find("\"type\":\"stop\"") != std::string::npos) stop_seen = true;
  }
  EXPECT_TRUE(stop_seen);
  EXPECT_TRUE(closed);
  const double points_at_stop = map_points();
  set_serve(true);
  for (int i = 0; i < 5; ++i) {
    const ButtonFrameResult* r = next();
    ASSERT_NE(r, nullptr);
    EXPECT_TRUE(r->stopped);
    EXPECT_TRUE(r->serving);
    EXPECT_FALSE(r->target_published);
    EXPECT_EQ(r->picker.state, PickerState::kStopped);
  }
  EXPECT_GT(map_points(), 0.5 * points_at_stop);
  EXPECT_EQ(results.back()->Stat("mono/tracked").value_or(0), 1);
  commands->Restart();
  EXPECT_FALSE(commands->stopped());
}

}  // namespace
}  // namespace sightline
