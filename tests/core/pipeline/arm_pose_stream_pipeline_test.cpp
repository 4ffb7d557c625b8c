// The button pipeline with the arm's pose streamed live (mono.run.metric_source = arm_stream, or
// auto while serving without arm_poses.txt): on the simulated panel approach, a client thread
// plays the recording's arm_poses.txt over TCP as arm_pose lines to the pipeline's arm-target
// server, and the copy of the recording the pipeline reads has no arm_poses.txt. The metric
// scale and the final target error must match the run that reads the recorded poses; without
// the stream the run says why no target was sent. Also the feed's bounded wait for a frame's
// pose.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <thread>
#include <variant>

#include "core/button/arm_client.h"
#include "core/common/pose_board.h"
#include "core/common/trajectory.h"
#include "core/io/dataset.h"
#include "core/pipeline/arm_pose_feed.h"
#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sim/simulate.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

namespace fs = std::filesystem;

std::map<std::string, double> Figures(const RunReport& report) {
  std::map<std::string, double> m;
  for (const auto& [key, value] : report.result.accuracy) m[key] = value;
  for (const auto& [key, value] : report.result.counts) m["counts." + key] = value;
  return m;
}

int FreePort() {
  ArmServerOptions probe;
  probe.port = 0;
  StatusOr<std::unique_ptr<ArmServer>> server = ArmServer::Start(probe);
  EXPECT_TRUE(server.ok()) << server.status().ToString();
  return server.ok() ? (*server)->port() : 0;
}

// The arm: connects as soon as the pipeline serves, streams `poses` as arm_pose lines, then
// reads until the server closes the connection.
class ArmThread {
 public:
  ArmThread(int port, const Trajectory& poses) {
    thread_ = std::thread([this, port, poses] {
      std::optional<ArmClient> arm;
      for (int k = 0; k < 6000 && !arm; ++k) {  // Up to 60 s for the server to start.
        StatusOr<ArmClient> c = ArmClient::Connect("127.0.0.1", port, "", 500);
        if (c.ok()) {
          arm.emplace(std::move(*c));
        } else {
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
      }
      if (!arm) return;
      std::string lines;
      for (const TimedPose& p : poses.poses()) {
        ArmPoseMessage m;
        m.stamp_s = p.time_s;
        m.base_from_end_effector = p.world_from_sensor;
        lines += ArmPoseLine(m) + "\n";
      }
      if (!arm->Send(lines).ok()) return;
      sent_ = int64_t(poses.size());
      for (int k = 0; k < 100000; ++k) {
        StatusOr<std::string> line = arm->ReadLine(120000);
        if (!line.ok()) break;
        if (line->find("\"type\":\"stop\"") != std::string::npos) stop_seen_ = true;
        if (line->find("\"type\":\"target\"") != std::string::npos) ++targets_;
      }
    });
  }
  ~ArmThread() { Join(); }
  void Join() {
    if (thread_.joinable()) thread_.join();
  }
  int64_t sent() const { return sent_; }
  int targets() const { return targets_; }
  bool stop_seen() const { return stop_seen_; }

 private:
  std::atomic<int64_t> sent_{0};
  std::atomic<int> targets_{0};
  std::atomic<bool> stop_seen_{false};
  std::thread thread_;
};

ArmPoseMessage PoseAt(double t, double x) {
  ArmPoseMessage m;
  m.stamp_s = t;
  m.base_from_end_effector.translation() = Eigen::Vector3d(x, 0, 0);
  return m;
}

// A frame newer than the newest pose waits for the pose that covers it (here it comes 50 ms
// later, well within wait_s), and gets the pose interpolated at its stamp; a pose that never
// comes leaves the frame without one once wait_s is over.
TEST(ArmPoseFeed, AFrameWaitsForThePoseCoveringItsStamp) {
  ArmPoseStreamOptions o;
  o.wait_s = 30;
  o.clock_offset_s = 100;
  ArmPoseFeed feed(o);
  PoseBoard::Global().Clear("arm");
  feed.Add(PoseAt(100.99, 0.0));
  std::thread arm([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    feed.Add(PoseAt(101.01, 0.2));
  });
  bool waited = false;
  const std::optional<Eigen::Isometry3d> pose = feed.At(1.0, &waited);  // Camera clock.
  arm.join();
  EXPECT_TRUE(waited);
  ASSERT_TRUE(pose.has_value());
  EXPECT_NEAR(pose->translation().x(), 0.1, 1e-9);
  EXPECT_EQ(feed.received(), 2);
  ASSERT_TRUE(PoseBoard::Global().Latest("arm").has_value());
  EXPECT_DOUBLE_EQ(PoseBoard::Global().Latest("arm")->stamp_s, 101.01);  // The arm's clock.
  // Covered already: no wait.
  EXPECT_TRUE(feed.At(1.005, &waited).has_value());
  EXPECT_FALSE(waited);
  ArmPoseStreamOptions short_wait = o;
  short_wait.wait_s = 0.01;
  ArmPoseFeed silent(short_wait);
  silent.Add(PoseAt(100.99, 0.0));
  EXPECT_FALSE(silent.At(1.0, &waited).has_value());
  EXPECT_TRUE(waited);
  // No pose received at all: no arm streams, nothing to wait for (wait_s = 30 would show).
  ArmPoseFeed no_arm(o);
  EXPECT_FALSE(no_arm.At(1.0, &waited).has_value());
  EXPECT_FALSE(waited);
}

class ArmPoseStreamPipeline : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    recorded_ = new std::string(testing::TempDir("arm_stream_recorded"));
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
    options.arm.sideways_m = 0.12;
    ASSERT_TRUE(sim::Simulate(options, *recorded_).ok());
    // The same recording without arm_poses.txt: the poses can only come from the stream.
    streamed_ = new std::string(testing::TempDir("arm_stream_streamed"));
    fs::remove_all(*streamed_);
    fs::copy(*recorded_, *streamed_, fs::copy_options::recursive);
    ASSERT_TRUE(fs::remove(fs::path(*streamed_) / "arm_poses.txt"));
  }
  static void TearDownTestSuite() {
    delete recorded_;
    delete streamed_;
  }

  // "button.run.tap=U,V@0" a few pixels off the true centre of the approached button (id 5).
  static std::string TapOnTarget() {
    StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(*recorded_ + "/buttons.csv");
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

  static StatusOr<RunReport> Run(const std::string& dir, const std::string& out,
                                 std::vector<std::string> overrides) {
    RunRequest request;
    request.pipeline = "button";
    request.dataset_path = dir;
    request.out_dir = out;
    request.overrides = std::move(overrides);
    return RunPipeline(BuiltinPipelines(), request);
  }

  static std::string* recorded_;
  static std::string* streamed_;
};
std::string* ArmPoseStreamPipeline::recorded_ = nullptr;
std::string* ArmPoseStreamPipeline::streamed_ = nullptr;

TEST_F(ArmPoseStreamPipeline, TheStreamedPosesGiveTheRecordedRunsScaleAndTarget) {
  StatusOr<RunReport> recorded =
      Run(*recorded_, testing::TempDir("arm_stream_out_file"), {TapOnTarget()});
  ASSERT_TRUE(recorded.ok()) << recorded.status().ToString();
  std::map<std::string, double> a = Figures(*recorded);
  ASSERT_TRUE(a.count("scale_ml") && a.count("final_error_mm"));
  EXPECT_EQ(a["counts.metric_from_arm_stream"], 0);

  StatusOr<Trajectory> poses = ReadTumTrajectory(*recorded_ + "/arm_poses.txt");
  ASSERT_TRUE(poses.ok()) << poses.status().ToString();
  ASSERT_GT(poses->size(), 50u);
  PoseBoard::Global().Clear("arm");
  const int port = FreePort();
  ArmThread arm(port, *poses);
  // keep_s: the arm thread sends the whole recording at once, far ahead of the frames.
  StatusOr<RunReport> streamed =
      Run(*streamed_, testing::TempDir("arm_stream_out_stream"),
          {TapOnTarget(), "button.run.serve=true", "button.arm.port=" + std::to_string(port),
           "button.run.wait_clients=1", "button.arm_pose.wait_s=30", "button.arm_pose.keep_s=600"});
  arm.Join();
  ASSERT_TRUE(streamed.ok()) << streamed.status().ToString();
  std::map<std::string, double> b = Figures(*streamed);
  for (const auto& [key, value] : b)
    std::printf("  %s = %g (file: %g)\n", key.c_str(), value, a[key]);
  EXPECT_EQ(b["counts.metric_from_arm_stream"], 1);
  EXPECT_EQ(arm.sent(), int64_t(poses->size()));
  EXPECT_EQ(b["counts.arm_poses_received"], double(poses->size()));
  EXPECT_EQ(b["counts.arm_poses_refused"], 0);
  EXPECT_EQ(b["counts.frames_without_arm_pose"], 0);
  EXPECT_EQ(b["counts.frames_with_arm_pose"], double(streamed->result.frames));
  ASSERT_TRUE(b.count("scale_ml") && b.count("final_error_mm"));
  EXPECT_NEAR(b["scale_ml"], a["scale_ml"], 0.01 * a["scale_ml"]);
  EXPECT_NEAR(b["final_error_mm"], a["final_error_mm"], 1.0);
  EXPECT_LT(b["final_error_mm"], 3.0);
  EXPECT_GT(b["targets_sent"], 0);
  EXPECT_GT(arm.targets(), 0);
  EXPECT_TRUE(arm.stop_seen());  // "source ended".
  // Every received pose went to the board: the newest is the recording's last.
  std::optional<BoardPose> board = PoseBoard::Global().Latest("arm");
  ASSERT_TRUE(board.has_value());
  EXPECT_EQ(board->count, int64_t(poses->size()));
  EXPECT_NEAR(board->stamp_s, poses->poses().back().time_s, 1e-6);
  EXPECT_LT(
      (board->pose.translation() - poses->poses().back().world_from_sensor.translation()).norm(),
      1e-6);
}

TEST_F(ArmPoseStreamPipeline, WithoutTheStreamTheRunSaysWhyNoTargetWasSent) {
  const std::string out = testing::TempDir("arm_stream_out_absent");
  StatusOr<RunReport> report =
      Run(*streamed_, out,
          {TapOnTarget(), "button.run.serve=true", "button.arm.port=" + std::to_string(FreePort()),
           "mono.run.metric_source=arm_stream", "button.arm_pose.wait_s=0.01"});
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  std::map<std::string, double> m = Figures(*report);
  EXPECT_EQ(m["targets_sent"], 0);
  EXPECT_EQ(m["counts.frames_with_arm_pose"], 0);
  EXPECT_EQ(m["counts.frames_without_arm_pose"], double(report->result.frames));
  const std::string& why = report->result.nothing_achieved;
  EXPECT_NE(why.find("no target sent"), std::string::npos) << why;
  EXPECT_NE(why.find("arm pose"), std::string::npos) << why;
  EXPECT_NE(why.find("arm_stream"), std::string::npos) << why;
  EXPECT_NE(testing::ReadAll(out + "/button_notes.txt").find(why), std::string::npos);
  // The stream needs the server; auto without serving and without arm_poses.txt tracks only.
  StatusOr<RunReport> unserved =
      Run(*streamed_, out, {TapOnTarget(), "mono.run.metric_source=arm_stream"});
  ASSERT_FALSE(unserved.ok());
  EXPECT_NE(unserved.status().message().find("needs serving"), std::string::npos)
      << unserved.status().ToString();
  StatusOr<RunReport> no_file = Run(*streamed_, out, {TapOnTarget()});
  ASSERT_TRUE(no_file.ok()) << no_file.status().ToString();
  EXPECT_EQ(Figures(*no_file)["counts.metric_scale"], 0);
  EXPECT_EQ(Figures(*no_file)["targets_sent"], 0);
  ASSERT_FALSE(no_file->result.notes.empty());
  EXPECT_NE(no_file->result.notes[0].find("no metric scale"), std::string::npos);
}

// A live camera whose frames carry the arm's pose at their stamps, as the ros:// source does
// from tf: the recording's frames, marked live with an arm-pose channel, and before each frame
// is handed on its arm pose from `arm` added to arm_poses() (none for the frames in `gaps`).
class LiveArmSource : public Source {
 public:
  LiveArmSource(std::unique_ptr<Source> frames, Trajectory arm, std::set<int64_t> gaps)
      : frames_(std::move(frames)), arm_(std::move(arm)), gaps_(std::move(gaps)) {
    info_ = frames_->info();
    info_.live = true;
    info_.frame_count = -1;
    info_.arm_pose_channel = "tf arm_base -> tool (test)";
  }
  Status Open() override { return Status::Ok(); }
  const SourceInfo& info() const override { return info_; }
  Status Grab() override { return frames_->Grab(); }
  StatusOr<Frame> Retrieve() override {
    StatusOr<Frame> frame = frames_->Retrieve();
    if (!frame.ok()) return frame;
    // Played in data time: no host-clock age at send time (a real camera's frames have one).
    std::visit([](auto& f) { f.stamp.host_time_s = 0; }, *frame);
    const double t = StampOf(*frame).sensor_time_s;
    const std::optional<size_t> i = arm_.Nearest(t, 1e-6);
    if (i && gaps_.count(index_) == 0) seen_.Add(t, arm_.poses()[*i].world_from_sensor);
    ++index_;
    return frame;
  }
  int64_t Position() const override { return index_; }
  const Trajectory* arm_poses() const override { return seen_.empty() ? nullptr : &seen_; }

 private:
  std::unique_ptr<Source> frames_;
  Trajectory arm_, seen_;
  std::set<int64_t> gaps_;
  SourceInfo info_;
  int64_t index_ = 0;
};

TEST(ArmPoseInput, ALiveSourcesArmChannelIsTakenWhenTheMountIsKnown) {
  SourceInfo info;
  info.path = "ros://?image=/cam/image";
  info.live = true;
  info.arm_pose_channel =
      "tf base_link -> end_effector (ros:// arm_base_frame, end_effector_frame)";
  MonoSlamRunOptions run;  // auto.
  run.hand_eye = "none";
  EXPECT_EQ(ChooseArmPoseInput(info, run, false, false), ArmPoseInput::kLiveSource);
  EXPECT_TRUE(ChooseButtonScaleMode(info, run, ArmPoseInput::kLiveSource).metric);
  // Serving does not take it away: the channel comes first.
  EXPECT_EQ(ChooseArmPoseInput(info, run, true, false), ArmPoseInput::kLiveSource);
  // Without the camera's mount auto tracks only, and says what to set.
  run.hand_eye.clear();
  EXPECT_EQ(ChooseArmPoseInput(info, run, false, false), ArmPoseInput::kRecorded);
  const ButtonScaleMode no_mount = ChooseButtonScaleMode(info, run, ArmPoseInput::kRecorded);
  EXPECT_FALSE(no_mount.metric);
  EXPECT_NE(no_mount.how.find("mono.run.hand_eye"), std::string::npos) << no_mount.how;
  EXPECT_NE(no_mount.how.find("end_effector"), std::string::npos) << no_mount.how;
  // arm requires it (the pipeline then needs the hand-eye); arm_stream and none keep theirs.
  run.metric_source = "arm";
  EXPECT_EQ(ChooseArmPoseInput(info, run, false, false), ArmPoseInput::kLiveSource);
  run.metric_source = "arm_stream";
  EXPECT_EQ(ChooseArmPoseInput(info, run, true, false), ArmPoseInput::kStream);
  run.metric_source = "none";
  EXPECT_FALSE(
      ChooseButtonScaleMode(info, run, ChooseArmPoseInput(info, run, false, false)).metric);
  // A recording, or a live source without the channel, never takes it.
  run.metric_source = "auto";
  run.hand_eye = "none";
  info.live = false;
  EXPECT_EQ(ChooseArmPoseInput(info, run, false, false), ArmPoseInput::kRecorded);
  info.live = true;
  info.arm_pose_channel.clear();
  EXPECT_EQ(ChooseArmPoseInput(info, run, false, false), ArmPoseInput::kRecorded);
}

// The button pipeline on a live source with the arm's poses at its frames' stamps: metric as on
// the recording (arm_poses.txt), the same scale and target; frames whose pose the source lacks
// are counted and named, and never take a neighbour's pose.
TEST_F(ArmPoseStreamPipeline, ALiveSourcesArmPosesGiveTheRecordedRunsScaleAndTarget) {
  StatusOr<RunReport> recorded =
      Run(*recorded_, testing::TempDir("arm_live_out_file"), {TapOnTarget()});
  ASSERT_TRUE(recorded.ok()) << recorded.status().ToString();
  std::map<std::string, double> a = Figures(*recorded);
  StatusOr<Trajectory> poses = ReadTumTrajectory(*recorded_ + "/arm_poses.txt");
  ASSERT_TRUE(poses.ok()) << poses.status().ToString();
  const auto run_live = [&](const std::string& out, std::set<int64_t> gaps) {
    RunRequest request;
    request.pipeline = "button";
    request.dataset_path = *streamed_;  // No arm_poses.txt: the poses come from the source only.
    request.out_dir = out;
    request.overrides = {TapOnTarget()};
    request.open_source = [&, gaps](const std::string& path) -> StatusOr<std::unique_ptr<Source>> {
      StatusOr<std::unique_ptr<Source>> frames = OpenDataset(path, SourceKind::kMono);
      if (!frames.ok()) return frames.status();
      return std::unique_ptr<Source>(
          std::make_unique<LiveArmSource>(std::move(*frames), *poses, gaps));
    };
    return RunPipeline(BuiltinPipelines(), request);
  };
  StatusOr<RunReport> live = run_live(testing::TempDir("arm_live_out"), {});
  ASSERT_TRUE(live.ok()) << live.status().ToString();
  std::map<std::string, double> b = Figures(*live);
  std::printf("  live source: scale_ml %g, final_error_mm %g (file: %g, %g)\n", b["scale_ml"],
              b["final_error_mm"], a["scale_ml"], a["final_error_mm"]);
  EXPECT_EQ(b["counts.metric_from_live_arm_poses"], 1);
  EXPECT_EQ(b["counts.metric_scale"], 1);
  EXPECT_EQ(b["counts.frames_with_arm_pose"], double(live->result.frames));
  EXPECT_EQ(b["counts.frames_without_arm_pose"], 0);
  ASSERT_TRUE(b.count("scale_ml") && b.count("final_error_mm"));
  EXPECT_NEAR(b["scale_ml"], a["scale_ml"], 0.01 * a["scale_ml"]);
  EXPECT_NEAR(b["final_error_mm"], a["final_error_mm"], 1.0);
  EXPECT_LT(b["final_error_mm"], 3.0);
  EXPECT_GT(b["targets_sent"], 0);

  // Frames 40..44 without a pose: counted, the first named with its stamp, the rest as before.
  StatusOr<RunReport> gaps = run_live(testing::TempDir("arm_live_out_gaps"), {40, 41, 42, 43, 44});
  ASSERT_TRUE(gaps.ok()) << gaps.status().ToString();
  std::map<std::string, double> c = Figures(*gaps);
  EXPECT_EQ(c["counts.frames_without_arm_pose"], 5);
  EXPECT_EQ(c["counts.frames_with_arm_pose"], double(gaps->result.frames - 5));
  char stamp[32];
  std::snprintf(stamp, sizeof(stamp), "%.6f s", poses->poses()[40].time_s);
  bool named = false;
  for (const std::string& note : gaps->result.notes) {
    named = named || (note.find("5 frame(s) without an arm pose") != std::string::npos &&
                      note.find(stamp) != std::string::npos &&
                      note.find("tf arm_base -> tool") != std::string::npos);
  }
  EXPECT_TRUE(named) << "no note names the first frame without a pose at " << stamp;
  EXPECT_LT(c["final_error_mm"], 3.0);
  EXPECT_GT(c["targets_sent"], 0);
}

}  // namespace
}  // namespace sightline
