// The arm-target server under load and attack, over real TCP on loopback: flooders, idle
// sockets, wrong tokens, a full queue when STOP is pressed, readers that never read, abrupt
// disconnects, a public bind without a token, a stop line on every way out, and an arm streaming
// its pose at 1 kHz. The assertions are about order and delivery (the stop arrives, the good
// client is served, the attackers are closed); the few time bounds are generous.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <thread>

#include "core/button/arm_client.h"
#include "core/button/arm_server.h"

namespace sightline {
namespace {

using Clock = std::chrono::steady_clock;

std::unique_ptr<ArmServer> StartServer(ArmServerOptions o) {
  o.port = 0;
  auto server = ArmServer::Start(o);
  EXPECT_TRUE(server.ok()) << server.status().ToString();
  return server.ok() ? std::move(*server) : nullptr;
}

bool Eventually(const std::function<bool()>& done, double seconds = 5) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return done();
}

ArmClient Connect(const ArmServer& server, const std::string& token) {
  auto client = ArmClient::Connect("127.0.0.1", server.port(), token);
  EXPECT_TRUE(client.ok()) << client.status().ToString();
  return std::move(*client);
}

// The next line, or "" on timeout or close.
std::string Next(ArmClient& client, int timeout_ms = 2000) {
  StatusOr<std::string> line = client.ReadLine(timeout_ms);
  return line.ok() ? *line : "";
}

bool Is(const std::string& line, const std::string& type) {
  return line.find("\"type\":\"" + type + "\"") != std::string::npos;
}

ArmTarget BigTarget() {
  ArmTarget t;
  t.position_m = {0.5, 0.0, 0.3};
  t.source_frames.assign(20000, 7);  // ~40 kB per line: a socket that is not read fills fast.
  return t;
}

// Reads lines until a stop (true) or until the connection ends or `timeout_ms` passes without a
// line; `lines` receives everything read.
bool ReadUntilStop(ArmClient& client, std::vector<std::string>* lines, int timeout_ms = 2000) {
  for (int k = 0; k < 100000; ++k) {
    StatusOr<std::string> line = client.ReadLine(timeout_ms);
    if (!line.ok()) return false;
    lines->push_back(*line);
    if (Is(*line, "stop")) return true;
  }
  return false;
}

// A raw loopback socket, for what ArmClient does not do (flood, reset).
int RawConnect(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(uint16_t(port));
  inet_pton(AF_INET, "127.0.0.1", &addr.sin_addr);
  if (connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

// Sends garbage as fast as the server takes it from `threads` connections, reconnecting when
// closed, until destroyed (and for at most 20 s).
class Flooder {
 public:
  Flooder(int port, int threads, std::string prefix = "") {
    for (int i = 0; i < threads; ++i) {
      threads_.emplace_back([this, port, prefix] {
        const std::string junk(64 * 1024, 'A');
        const auto end = Clock::now() + std::chrono::seconds(20);
        while (!done_ && Clock::now() < end) {
          const int fd = RawConnect(port);
          if (fd < 0) continue;
          ++connections_;
          timeval tv{0, 100000};  // A send blocked by a full window gives up now and then.
          setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof(tv));
          if (!prefix.empty()) send(fd, prefix.data(), prefix.size(), MSG_NOSIGNAL);
          while (!done_ && Clock::now() < end) {
            const ssize_t n = send(fd, junk.data(), junk.size(), MSG_NOSIGNAL);
            if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) break;
          }
          close(fd);
        }
      });
    }
  }
  ~Flooder() {
    done_ = true;
    for (auto& t : threads_) t.join();
  }
  int connections() const { return connections_.load(); }

 private:
  std::atomic<bool> done_{false};
  std::atomic<int> connections_{0};
  std::vector<std::thread> threads_;
};

TEST(ArmServerAttack, FloodersDelayNeitherHeartbeatsNorTheStop) {
  ArmServerOptions o;
  o.token = "s3cret";
  o.heartbeat_s = 0.05;
  auto server = StartServer(o);
  ASSERT_TRUE(server);
  ArmClient good = Connect(*server, "s3cret");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 1; }));
  Flooder without_token(server->port(), 2);
  Flooder with_token(server->port(), 2, "{\"token\": \"s3cret\"}\n");
  ASSERT_TRUE(Eventually(
      [&] { return without_token.connections() >= 2 && with_token.connections() >= 2; }));
  // Heartbeats keep coming: 10 of them (0.5 s worth) arrive, each within 1 s of the last.
  int heartbeats = 0;
  for (int k = 0; k < 1000 && heartbeats < 10; ++k) {
    StatusOr<std::string> line = good.ReadLine(1000);
    ASSERT_TRUE(line.ok()) << "after " << heartbeats << " heartbeats: " << line.status().ToString();
    heartbeats += Is(*line, "heartbeat") ? 1 : 0;
  }
  EXPECT_EQ(heartbeats, 10);
  server->PublishTarget(BigTarget());
  const auto start = Clock::now();
  server->PublishStop("operator");
  std::vector<std::string> lines;
  ASSERT_TRUE(ReadUntilStop(good, &lines));
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 2.0);
  // The flooders were closed: without the token at their first over-long line, with it for
  // talking after the handshake.
  const ArmServerStats stats = server->Stats();
  EXPECT_GT(stats.token_failures, 0);
  EXPECT_GT(stats.closed_for_input, 0);
}

TEST(ArmServerAttack, FiftyIdleSocketsDoNotLockOutAClientAndAreClosed) {
  ArmServerOptions o;
  o.token = "s3cret";
  o.heartbeat_s = 0.05;
  o.handshake_s = 0.5;
  o.max_unauthenticated = 4;
  auto server = StartServer(o);
  ASSERT_TRUE(server);
  std::vector<ArmClient> idle;
  for (int i = 0; i < 50; ++i) idle.push_back(Connect(*server, ""));
  ArmClient good = Connect(*server, "s3cret");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 1; }));
  server->PublishTarget(BigTarget());
  std::string line;
  for (int k = 0; k < 100 && !Is(line, "target"); ++k) line = Next(good);
  EXPECT_TRUE(Is(line, "target"));
  // Every idle socket is closed without a byte: evicted by newer ones or past its deadline.
  for (ArmClient& c : idle) EXPECT_EQ(c.ReadLine(5000).status().code(), StatusCode::kUnavailable);
  EXPECT_TRUE(Eventually([&] { return server->Stats().clients == 1; }));
  const ArmServerStats stats = server->Stats();
  EXPECT_EQ(stats.evicted + stats.handshake_timeouts, 50);
}

TEST(ArmServerAttack, AnIdleSocketIsClosedAtTheHandshakeDeadlineNotBefore) {
  ArmServerOptions o;
  o.token = "s3cret";
  o.handshake_s = 0.4;
  auto server = StartServer(o);
  ASSERT_TRUE(server);
  ArmClient idle = Connect(*server, "");
  EXPECT_EQ(idle.ReadLine(100).status().code(), StatusCode::kOutOfRange);  // Still open.
  EXPECT_EQ(idle.ReadLine(5000).status().code(), StatusCode::kUnavailable);
  EXPECT_EQ(server->Stats().handshake_timeouts, 1);
}

TEST(ArmServerAttack, OneTokenAttemptPerConnection) {
  ArmServerOptions o;
  o.token = "s3cret";
  o.heartbeat_s = 0.01;
  auto server = StartServer(o);
  ASSERT_TRUE(server);
  // A wrong guess then the right token on the same connection: closed after the first line.
  ArmClient guesser = Connect(*server, "guess");
  (void)guesser.Send("{\"token\": \"s3cret\"}\n");  // Fails when it is already closed.
  EXPECT_EQ(guesser.ReadLine(2000).status().code(), StatusCode::kUnavailable);
  ArmClient both = Connect(*server, "");
  ASSERT_TRUE(both.Send("{\"token\": \"nope\"}\n{\"token\": \"s3cret\"}\n").ok());
  EXPECT_EQ(both.ReadLine(2000).status().code(), StatusCode::kUnavailable);
  EXPECT_EQ(server->Stats().token_failures, 2);
  EXPECT_EQ(server->Stats().authorised, 0);
  // A new connection with the right token is served.
  ArmClient good = Connect(*server, "s3cret");
  StatusOr<std::string> line = good.ReadLine(2000);
  ASSERT_TRUE(line.ok()) << line.status().ToString();
  EXPECT_TRUE(Is(*line, "heartbeat")) << *line;
}

TEST(ArmServerAttack, AFullQueueNeverLosesTheStop) {
  ArmServerOptions o;
  o.heartbeat_s = 0.005;  // Heartbeats keep arriving while the client does not read.
  o.queue_messages = 4;
  auto server = StartServer(o);
  ASSERT_TRUE(server);
  ArmClient slow = Connect(*server, "");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 1; }));
  // 40 MB: more than the loopback socket buffers hold, and 4 lines queued at most.
  for (int k = 0; k < 1000; ++k) server->PublishTarget(BigTarget());
  ASSERT_TRUE(Eventually([&] { return server->Stats().dropped >= 500; }));
  server->PublishStop("operator");
  const int64_t heartbeats = server->Stats().heartbeats;
  ASSERT_TRUE(Eventually([&] { return server->Stats().heartbeats > heartbeats + 20; }));
  for (int k = 0; k < 10; ++k) EXPECT_EQ(server->PublishTarget(BigTarget()), -1);
  // The reader wakes up: the stop is there, and after it no target; heartbeats say disabled.
  std::vector<std::string> lines;
  ASSERT_TRUE(ReadUntilStop(slow, &lines));
  for (int k = 0; k < 5; ++k) {
    StatusOr<std::string> line = slow.ReadLine(1000);
    ASSERT_TRUE(line.ok()) << line.status().ToString();
    EXPECT_TRUE(Is(*line, "heartbeat")) << line->substr(0, 80);
    EXPECT_NE(line->find("\"targets_enabled\":false"), std::string::npos) << *line;
  }
}

TEST(ArmServerAttack, ReadersThatNeverReadDelayNeitherPublishingNorOthers) {
  ArmServerOptions o;
  o.heartbeat_s = 0.05;
  o.queue_messages = 8;
  o.close_flush_s = 0.2;
  auto server = StartServer(o);
  ASSERT_TRUE(server);
  std::vector<ArmClient> dead;
  for (int i = 0; i < 4; ++i) dead.push_back(Connect(*server, ""));
  ArmClient live = Connect(*server, "");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 5; }));
  for (int k = 0; k < 100; ++k) {
    server->PublishTarget(BigTarget());
    for (int r = 0; r < 10; ++r) {  // The live client keeps up.
      if (!live.ReadLine(0).ok()) break;
    }
  }
  server->PublishStop("operator");
  std::vector<std::string> lines;
  ASSERT_TRUE(ReadUntilStop(live, &lines));
  // Closing does not hang on the dead readers: it gives up on them after close_flush_s.
  const auto start = Clock::now();
  server->SendStopAndClose("quit");
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 5.0);
  lines.clear();
  EXPECT_TRUE(ReadUntilStop(live, &lines));
  EXPECT_NE(lines.back().find("\"reason\":\"quit\""), std::string::npos) << lines.back();
}

TEST(ArmServerAttack, AbruptDisconnectsDoNoHarm) {
  ArmServerOptions o;
  o.token = "s3cret";
  o.heartbeat_s = 0.01;
  auto server = StartServer(o);
  ASSERT_TRUE(server);
  ArmClient good = Connect(*server, "s3cret");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 1; }));
  for (int i = 0; i < 20; ++i) {
    const int fd = RawConnect(server->port());
    ASSERT_GE(fd, 0);
    if (i % 2 == 0) {
      const std::string token = "{\"token\": \"s3cret\"}\n";
      send(fd, token.data(), token.size(), MSG_NOSIGNAL);
      server->PublishTarget(BigTarget());
    }
    linger reset{1, 0};  // close() sends a reset instead of a FIN.
    setsockopt(fd, SOL_SOCKET, SO_LINGER, &reset, sizeof(reset));
    close(fd);
  }
  ASSERT_TRUE(Eventually([&] { return server->Stats().clients == 1; }));
  server->PublishStop("operator");
  std::vector<std::string> lines;
  EXPECT_TRUE(ReadUntilStop(good, &lines));
}

TEST(ArmServerAttack, APublicBindNeedsAToken) {
  ArmServerOptions o;
  o.port = 0;
  o.bind_address = "0.0.0.0";
  std::string error;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("button.arm.token"), std::string::npos) << error;
  auto refused = ArmServer::Start(o);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(refused.status().message().find("button.arm.token"), std::string::npos);
  o.token = "s3cret";
  EXPECT_TRUE(o.IsValid(&error)) << error;  // Not started: tests stay on loopback.
  o.token.clear();
  o.bind_address = "127.0.0.2";
  EXPECT_TRUE(o.IsValid(&error)) << error;
  EXPECT_TRUE(IsLoopbackAddress("127.0.0.1"));
  EXPECT_FALSE(IsLoopbackAddress("10.0.0.1"));
  EXPECT_FALSE(IsLoopbackAddress("128.0.0.1"));
}

TEST(ArmServerAttack, EveryWayOutSendsAStopLine) {
  ArmServerOptions o;
  o.heartbeat_s = 0;
  // The destructor.
  auto server = StartServer(o);
  ASSERT_TRUE(server);
  ArmClient a = Connect(*server, "");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 1; }));
  server->PublishTarget(BigTarget());
  server.reset();
  std::vector<std::string> lines;
  ASSERT_TRUE(ReadUntilStop(a, &lines));
  EXPECT_NE(lines.back().find("\"reason\":\"shutdown\""), std::string::npos);
  EXPECT_EQ(a.ReadLine(2000).status().code(), StatusCode::kUnavailable);  // Then closed.
  // SendStopAndClose: idempotent, publishing afterwards is refused.
  server = StartServer(o);
  ArmClient b = Connect(*server, "");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 1; }));
  server->SendStopAndClose("pipeline switched");
  server->SendStopAndClose("again");
  EXPECT_EQ(server->PublishTarget(BigTarget()), -1);
  EXPECT_EQ(server->PublishStop("late"), -1);
  lines.clear();
  ASSERT_TRUE(ReadUntilStop(b, &lines));
  EXPECT_NE(lines.back().find("\"reason\":\"pipeline switched\""), std::string::npos);
  EXPECT_EQ(b.ReadLine(2000).status().code(), StatusCode::kUnavailable);
  EXPECT_EQ(server->Stats().sent_stops, 1);
}

// Heartbeats due at every wake of the I/O thread: the final stop is still the last line the
// client reads before the socket closes (a heartbeat queued after it would tell the arm the
// server is alive after it said goodbye).
TEST(ArmServerAttack, TheFinalStopIsTheLastLineWhileHeartbeatsAreDue) {
  ArmServerOptions o;
  o.heartbeat_s = 0.001;
  for (int round = 0; round < 20; ++round) {
    auto server = StartServer(o);
    ASSERT_TRUE(server);
    ArmClient client = Connect(*server, "");
    ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 1; }));
    ASSERT_TRUE(Is(Next(client), "heartbeat"));
    server->SendStopAndClose("quit");
    std::vector<std::string> lines;
    while (true) {
      StatusOr<std::string> line = client.ReadLine(2000);
      if (!line.ok()) {
        EXPECT_EQ(line.status().code(), StatusCode::kUnavailable) << line.status().ToString();
        break;
      }
      lines.push_back(*line);
    }
    ASSERT_FALSE(lines.empty()) << "round " << round;
    EXPECT_TRUE(Is(lines.back(), "stop")) << "round " << round << ": " << lines.back();
    EXPECT_NE(lines.back().find("\"reason\":\"quit\""), std::string::npos) << lines.back();
  }
}

TEST(ArmServerAttack, AClientThatJoinsWhileStoppedIsToldAtOnce) {
  ArmServerOptions o;
  o.heartbeat_s = 0;
  auto server = StartServer(o);
  ASSERT_TRUE(server);
  server->PublishStop("operator");
  ArmClient late = Connect(*server, "");
  std::vector<std::string> lines;
  ASSERT_TRUE(ReadUntilStop(late, &lines));
  EXPECT_EQ(lines.size(), 1u);
  server->Resume();
  ArmClient later = Connect(*server, "");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 2; }));
  server->PublishTarget(BigTarget());
  EXPECT_TRUE(Is(Next(later), "target"));
}

// The arm streams its pose at 1 kHz (five times button.arm_pose.max_rate_hz) while the operator
// presses STOP: the stop reaches the other client and the arm, and the arm is not closed.
TEST(ArmServerAttack, AnArmStreamingPosesAtOneKilohertzDelaysNoStop) {
  ArmServerOptions o;
  o.token = "s3cret";
  o.heartbeat_s = 0.05;
  o.port = 0;
  std::atomic<int64_t> sunk{0};
  auto started = ArmServer::Start(
      o, [&sunk](const ArmPoseMessage&) { ++sunk; }, ArmPoseStreamOptions{});
  ASSERT_TRUE(started.ok()) << started.status().ToString();
  std::unique_ptr<ArmServer> server = std::move(*started);
  ArmClient good = Connect(*server, "s3cret");
  ArmClient arm = Connect(*server, "s3cret");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 2; }));
  std::atomic<bool> done{false};
  std::thread streamer([&] {
    ArmPoseMessage pose;
    pose.base_from_end_effector.translation() = Eigen::Vector3d(0.4, 0.0, 0.3);
    auto next = Clock::now();
    for (int64_t k = 0; !done && k < 20000; ++k) {
      pose.stamp_s = 100.0 + 0.001 * double(k);  // 1 kHz of arm time ...
      if (!arm.Send(ArmPoseLine(pose) + "\n").ok()) return;
      next += std::chrono::milliseconds(1);  // ... sent at 1 kHz.
      std::this_thread::sleep_until(next);
    }
  });
  ASSERT_TRUE(Eventually([&] { return server->Stats().poses_over_rate > 200; }, 20));
  server->PublishTarget(BigTarget());
  const auto start = Clock::now();
  server->PublishStop("operator");
  std::vector<std::string> lines;
  const bool stopped = ReadUntilStop(good, &lines);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::vector<std::string> arm_lines;
  const bool arm_stopped = ReadUntilStop(arm, &arm_lines);
  done = true;
  streamer.join();
  EXPECT_TRUE(stopped);
  EXPECT_LT(seconds, 2.0);
  EXPECT_TRUE(arm_stopped);
  const ArmServerStats stats = server->Stats();
  EXPECT_EQ(stats.closed_for_input, 0);
  EXPECT_TRUE(stats.arm_connected);
  EXPECT_EQ(stats.poses_refused, 0) << stats.last_pose_error;
  EXPECT_EQ(stats.poses_received, sunk.load());
  EXPECT_GT(stats.poses_received, 40);
  // 1 kHz against a 200 Hz limit: about four of five are dropped.
  EXPECT_NEAR(double(stats.poses_over_rate) / double(stats.poses_received + stats.poses_over_rate),
              0.8, 0.02);
}

}  // namespace
}  // namespace sightline
