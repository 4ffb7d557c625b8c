// sightline-cli arm-listen as a user runs it, against an arm-target server in this process:
// it prints the JSON lines that arrive, presents the token, fails with one line, drops
// over-long lines, and tells a stream that ended with a stop from one that did not.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

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
  EXPECT_TRUE(Contains(r.out, R"({"version":2,"type":"target",)")) << r.out;
  EXPECT_TRUE(Contains(r.out, R"("position_m":[0.5,0.01,0.3])")) << r.out;
  EXPECT_FALSE(Contains(r.out, "heartbeat")) << r.out;
}

TEST(ArmListenCli, PresentsTheToken) {
  auto server = Server("t0k");
  Publisher publisher(server.get());
  const std::string address = "127.0.0.1:" + std::to_string(server->port());
  const auto good = Cli("arm-listen " + address + " --token t0k --count 2 --timeout 5");
  ASSERT_EQ(good.exit_code, 0) << good.out;
  EXPECT_TRUE(Contains(good.out, R"("version":2)")) << good.out;
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

// A stand-in server on loopback that sends `bytes` to its first client, then closes.
class RawServer {
 public:
  explicit RawServer(std::string bytes) {
    fd_ = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    inet_pton(AF_INET, "127.0.0.1", &addr.sin_addr);
    EXPECT_EQ(bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)), 0);
    EXPECT_EQ(listen(fd_, 4), 0);
    socklen_t len = sizeof(addr);
    getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len);
    port_ = ntohs(addr.sin_port);
    thread_ = std::thread([this, bytes = std::move(bytes)] {
      const int client = accept(fd_, nullptr, nullptr);
      if (client < 0) return;
      for (size_t done = 0; done < bytes.size();) {
        const ssize_t n = send(client, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
        if (n <= 0) break;
        done += size_t(n);
      }
      close(client);
    });
  }
  ~RawServer() {
    shutdown(fd_, SHUT_RDWR);  // Ends a pending accept().
    thread_.join();
    close(fd_);
  }
  std::string address() const { return "127.0.0.1:" + std::to_string(port_); }

 private:
  int fd_ = -1;
  int port_ = 0;
  std::thread thread_;
};

const char kTarget[] = R"({"version":2,"type":"target","seq":0,"stamp":1.000000})";
const char kStop[] = R"({"version":2,"type":"stop","seq":2,"stamp":2.000000,"reason":"operator"})";

TEST(ArmListenCli, DropsOverlongLinesAndReadsOn) {
  const std::string overlong = "{\"x\":\"" + std::string(200000, 'A') + "\"}\n";
  RawServer server(std::string(kTarget) + "\n" + overlong + kStop + "\n");
  const auto r = Cli("arm-listen " + server.address() + " --max-line-bytes 1000 --timeout 10");
  EXPECT_EQ(r.exit_code, 0) << r.out.substr(0, 2000);
  EXPECT_TRUE(Contains(r.out, "dropped a line of 200008 bytes")) << r.out.substr(0, 2000);
  EXPECT_TRUE(Contains(r.out, kTarget)) << r.out.substr(0, 2000);
  EXPECT_TRUE(Contains(r.out, kStop)) << r.out.substr(0, 2000);
  EXPECT_LT(r.out.size(), 2000u);  // Nothing of the over-long line is printed.
}

TEST(ArmListenCli, AStreamThatEndsWithoutAStopFails) {
  RawServer server(std::string(kTarget) + "\n");
  const auto r = Cli("arm-listen " + server.address() + " --timeout 10");
  EXPECT_NE(r.exit_code, 0) << r.out;
  EXPECT_TRUE(Contains(r.out, kTarget)) << r.out;
  EXPECT_TRUE(Contains(r.out, "without a stop line")) << r.out;
}

TEST(ArmListenCli, AServerThatClosesWithAStopEndsTheListenerCleanly) {
  auto server = Server("");
  testing::ProcessResult r;
  std::thread listener(
      [&] { r = Cli("arm-listen 127.0.0.1:" + std::to_string(server->port()) + " --timeout 20"); });
  for (int k = 0; k < 1000 && server->Stats().authorised < 1; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(server->Stats().authorised, 1);
  server->SendStopAndClose("quit");
  listener.join();
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(Contains(r.out, R"("type":"stop")")) << r.out;
  EXPECT_TRUE(Contains(r.out, R"("reason":"quit")")) << r.out;
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
