// The operator loop closed live over real TCP, in one process with threads: the button pipeline
// runs on the live simulated camera sim://panel (rendered from the arm's streamed pose), serves
// its targets, and the simulated arm (core/button/arm_simulator.h) streams its pose, flies its
// plan and presses what it is sent: camera -> SLAM -> tap -> target -> arm -> camera. Outcomes
// against the scene's truth; no timed assertion (the machine's load only makes it slower).
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "core/button/arm_sim_session.h"
#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/button_result.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/pipeline/sim_panel_source.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

// A loopback port free right now (the server binds it a moment later).
int FreePort() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = 0;
  bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr));
  socklen_t size = sizeof(addr);
  getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &size);
  close(fd);
  return ntohs(addr.sin_port);
}

// The arm's options for the loop: slow enough for a SLAM at a few frames per second.
ArmSimOptions LoopArm() {
  ArmSimOptions o;
  o.max_speed_mps = 0.02;
  o.max_angular_speed_dps = 5;
  o.max_time_s = 400;  // A loop that never sends a target fails, with its figures.
  return o;
}

struct Loop {
  int seed = 4;
  int button = 5;
  std::shared_ptr<ButtonCommands> commands = std::make_shared<ButtonCommands>();
  std::atomic<bool> cancel_run{false}, cancel_arm{false};
  bool operator_panel = false;  // Run with ButtonCommands (STOP) rather than headless.
  std::atomic<int> phase{-1};
  std::atomic<bool> arm_done{false};
  StatusOr<RunReport> report = Unavailable("not run");
  std::string out_dir;
  StatusOr<ArmSimSessionResult> arm_result = Unavailable("not run");
  std::unique_ptr<ArmSimulator> arm;
  std::thread run_thread, arm_thread;

  void Start() {
    const int port = FreePort();
    const std::string uri = "sim://panel?seed=" + std::to_string(seed) + "&fps=4";
    out_dir = testing::TempDir("closed_loop_" + std::to_string(seed) + "_" +
                               std::to_string(button) + (operator_panel ? "_panel" : ""));
    StatusOr<ArmSimWorld> world = BuildArmSimWorld(seed, LoopArm());
    ASSERT_TRUE(world.ok()) << world.status().ToString();
    arm = std::make_unique<ArmSimulator>(LoopArm(), std::move(*world));
    arm->set_event_sink([this](const ArmSimEvent& e) {
      std::printf("  seed %d arm %.3f %s\n", seed, e.time_s, e.what.c_str());
      std::fflush(stdout);
    });
    run_thread = std::thread([this, uri, port] {
      PipelineRegistry registry = BuiltinPipelines();
      if (operator_panel) {
        registry = PipelineRegistry();
        (void)registry.Register(ButtonPipelineInfo(commands));
      }
      RunRequest request;
      request.pipeline = "button";
      request.dataset_path = uri;
      request.out_dir = out_dir;
      request.overrides = {"button.run.tap=button:" + std::to_string(button),
                           "button.run.serve=true",
                           "button.arm.port=" + std::to_string(port),
                           "button.arm.token=loop-secret",
                           "button.run.wait_clients=1",
                           "button.run.wait_clients_s=120",
                           "mono.run.max_frames=3000"};
      request.cancel = &cancel_run;
      report = RunPipeline(registry, request);
    });
    arm_thread = std::thread([this, port] {
      for (int attempt = 0; attempt < 600 && !cancel_arm; ++attempt) {
        arm_result = RunArmSimSession(
            "127.0.0.1", port, "loop-secret", arm.get(), &cancel_arm,
            [this](double, const Eigen::Isometry3d&) { phase = static_cast<int>(arm->phase()); });
        if (arm_result.ok()) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));  // Server not up yet.
      }
      arm_done = true;
    });
  }
  void Join() {
    arm_thread.join();
    cancel_run = true;
    run_thread.join();
  }
};

// One test per seed (a live loop takes a minute or two; each stays within ctest's timeout).
class ClosedLoopSeed : public ::testing::TestWithParam<int> {};

TEST_P(ClosedLoopSeed, TheSimulatedArmPressesTheTappedButton) {
  const int seed = GetParam();
  Loop loop;
  loop.seed = seed;
  loop.button = 5;
  loop.Start();
  loop.Join();
  ASSERT_TRUE(loop.arm_result.ok()) << loop.arm_result.status().ToString();
  const ArmSimOutcome& o = loop.arm_result->outcome;
  std::printf(
      "seed %d: end %s, nearest button %d, error %.2f mm (across %.2f, along the push "
      "%+.2f), approach %.2f deg, targets %lld; within 3 mm and 5 deg: %s\n",
      seed, loop.arm_result->end_reason.c_str(), o.nearest_button, o.distance_mm, o.lateral_mm,
      o.depth_mm, o.approach_error_deg,
      static_cast<long long>(loop.arm->counts().count("targets") ? loop.arm->counts().at("targets")
                                                                 : 0),
      o.distance_mm < 3.0 && o.approach_error_deg < 5.0 ? "yes" : "no");
  // It pressed the tapped button within 3 mm of its centre, the tool along the push within
  // 5 deg. The approach is the plane the arm's own sideways moves show (arm_plane_normal.h).
  EXPECT_EQ(loop.arm_result->end_reason, "finished");
  EXPECT_EQ(o.nearest_button, 5);
  EXPECT_LT(o.distance_mm, 3.0);
  EXPECT_LT(o.approach_error_deg, 5.0);
  EXPECT_EQ(loop.arm->counts().count("malformed"), 0u);
  // The live run has no end of its own: cancelled after the press, it still wrote its results.
  ASSERT_TRUE(loop.report.ok()) << loop.report.status().ToString();
  EXPECT_EQ(loop.report->metrics.ended, "cancelled");
  EXPECT_EQ(loop.report->result.ended_early.code(), StatusCode::kCancelled);
  EXPECT_GT(loop.report->metrics.frames, 10);
  EXPECT_TRUE(std::filesystem::is_regular_file(loop.out_dir + "/button.csv"));
  EXPECT_TRUE(std::filesystem::is_regular_file(loop.out_dir + "/metrics.json"));
  for (const std::string& note : loop.report->result.notes) {
    EXPECT_NE(note.rfind("replay:", 0), 0u) << "a live camera is not a replay: " << note;
  }
}

INSTANTIATE_TEST_SUITE_P(FiveSeeds, ClosedLoopSeed, ::testing::Values(1, 2, 3, 4, 5));

TEST(ClosedLoop, AStopMidApproachStopsTheArmAtOnce) {
  Loop loop;
  loop.seed = 4;
  loop.button = 3;
  loop.operator_panel = true;
  loop.Start();
  // The operator presses STOP while the arm moves to the target it was sent.
  while (loop.phase.load() != static_cast<int>(ArmSimPhase::kToStandoff) && !loop.arm_done) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::this_thread::sleep_for(std::chrono::seconds(2));
  loop.commands->Stop("operator");
  std::this_thread::sleep_for(std::chrono::seconds(3));
  loop.cancel_arm = true;
  loop.Join();
  ASSERT_TRUE(loop.arm_result.ok()) << loop.arm_result.status().ToString();
  ASSERT_TRUE(loop.arm->stopped());
  double stop_s = 0;
  for (const ArmSimEvent& e : loop.arm->events()) {
    if (e.what.rfind("stopped (operator)", 0) == 0 && stop_s == 0) stop_s = e.time_s;
  }
  ASSERT_GT(stop_s, 0) << "no stop line reached the arm";
  const Eigen::Vector3d final = loop.arm->pose().translation();
  int after = 0, moving_before = 0;
  const std::vector<ArmSimStep>& steps = loop.arm->steps();
  for (size_t i = 1; i < steps.size(); ++i) {
    if (steps[i].time_s >= stop_s) {
      EXPECT_EQ(steps[i].position, final) << "+" << steps[i].time_s - stop_s << " s";
      ++after;
    } else if (steps[i].time_s > stop_s - 1 && steps[i].position != steps[i - 1].position) {
      ++moving_before;  // It was moving in the second before the stop.
    }
  }
  EXPECT_GT(after, 50);
  EXPECT_GT(moving_before, 10);
  EXPECT_GT(loop.arm->Outcome().distance_mm, 10);  // Stopped on its way.
}

}  // namespace
}  // namespace sightline
