// The arm's pose stream over real TCP on loopback: the authenticated arm client's arm_pose lines
// reach the sink in order and exactly as sent (well past the closing budget of other chatter);
// poses before the token, from a second client, malformed, out of order or above the rate are
// refused or dropped and counted, the refusal naming the member; the arm's role passes on when
// it disconnects.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <mutex>
#include <thread>

#include "core/button/arm_client.h"
#include "core/button/arm_server.h"

namespace sightline {
namespace {

using Clock = std::chrono::steady_clock;

// What the sink received.
struct Received {
  std::mutex mutex;
  std::vector<ArmPoseMessage> poses;

  ArmPoseSink Sink() {
    return [this](const ArmPoseMessage& pose) {
      std::lock_guard<std::mutex> lock(mutex);
      poses.push_back(pose);
    };
  }
  size_t size() {
    std::lock_guard<std::mutex> lock(mutex);
    return poses.size();
  }
};

std::unique_ptr<ArmServer> StartServer(ArmServerOptions o, ArmPoseSink sink,
                                       ArmPoseStreamOptions pose_options = {}) {
  o.port = 0;
  auto server = ArmServer::Start(o, std::move(sink), pose_options);
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

// A pose on a known path: stamp t, position and a rotation about z that change with t.
ArmPoseMessage PoseAt(double t) {
  ArmPoseMessage m;
  m.stamp_s = t;
  m.base_from_end_effector = Eigen::Translation3d(0.4 + 0.1 * t, -0.2 * t, 0.3) *
                             Eigen::AngleAxisd(0.5 * t, Eigen::Vector3d::UnitZ());
  m.joints = {0.1 * t, 0.2};
  return m;
}

std::string Line(double t) { return ArmPoseLine(PoseAt(t)) + "\n"; }

TEST(ArmServerPoses, TheAuthenticatedArmsPosesReachTheSinkInOrderPastTheChatterBudget) {
  Received received;
  ArmServerOptions o;
  o.token = "s3cret";
  o.heartbeat_s = 0.05;
  auto server = StartServer(o, received.Sink());
  ASSERT_TRUE(server);
  ArmClient arm = Connect(*server, "s3cret");
  // 2000 poses at 200 Hz of arm time, sent in bursts: about 300 kB, far over the 16 x 1024
  // bytes an authorised client may send otherwise.
  const int kPoses = 2000;
  std::string burst;
  size_t bytes = 0;
  for (int i = 0; i < kPoses; ++i) {
    burst += Line(10.0 + i * 0.005);
    if (burst.size() > 8000 || i == kPoses - 1) {
      ASSERT_TRUE(arm.Send(burst).ok()) << "after " << i << " poses";
      bytes += burst.size();
      burst.clear();
    }
  }
  EXPECT_GT(bytes, size_t(16 * 1024 * 10));
  ASSERT_TRUE(Eventually([&] { return received.size() == size_t(kPoses); }))
      << received.size() << " of " << kPoses << "; over rate " << server->Stats().poses_over_rate
      << ", refused " << server->Stats().poses_refused << ": " << server->Stats().last_pose_error;
  const ArmServerStats stats = server->Stats();
  EXPECT_EQ(stats.poses_received, kPoses);
  EXPECT_EQ(stats.poses_refused, 0) << stats.last_pose_error;
  EXPECT_EQ(stats.poses_over_rate, 0);
  EXPECT_EQ(stats.closed_for_input, 0);
  EXPECT_EQ(stats.ignored_lines, 0);
  EXPECT_TRUE(stats.arm_connected);
  std::lock_guard<std::mutex> lock(received.mutex);
  for (int i = 0; i < kPoses; ++i) {
    const ArmPoseMessage truth = PoseAt(10.0 + i * 0.005);
    const ArmPoseMessage& got = received.poses[size_t(i)];
    ASSERT_NEAR(got.stamp_s, truth.stamp_s, 1e-6) << i;
    EXPECT_LT(
        (got.base_from_end_effector.translation() - truth.base_from_end_effector.translation())
            .norm(),
        1e-8)
        << i;
    EXPECT_LT(Eigen::AngleAxisd(got.base_from_end_effector.linear().transpose() *
                                truth.base_from_end_effector.linear())
                  .angle(),
              1e-7)
        << i;
    ASSERT_EQ(got.joints.size(), 2u);
  }
  // The arm is still served: heartbeats keep coming.
  StatusOr<std::string> line = arm.ReadLine(2000);
  ASSERT_TRUE(line.ok()) << line.status().ToString();
  EXPECT_NE(line->find("heartbeat"), std::string::npos);
}

TEST(ArmServerPoses, RefusedPosesAreCountedNamingTheMember) {
  Received received;
  ArmServerOptions o;
  o.token = "s3cret";
  ArmPoseStreamOptions limits;
  limits.max_rate_hz = 200;
  auto server = StartServer(o, received.Sink(), limits);
  ASSERT_TRUE(server);
  // Before the token: the connection's one attempt fails, the pose is refused.
  ArmClient early = Connect(*server, "");
  ASSERT_TRUE(early.Send(Line(1.0)).ok());
  EXPECT_EQ(early.ReadLine(2000).status().code(), StatusCode::kUnavailable);
  ASSERT_TRUE(Eventually([&] { return server->Stats().poses_refused == 1; }));
  EXPECT_EQ(server->Stats().token_failures, 1);
  EXPECT_NE(server->Stats().last_pose_error.find("token"), std::string::npos);
  // The first authorised client that sends a valid pose is the arm.
  ArmClient arm = Connect(*server, "s3cret");
  ArmClient other = Connect(*server, "s3cret");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 2; }));
  ASSERT_TRUE(arm.Send(Line(2.0)).ok());
  ASSERT_TRUE(Eventually([&] { return server->Stats().poses_received == 1; }));
  EXPECT_TRUE(server->Stats().arm_connected);
  // A second client's pose: refused.
  ASSERT_TRUE(other.Send(Line(2.5)).ok());
  ASSERT_TRUE(Eventually([&] { return server->Stats().poses_refused == 2; }));
  EXPECT_NE(server->Stats().last_pose_error.find("another client is the arm"), std::string::npos);
  // The arm's malformed, out-of-order and over-rate poses.
  const std::vector<std::pair<std::string, std::string>> refused = {
      {R"({"type":"arm_pose","stamp":3,"position_m":[0,0],"quaternion_xyzw":[0,0,0,1]})",
       "position_m"},
      {R"({"type":"arm_pose","stamp":3,"position_m":[0,0,0],"quaternion_xyzw":[0,0,2,1]})",
       "quaternion_xyzw"},
      {R"({"type":"arm_pose","position_m":[0,0,0],"quaternion_xyzw":[0,0,0,1]})", "stamp"},
      {ArmPoseLine(PoseAt(1.5)), "stamp"},  // Before the arm's previous pose.
  };
  int64_t count = 2;
  for (const auto& [line, member] : refused) {
    ASSERT_TRUE(arm.Send(line + "\n").ok());
    ++count;
    ASSERT_TRUE(Eventually([&] { return server->Stats().poses_refused == count; })) << line;
    EXPECT_NE(server->Stats().last_pose_error.find(member), std::string::npos)
        << server->Stats().last_pose_error << " for " << line;
  }
  ASSERT_TRUE(arm.Send(Line(2.001) + Line(2.004) + Line(2.006)).ok());  // 1/200 s: 2.005.
  ASSERT_TRUE(Eventually([&] { return server->Stats().poses_received == 2; }));
  EXPECT_EQ(server->Stats().poses_over_rate, 2);
  EXPECT_EQ(server->Stats().poses_refused, count);
  // Lines that are no pose are ignored as before.
  ASSERT_TRUE(arm.Send("{\"hello\": 1}\n").ok());
  ASSERT_TRUE(Eventually([&] { return server->Stats().ignored_lines == 1; }));
  // When the arm leaves, the next client to send a pose is the arm.
  arm.Close();
  ASSERT_TRUE(Eventually([&] { return !server->Stats().arm_connected; }));
  ASSERT_TRUE(other.Send(Line(3.0)).ok());
  ASSERT_TRUE(Eventually([&] { return server->Stats().poses_received == 3; }));
  EXPECT_TRUE(server->Stats().arm_connected);
  std::lock_guard<std::mutex> lock(received.mutex);
  ASSERT_EQ(received.poses.size(), 3u);
  EXPECT_DOUBLE_EQ(received.poses[0].stamp_s, 2.0);
  EXPECT_DOUBLE_EQ(received.poses[1].stamp_s, 2.006);
  EXPECT_DOUBLE_EQ(received.poses[2].stamp_s, 3.0);
}

TEST(ArmServerPoses, WithoutASinkEveryPoseIsRefused) {
  auto server = StartServer({}, nullptr);
  ASSERT_TRUE(server);
  ArmClient client = Connect(*server, "");
  ASSERT_TRUE(client.Send(Line(1.0)).ok());
  ASSERT_TRUE(Eventually([&] { return server->Stats().poses_refused == 1; }));
  EXPECT_NE(server->Stats().last_pose_error.find("takes no arm poses"), std::string::npos);
  EXPECT_EQ(server->Stats().poses_received, 0);
  EXPECT_FALSE(server->Stats().arm_connected);
}

TEST(ArmServerPoses, MalformedPosesStillCountTowardTheClosingBudget) {
  Received received;
  ArmServerOptions o;
  o.max_line_bytes = 256;
  auto server = StartServer(o, received.Sink());
  ASSERT_TRUE(server);
  ArmClient client = Connect(*server, "");
  ASSERT_TRUE(Eventually([&] { return server->Stats().authorised == 1; }));
  const std::string bad =
      R"({"type":"arm_pose","stamp":1,"position_m":[0,0],"quaternion_xyzw":[0,0,0,1]})"
      "\n";
  std::string lines;
  while (lines.size() < 16 * 256 + 512) lines += bad;
  (void)client.Send(lines);  // May fail once the server has closed it.
  EXPECT_EQ(client.ReadLine(5000).status().code(), StatusCode::kUnavailable);
  EXPECT_EQ(server->Stats().closed_for_input, 1);
  EXPECT_GT(server->Stats().poses_refused, 0);
  EXPECT_EQ(received.size(), 0u);
}

}  // namespace
}  // namespace sightline
