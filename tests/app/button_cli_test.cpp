// `sightline-cli run button` as a user runs it on the simulated panel approach (camera in the
// arm's hand, 12 cm sideways first, as the mono SLAM's accuracy test): the whole chain headless,
// its accuracy against the true button centres, a listening arm client receiving the targets,
// an arm client streaming its poses (arm-listen --poses) in place of arm_poses.txt, and a tap on
// the blank wall.
#include <gtest/gtest.h>
#include <signal.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>

#include "core/button/arm_client.h"
#include "core/button/arm_server.h"
#include "core/pipeline/button_pipeline.h"
#include "core/sim/simulate.h"
#include "tests/app/process.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

const std::string kCli = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";

class ButtonCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(testing::TempDir("button_cli_panel"));
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
    options.arm.sideways_m = 0.12;
    ASSERT_TRUE(sim::Simulate(options, *dir_).ok());
  }
  static void TearDownTestSuite() { delete dir_; }

  // "--tap U,V@0" a few pixels off the true centre of the approached button (id 5) at frame 0.
  static std::string TapOnTarget() {
    StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(*dir_ + "/buttons.csv");
    EXPECT_TRUE(buttons.ok()) << buttons.status().ToString();
    for (const TrueButton& b : *buttons) {
      if (b.id != 5) continue;
      EXPECT_TRUE(b.visible.at(0));
      char tap[64];
      std::snprintf(tap, sizeof(tap), "%.1f,%.1f@0", b.pixel[0].x() + 2, b.pixel[0].y() - 2);
      return tap;
    }
    ADD_FAILURE() << "button 5 not in buttons.csv";
    return "0,0";
  }

  static std::string* dir_;
};
std::string* ButtonCli::dir_ = nullptr;

TEST_F(ButtonCli, SimulatedApproachIsWithinThreeMillimetresWithTheMlScale) {
  const std::string out = testing::TempDir("button_cli_run");
  const testing::ProcessResult r = testing::RunProcess(kCli + " run button " + *dir_ + " --tap " +
                                                       TapOnTarget() + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::printf("%s", r.out.c_str());
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  const auto final_mm = testing::JsonNumber(metrics, "accuracy", "final_error_mm");
  const auto single_mm = testing::JsonNumber(metrics, "accuracy", "final_error_mm_single_ratio");
  const auto track_px = testing::JsonNumber(metrics, "accuracy", "track_error_px_median");
  const auto track_max_px = testing::JsonNumber(metrics, "accuracy", "track_error_px_max");
  const auto targets = testing::JsonNumber(metrics, "accuracy", "targets_sent");
  ASSERT_TRUE(final_mm && single_mm && track_px && track_max_px && targets) << metrics;
  EXPECT_LT(*final_mm, 3.0);
  EXPECT_GE(*single_mm, 0.0);  // Reported beside it.
  EXPECT_LT(*track_px, 3.0);
  EXPECT_LT(*track_max_px, 3.0);  // Within 3 px over the whole approach.
  EXPECT_GT(*targets, 0);
  EXPECT_TRUE(testing::JsonNumber(metrics, "tracking", "median").has_value()) << metrics;
  EXPECT_TRUE(testing::JsonNumber(metrics, "counts", "tap_to_first_target_frames").has_value())
      << metrics;
  EXPECT_EQ(testing::JsonNumber(metrics, "counts", "true_button").value_or(-1), 5);
  const std::string csv = testing::ReadTextFile(out + "/button.csv");
  EXPECT_EQ(csv.rfind("frame,time_s,state,gate,u_px,v_px", 0), 0u) << csv.substr(0, 200);
  EXPECT_NE(csv.find(",target_sent,send,"), std::string::npos);
}

TEST_F(ButtonCli, AListeningArmClientReceivesTheTargets) {
  int port = 0;
  {  // A free port on loopback.
    ArmServerOptions probe;
    probe.port = 0;
    auto server = ArmServer::Start(probe);
    ASSERT_TRUE(server.ok()) << server.status().ToString();
    port = (*server)->port();
  }
  const std::string address = "127.0.0.1:" + std::to_string(port);
  const std::string out = testing::TempDir("button_cli_serve");
  testing::ProcessResult run;
  std::thread runner([&] {
    run =
        testing::RunProcess(kCli + " run button " + *dir_ + " --tap " + TapOnTarget() + " --out " +
                            out + " --serve " + address + " --set button.run.wait_clients=2");
  });
  // An in-process client first (it also tells when the server is up) ...
  std::optional<ArmClient> client;
  for (int attempt = 0; attempt < 600 && !client; ++attempt) {
    auto c = ArmClient::Connect("127.0.0.1", port, "", 1000);
    if (c.ok()) {
      client.emplace(std::move(*c));
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  ASSERT_TRUE(client.has_value()) << "the button run never served " << address;
  // ... then sightline-cli arm-listen, the second client the run waits for.
  const testing::ProcessResult listen = testing::RunProcess(
      kCli + " arm-listen " + address + " --count 1 --timeout 120 --no-heartbeats");
  bool target = false;
  for (int i = 0; i < 10000 && !target; ++i) {
    StatusOr<std::string> line = client->ReadLine(60000);
    if (!line.ok()) break;
    target = line->find("\"type\":\"target\"") != std::string::npos;
  }
  runner.join();
  ASSERT_EQ(run.exit_code, 0) << run.out;
  ASSERT_EQ(listen.exit_code, 0) << listen.out;
  EXPECT_NE(listen.out.find("\"type\":\"target\""), std::string::npos) << listen.out;
  EXPECT_NE(listen.out.find("\"frame_id\":\"arm_base\""), std::string::npos) << listen.out;
  EXPECT_TRUE(target);
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  EXPECT_GT(testing::JsonNumber(metrics, "accuracy", "targets_sent").value_or(0), 0);
  EXPECT_EQ(testing::JsonNumber(metrics, "counts", "arm_clients_at_start").value_or(0), 2);
}

// The recording without arm_poses.txt: `run button --serve` takes the scale from the arm's pose
// stream (auto), played by `arm-listen --poses` from the original arm_poses.txt.
TEST_F(ButtonCli, AnArmClientStreamingItsPosesGivesTheMetricScale) {
  const std::string copy = testing::TempDir("button_cli_stream_copy");
  std::filesystem::remove_all(copy);
  std::filesystem::copy(*dir_, copy, std::filesystem::copy_options::recursive);
  ASSERT_TRUE(std::filesystem::remove(copy + "/arm_poses.txt"));
  int port = 0;
  {  // A free port on loopback.
    ArmServerOptions probe;
    probe.port = 0;
    auto server = ArmServer::Start(probe);
    ASSERT_TRUE(server.ok()) << server.status().ToString();
    port = (*server)->port();
  }
  const std::string address = "127.0.0.1:" + std::to_string(port);
  const std::string out = testing::TempDir("button_cli_stream");
  testing::ProcessResult run;
  std::thread runner([&] {
    run = testing::RunProcess(kCli + " run button " + copy + " --tap " + TapOnTarget() + " --out " +
                              out + " --serve " + address +
                              " --set button.run.wait_clients=1 --set button.arm_pose.wait_s=30"
                              " --set button.arm_pose.keep_s=600");
  });
  testing::ProcessResult arm;
  for (int attempt = 0; attempt < 600; ++attempt) {  // Until the run serves.
    arm = testing::RunProcess(kCli + " arm-listen " + address + " --poses " + *dir_ +
                              "/arm_poses.txt --timeout 120 --no-heartbeats");
    if (arm.out.find("cannot connect") == std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  runner.join();
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_EQ(arm.exit_code, 0) << arm.out;  // Ended by the stop line of "source ended".
  EXPECT_NE(arm.out.find("\"type\":\"target\""), std::string::npos) << arm.out;
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  EXPECT_EQ(testing::JsonNumber(metrics, "counts", "metric_from_arm_stream").value_or(0), 1);
  EXPECT_EQ(testing::JsonNumber(metrics, "counts", "frames_without_arm_pose").value_or(-1), 0);
  EXPECT_GT(testing::JsonNumber(metrics, "counts", "arm_poses_received").value_or(0), 50);
  EXPECT_LT(testing::JsonNumber(metrics, "accuracy", "final_error_mm").value_or(1e9), 3.0);
}

TEST_F(ButtonCli, SigtermSendsTheArmClientsAStopLine) {
  int port = 0;
  {  // A free port on loopback.
    ArmServerOptions probe;
    probe.port = 0;
    auto server = ArmServer::Start(probe);
    ASSERT_TRUE(server.ok()) << server.status().ToString();
    port = (*server)->port();
  }
  const std::string out = testing::TempDir("button_cli_sigterm");
  const std::string pid_file = out + "/run.pid";
  testing::ProcessResult run;
  std::thread runner([&] {
    run = testing::RunProcess("echo $$ > " + pid_file + "; exec " + kCli + " run button " + *dir_ +
                              " --tap " + TapOnTarget() + " --out " + out + " --serve 127.0.0.1:" +
                              std::to_string(port) + " --set button.run.wait_clients=1");
  });
  std::optional<ArmClient> client;
  for (int attempt = 0; attempt < 600 && !client; ++attempt) {
    auto c = ArmClient::Connect("127.0.0.1", port, "", 1000);
    if (c.ok()) {
      client.emplace(std::move(*c));
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  ASSERT_TRUE(client.has_value()) << "the button run never served port " << port;
  // The run is serving and has sent a target: terminate it the way a service manager does.
  bool targeted = false;
  for (int i = 0; i < 10000 && !targeted; ++i) {
    StatusOr<std::string> line = client->ReadLine(60000);
    ASSERT_TRUE(line.ok()) << "no target before: " << line.status().ToString();
    targeted = line->find("\"type\":\"target\"") != std::string::npos;
  }
  const int pid = std::atoi(testing::ReadTextFile(pid_file).c_str());
  ASSERT_GT(pid, 0);
  ASSERT_EQ(kill(pid, SIGTERM), 0);
  std::string stop;
  for (int i = 0; i < 10000 && stop.empty(); ++i) {
    StatusOr<std::string> line = client->ReadLine(60000);
    ASSERT_TRUE(line.ok()) << "no stop line before: " << line.status().ToString();
    if (line->find("\"type\":\"stop\"") != std::string::npos) stop = *line;
  }
  EXPECT_NE(stop.find("\"reason\":\"cancelled\""), std::string::npos) << stop;
  EXPECT_EQ(client->ReadLine(10000).status().code(), StatusCode::kUnavailable);  // Then closed.
  runner.join();
  EXPECT_EQ(run.exit_code, kExitCancelled) << run.out;
  EXPECT_NE(run.out.find("cancelled"), std::string::npos) << run.out;
  // Cancelled mid-run, it still wrote what it had: the button's track and its figures.
  EXPECT_TRUE(std::filesystem::is_regular_file(out + "/button.csv")) << run.out;
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  EXPECT_NE(metrics.find("\"ended\": \"cancelled\""), std::string::npos) << metrics;
  EXPECT_GT(testing::JsonNumber(metrics, "accuracy", "targets_sent").value_or(0), 0) << metrics;
  // A recording served to an arm says so: its targets are not from a live camera.
  const std::string replay = "replay: the targets served come from the recorded frames of ";
  EXPECT_NE(metrics.find(replay), std::string::npos) << metrics;
  EXPECT_NE(run.out.find(replay), std::string::npos) << run.out;
}

TEST_F(ButtonCli, ServingBeyondLoopbackNeedsAToken) {
  const std::string out = testing::TempDir("button_cli_public");
  const testing::ProcessResult r =
      testing::RunProcess(kCli + " run button " + *dir_ + " --tap " + TapOnTarget() + " --out " +
                          out + " --serve 0.0.0.0:5757");
  EXPECT_NE(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("button.arm.token"), std::string::npos) << r.out;
}

TEST_F(ButtonCli, ARunThatSendsNoTargetExitsThreeWithTheReasonInMetrics) {
  // Three frames: the tap finds the button, but no target can be located and gated that soon.
  const std::string out = testing::TempDir("button_cli_nothing");
  const testing::ProcessResult r =
      testing::RunProcess(kCli + " run button " + *dir_ + " --tap " + TapOnTarget() + " --out " +
                          out + " --quiet --set mono.run.max_frames=3");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_EQ(r.out.rfind("sightline-cli: run button achieved nothing: no target sent", 0), 0u)
      << r.out;
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  EXPECT_NE(metrics.find("\"failure\""), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("no target sent"), std::string::npos) << metrics;
}

TEST_F(ButtonCli, ATapOnTheBlankWallIsNoButton) {
  const std::string out = testing::TempDir("button_cli_wall");
  const testing::ProcessResult r =
      testing::RunProcess(kCli + " run button " + *dir_ + " --tap 8,8@0 --out " + out);
  EXPECT_NE(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("no button here"), std::string::npos) << r.out;
  const testing::ProcessResult bad =
      testing::RunProcess(kCli + " run button " + *dir_ + " --tap 1x2 --out " + out);
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.out.find("button.run.tap"), std::string::npos) << bad.out;
  const testing::ProcessResult none =
      testing::RunProcess(kCli + " run button " + *dir_ + " --out " + out);
  EXPECT_NE(none.exit_code, 0);
  EXPECT_NE(none.out.find("--tap"), std::string::npos) << none.out;
}

// train-button-classifier: a bad labels file is named with its line; on two labelled photos
// it writes a trained model in the built-in model's form.
TEST(TrainButtonClassifierCli, NamesABadLabelsLineAndWritesATrainedModel) {
  const std::string dir = testing::TempDir("train_button_cli");
  {
    std::ofstream bad(dir + "/bad.csv");
    bad << "# comment\n1.jpg,button,10,20,30,40,1\n1.jpg,button,10,x,30,40,2\n";
  }
  testing::ProcessResult r = testing::RunProcess(kCli + " train-button-classifier " + dir +
                                                 "/bad.csv " + dir + " --out " + dir + "/m.inc");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("bad.csv line 3"), std::string::npos) << r.out;
  r = testing::RunProcess(kCli + " train-button-classifier " + dir + "/none.csv " + dir +
                          " --out " + dir + "/m.inc");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("none.csv"), std::string::npos) << r.out;
  SIGHTLINE_REQUIRE_DATA(photos, "button_panels/test_panels");
  {
    std::ifstream all(SIGHTLINE_BUTTON_LABELS);
    std::ofstream two(dir + "/two.csv");
    std::string line;
    while (std::getline(all, line)) {
      if (line.rfind("33.jpg,", 0) == 0 || line.rfind("10.jpg,", 0) == 0) two << line << "\n";
    }
  }
  r = testing::RunProcess(kCli + " train-button-classifier " + dir + "/two.csv " + photos +
                          " --out " + dir + "/m.inc");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("2 photos"), std::string::npos) << r.out;
  const std::string model = testing::ReadTextFile(dir + "/m.inc");
  EXPECT_NE(model.find("kRegionModelTrained = true"), std::string::npos);
  EXPECT_NE(model.find("kRegionWeights[] = {"), std::string::npos);
}

}  // namespace
}  // namespace sightline
