// sightline-cli arm-listen as a user runs it, against an arm-target server in this process:
// it prints the JSON lines that arrive, presents the token, and fails with one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include "core/button/arm_server.h"
#include "tests/app/process.h"

namespace sightline {
namespace {

const std::string kCli = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";

testing::ProcessResult Cli(const std::string& args) {
  return testing::RunProcess(kCli + " " + args);
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Publishes a target every 20 ms until destroyed, so a listener started at any time sees some.
class Publisher {
 public:
  explicit Publisher(ArmServer* server)
      : thread_([this, server] {
          ArmTarget t;
          t.position_m = {0.5, 0.01, 0.3};
          t.source_frames = {7};
          while (!done_) {
            server->PublishTarget(t);
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
          }
        }) {}
  ~Publisher() {
    done_ = true;
    thread_.join();
  }

 private:
  std::atomic<bool> done_{false};
  std::thread thread_;
};

std::unique_ptr<ArmServer> Server(const std::string& token) {
  ArmServerOptions o;
  o.port = 0;
  o.token = token;
  o.heartbeat_s = 0.05;
  auto server = ArmServer::Start(o);
  EXPECT_TRUE(server.ok()) << server.status().ToString();
  return std::move(*server);
}

TEST(ArmListenCli, PrintsTheTargetsThatArrive) {
  auto server = Server("");
  Publisher publisher(server.get());
  const auto r = Cli("arm-listen 127.0.0.1:" + std::to_string(server->port()) +
                     " --count 3 --timeout 5 --no-heartbeats");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 3) << r.out;
  EXPECT_TRUE(Contains(r.out, R"({"version":1,"type":"target",)")) << r.out;
  EXPECT_TRUE(Contains(r.out, R"("position_m":[0.5,0.01,0.3])")) << r.out;
  EXPECT_FALSE(Contains(r.out, "heartbeat")) << r.out;
}

TEST(ArmListenCli, PresentsTheToken) {
  auto server = Server("t0k");
  Publisher publisher(server.get());
  const std::string address = "127.0.0.1:" + std::to_string(server->port());
  const auto good = Cli("arm-listen " + address + " --token t0k --count 2 --timeout 5");
  ASSERT_EQ(good.exit_code, 0) << good.out;
  EXPECT_TRUE(Contains(good.out, R"("version":1)")) << good.out;
  // Without the token nothing arrives: not even heartbeats.
  const auto none = Cli("arm-listen " + address + " --count 1 --timeout 0.5");
  EXPECT_NE(none.exit_code, 0);
  EXPECT_TRUE(Contains(none.out, "nothing arrived within 0.5 s")) << none.out;
  EXPECT_FALSE(Contains(none.out, "version")) << none.out;
}

TEST(ArmListenCli, PrintsAStop) {
  auto server = Server("");
  std::atomic<bool> done{false};
  std::thread stopper([&] {  // Until the listener has certainly connected.
    while (!done) {
      server->PublishStop("operator");
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  });
  const auto r = Cli("arm-listen 127.0.0.1:" + std::to_string(server->port()) +
                     " --count 1 --timeout 5 --no-heartbeats");
  done = true;
  stopper.join();
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(Contains(r.out, R"("type":"stop")")) << r.out;
  EXPECT_TRUE(Contains(r.out, R"("reason":"operator")")) << r.out;
}

TEST(ArmListenCli, BadArgumentsFailWithOneLine) {
  for (const std::string& args :
       {"arm-listen", "arm-listen localhost", "arm-listen 127.0.0.1:0",
        "arm-listen 127.0.0.1:1 --count 1 --timeout 1", "arm-listen 127.0.0.1:5757 --count -2"}) {
    const auto r = Cli(args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
    EXPECT_TRUE(Contains(r.out, "arm-listen")) << r.out;
  }
  EXPECT_TRUE(Contains(Cli("--help").out, "arm-listen HOST:PORT"));
  EXPECT_TRUE(Contains(Cli("arm-listen --help").out, "--token T"));
}

}  // namespace
}  // namespace sightline
