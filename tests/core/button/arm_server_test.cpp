// The arm-target protocol over real TCP on loopback: schema, token, several clients, STOP
// latency, slow and dead clients, malformed client input, and the handshake parser.
#include "core/button/arm_server.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <regex>
#include <thread>

#include "core/button/arm_client.h"
#include "core/button/server_lines.h"

namespace sightline {
namespace {

using Clock = std::chrono::steady_clock;

std::unique_ptr<ArmServer> StartServer(ArmServerOptions o = {}) {
  o.port = 0;  // Any free port: tests run in parallel.
  auto server = ArmServer::Start(o);
  EXPECT_TRUE(server.ok()) << server.status().ToString();
  return server.ok() ? std::move(*server) : nullptr;
}

ArmClient Connect(const ArmServer& server, const std::string& token = "") {
  auto client = ArmClient::Connect("127.0.0.1", server.port(), token);
  EXPECT_TRUE(client.ok()) << client.status().ToString();
  return std::move(*client);
}

// Waits until the server counts `n` authorised clients (connect and handshake are async).
bool WaitForClients(const ArmServer& server, int n) {
  const auto deadline = Clock::now() + std::chrono::seconds(5);
  while (Clock::now() < deadline) {
    if (server.Stats().authorised == n) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return false;
}

// The next line that is not a heartbeat, or "" on timeout.
std::string NextMessage(ArmClient& client, int timeout_ms = 2000) {
  while (true) {
    auto line = client.ReadLine(timeout_ms);
    if (!line.ok()) return "";
    if (line->find("\"type\":\"heartbeat\"") == std::string::npos) return *line;
  }
}

ArmTarget Target() {
  ArmTarget t;
  t.stamp_s = 12.5;
  t.position_m = {0.512, -0.031, 0.318};
  t.approach = {1, 0, 0};
  t.uncertainty_m = 0.0021;
  t.approach_sigma_deg = 1.5;
  t.source_frames = {41, 42};
  return t;
}

TEST(ArmServer, AClientReceivesTargetsWithTheSchema) {
  auto server = StartServer();
  ASSERT_TRUE(server);
  ArmClient client = Connect(*server);
  ASSERT_TRUE(WaitForClients(*server, 1));
  const int64_t seq = server->PublishTarget(Target());
  const std::string line = NextMessage(client);
  ASSERT_FALSE(line.empty());
  const std::regex schema(
      R"(\{"version":2,"type":"target","seq":(\d+),"stamp":\d{10}\.\d{6},"frame_stamp":12\.500000,)"
      R"("frame_id":"arm_base","position_m":\[0\.512,-0\.031,0\.318\],"approach":\[1,0,0\],)"
      R"("uncertainty_m":0\.0021,"approach_sigma_deg":1\.5,"source_frames":\[41,42\]\})");
  std::smatch m;
  ASSERT_TRUE(std::regex_match(line, m, schema)) << line;
  EXPECT_EQ(std::stoll(m[1]), seq);
}

TEST(ArmServer, HeartbeatsArrive) {
  ArmServerOptions o;
  o.heartbeat_s = 0.02;
  auto server = StartServer(o);
  ArmClient client = Connect(*server);
  auto line = client.ReadLine(2000);
  ASSERT_TRUE(line.ok()) << line.status().ToString();
  EXPECT_NE(line->find(R"("version":2,"type":"heartbeat")"), std::string::npos) << *line;
  EXPECT_NE(line->find(R"("targets_enabled":true)"), std::string::npos) << *line;
}

TEST(ArmServer, WithoutTheTokenAClientReceivesNothing) {
  ArmServerOptions o;
  o.token = "s3cret";
  o.heartbeat_s = 0.01;
  auto server = StartServer(o);
  ArmClient good = Connect(*server, "s3cret");
  ArmClient wrong = Connect(*server, "guess");
  ArmClient silent = Connect(*server);
  ASSERT_TRUE(WaitForClients(*server, 1));
  server->PublishTarget(Target());
  EXPECT_NE(NextMessage(good).find("\"type\":\"target\""), std::string::npos);
  server->PublishStop("test");
  EXPECT_NE(NextMessage(good).find("\"type\":\"stop\""), std::string::npos);
  // Heartbeats every 10 ms would have arrived by now; neither client gets a single byte: the
  // wrong token is closed, the silent one waits for its handshake deadline (2 s).
  EXPECT_EQ(wrong.ReadLine(2000).status().code(), StatusCode::kUnavailable);
  EXPECT_EQ(silent.ReadLine(50).status().code(), StatusCode::kOutOfRange);
  EXPECT_EQ(server->Stats().authorised, 1);
  EXPECT_EQ(server->Stats().token_failures, 1);
}

TEST(ArmServer, SeveralClientsEachReceiveEverything) {
  auto server = StartServer();
  std::vector<ArmClient> clients;
  for (int i = 0; i < 4; ++i) clients.push_back(Connect(*server));
  ASSERT_TRUE(WaitForClients(*server, 4));
  for (int k = 0; k < 5; ++k) server->PublishTarget(Target());
  for (ArmClient& c : clients) {
    for (int k = 0; k < 5; ++k)
      EXPECT_NE(NextMessage(c).find("\"type\":\"target\""), std::string::npos);
  }
}

TEST(ArmServer, StopReachesTheClientWithinFiftyMilliseconds) {
  ArmServerOptions o;
  o.heartbeat_s = 0;  // Only the stop is on the wire.
  auto server = StartServer(o);
  ArmClient client = Connect(*server);
  ASSERT_TRUE(WaitForClients(*server, 1));
  const auto start = Clock::now();
  server->PublishStop("operator");
  auto line = client.ReadLine(1000);
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  ASSERT_TRUE(line.ok()) << line.status().ToString();
  EXPECT_NE(line->find(R"("type":"stop")"), std::string::npos);
  EXPECT_NE(line->find(R"("reason":"operator")"), std::string::npos);
  EXPECT_LT(ms, 50.0);
}

TEST(ArmServer, StopSuppressesTargetsUntilResume) {
  ArmServerOptions o;
  o.heartbeat_s = 0;
  auto server = StartServer(o);
  ArmClient client = Connect(*server);
  ASSERT_TRUE(WaitForClients(*server, 1));
  server->PublishStop("operator");
  EXPECT_EQ(server->PublishTarget(Target()), -1);
  EXPECT_NE(NextMessage(client).find("\"type\":\"stop\""), std::string::npos);
  EXPECT_EQ(client.ReadLine(100).status().code(), StatusCode::kOutOfRange);
  server->Resume();
  EXPECT_GE(server->PublishTarget(Target()), 0);
  EXPECT_NE(NextMessage(client).find("\"type\":\"target\""), std::string::npos);
  EXPECT_EQ(server->Stats().suppressed, 1);
}

TEST(ArmServer, ATargetTheArmWouldRefuseNeverGoesOut) {
  ArmServerOptions o;
  o.heartbeat_s = 0;
  auto server = StartServer(o);
  ArmClient client = Connect(*server);
  ASSERT_TRUE(WaitForClients(*server, 1));
  ArmTarget zero = Target();
  zero.approach.setZero();
  ArmTarget tiny = Target();
  tiny.approach = {1e-200, 0, 0};
  ArmTarget nan = Target();
  nan.position_m.y() = std::nan("");
  for (const ArmTarget& bad : {zero, tiny, nan}) EXPECT_EQ(server->PublishTarget(bad), -1);
  EXPECT_EQ(client.ReadLine(100).status().code(), StatusCode::kOutOfRange);
  EXPECT_GE(server->PublishTarget(Target()), 0);
  const std::string line = NextMessage(client);
  EXPECT_NE(line.find("\"type\":\"target\""), std::string::npos);
  StatusOr<ServerLine> parsed = ParseServerLine(line);
  ASSERT_TRUE(parsed.ok()) << parsed.status().message();
  EXPECT_EQ(server->Stats().malformed, 3);
  EXPECT_EQ(server->Stats().targets, 1);
}

TEST(ArmServer, ADeadClientDoesNotStallPublishingOrOthers) {
  ArmServerOptions o;
  o.heartbeat_s = 0;
  o.queue_messages = 8;
  auto server = StartServer(o);
  ArmClient dead = Connect(*server);  // Never reads.
  ArmClient live = Connect(*server);
  ASSERT_TRUE(WaitForClients(*server, 2));
  ArmTarget big = Target();
  big.source_frames.assign(20000, 7);  // ~40 kB per line fills the dead client's socket fast.
  const auto start = Clock::now();
  int received = 0;
  double slowest_publish_ms = 0;
  for (int k = 0; k < 400; ++k) {
    const auto before = Clock::now();
    server->PublishTarget(big);
    slowest_publish_ms =
        std::max(slowest_publish_ms,
                 std::chrono::duration<double, std::milli>(Clock::now() - before).count());
    while (true) {  // The live client keeps up.
      auto line = live.ReadLine(0);
      if (!line.ok()) break;
      ++received;
    }
  }
  const double publish_s = std::chrono::duration<double>(Clock::now() - start).count();
  server->PublishStop("operator");
  // The stop still reaches the live client past the backlog.
  std::string last;
  while (true) {
    auto line = live.ReadLine(1000);
    if (!line.ok()) break;
    last = *line;
    if (last.find("\"type\":\"stop\"") != std::string::npos) break;
  }
  EXPECT_NE(last.find("\"type\":\"stop\""), std::string::npos);
  EXPECT_GT(server->Stats().dropped, 0);  // The dead client's queue overflowed.
  EXPECT_GT(received, 100);
  // Publishing never waits for the dead peer (functional bounds with a wide margin: a blocked
  // publish would wait forever).
  EXPECT_LT(slowest_publish_ms, 500.0);
  EXPECT_LT(publish_s, 30.0);
}

TEST(ArmServer, AMalformedTokenLineClosesTheConnection) {
  ArmServerOptions o;
  o.token = "tok";
  o.heartbeat_s = 0;
  o.max_line_bytes = 64;
  auto server = StartServer(o);
  const std::vector<std::string> attempts = {"not json\n", "{\"token\": 5}\n",
                                             "{\"token\":\"tok\"\n", std::string(5000, 'x'),
                                             std::string("\0\xff\n", 3)};
  for (const std::string& bytes : attempts) {
    auto raw = ArmClient::Connect("127.0.0.1", server->port(), "");
    ASSERT_TRUE(raw.ok());
    ASSERT_TRUE(raw->Send(bytes).ok());
    EXPECT_EQ(raw->ReadLine(2000).status().code(), StatusCode::kUnavailable) << bytes.size();
  }
  EXPECT_EQ(server->Stats().token_failures, int64_t(attempts.size()));
  EXPECT_EQ(server->Stats().authorised, 0);
}

TEST(ArmServer, ClientInputAfterTheHandshakeIsIgnored) {
  ArmServerOptions o;
  o.token = "tok";
  o.heartbeat_s = 0;
  o.max_line_bytes = 64;
  auto server = StartServer(o);
  auto raw = ArmClient::Connect("127.0.0.1", server->port(), "");
  ASSERT_TRUE(raw.ok());
  ASSERT_TRUE(raw->Send("{\"token\": \"tok\", \"client\": \"arm\"}\n").ok());
  ASSERT_TRUE(WaitForClients(*server, 1));
  ASSERT_TRUE(raw->Send("{\"garbage\n\n\n" + std::string(200, 'y') + "\n").ok());
  server->PublishTarget(Target());
  EXPECT_NE(NextMessage(*raw).find("\"type\":\"target\""), std::string::npos);
  // A client that connects and disconnects at once does no harm.
  { auto gone = ArmClient::Connect("127.0.0.1", server->port(), ""); }
  server->PublishTarget(Target());
  EXPECT_NE(NextMessage(*raw).find("\"type\":\"target\""), std::string::npos);
  EXPECT_EQ(server->Stats().ignored_lines, 4);
}

TEST(ArmServer, OptionsAndBindingErrors) {
  ArmServerOptions o;
  EXPECT_EQ(o.bind_address, "127.0.0.1");  // Loopback only by default.
  o.bind_address = "not-an-ip";
  std::string error;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("bind_address"), std::string::npos);
  EXPECT_EQ(ArmServer::Start(o).status().code(), StatusCode::kInvalidArgument);
  auto first = StartServer();
  ArmServerOptions same;
  same.port = first->port();
  auto second = ArmServer::Start(same);
  ASSERT_FALSE(second.ok());
  EXPECT_EQ(second.status().code(), StatusCode::kUnavailable);
  EXPECT_NE(second.status().message().find(std::to_string(first->port())), std::string::npos);
}

TEST(ArmProtocol, ParsesOnlyAValidTokenLine) {
  EXPECT_EQ(ParseTokenLine(R"({"token": "abc"})").value_or("?"), "abc");
  EXPECT_EQ(ParseTokenLine(R"( {"client":"x","token":"a\"b","n":3} )").value_or("?"), "a\"b");
  EXPECT_FALSE(ParseTokenLine(R"({"token": 3})"));
  EXPECT_FALSE(ParseTokenLine(R"({"token": "abc")"));
  EXPECT_FALSE(ParseTokenLine(R"({"token": "abc"} trailing)"));
  EXPECT_FALSE(ParseTokenLine(R"({"other": "abc"})"));
  EXPECT_FALSE(ParseTokenLine(""));
  EXPECT_FALSE(ParseTokenLine("[1,2]"));
  EXPECT_EQ(StopLine(3, 1.5, "operator"),
            "{\"version\":2,\"type\":\"stop\",\"seq\":3,\"stamp\":1.500000,"
            "\"reason\":\"operator\"}\n");
}

TEST(ArmProtocol, StampsHaveMicroseconds) {
  const std::string stop = StopLine(0, 1763805600.123456, "x");
  EXPECT_NE(stop.find("\"stamp\":1763805600.123456,"), std::string::npos) << stop;
  ArmTarget t;
  t.stamp_s = 12.000042;
  const std::string target = TargetLine(1, 1763805600.5, t);
  EXPECT_NE(target.find("\"stamp\":1763805600.500000,"), std::string::npos) << target;
  EXPECT_NE(target.find("\"frame_stamp\":12.000042,"), std::string::npos) << target;
}

TEST(ArmProtocol, TokensMatchOnlyWhenEqual) {
  EXPECT_TRUE(TokensMatch("s3cret", "s3cret"));
  EXPECT_FALSE(TokensMatch("s3cre", "s3cret"));
  EXPECT_FALSE(TokensMatch("s3crett", "s3cret"));
  EXPECT_FALSE(TokensMatch("S3cret", "s3cret"));
  EXPECT_FALSE(TokensMatch("", "s3cret"));
  EXPECT_FALSE(TokensMatch(std::string("s3cret\0", 7), "s3cret"));
}

TEST(ArmClient, ParsesAddresses) {
  std::string host;
  int port = 0;
  EXPECT_TRUE(ArmClient::ParseAddress("127.0.0.1:5757", &host, &port).ok());
  EXPECT_EQ(host, "127.0.0.1");
  EXPECT_EQ(port, 5757);
  EXPECT_FALSE(ArmClient::ParseAddress("localhost", &host, &port).ok());
  EXPECT_FALSE(ArmClient::ParseAddress("h:99999", &host, &port).ok());
  EXPECT_EQ(ArmClient::Connect("127.0.0.1", 1, "").status().code(), StatusCode::kUnavailable);
}

}  // namespace
}  // namespace sightline
