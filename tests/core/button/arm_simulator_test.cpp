// The simulated arm (core/button/arm_simulator.h): the server lines it reads, its plan in the
// panel scene, following a target to a standoff and onto the button at a bounded speed, STOP,
// a silent link and malformed lines, driven step by step; then the session over real TCP
// against the arm-target server, which takes the pose stream.
#include "core/button/arm_simulator.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <thread>

#include "core/button/arm_pose_stream.h"
#include "core/button/arm_server.h"
#include "core/button/arm_sim_session.h"
#include "core/button/server_lines.h"

namespace sightline {
namespace {

constexpr double kDeg = M_PI / 180;

ArmSimOptions FastOptions() {
  ArmSimOptions o;
  o.hold_s = 0.2;
  o.plan_s = 2;
  o.max_speed_mps = 0.1;
  o.max_angular_speed_dps = 30;
  return o;
}

ArmSimWorld World(const ArmSimOptions& o = FastOptions(), int seed = 4) {
  StatusOr<ArmSimWorld> world = BuildArmSimWorld(seed, o);
  EXPECT_TRUE(world.ok()) << world.status().ToString();
  return std::move(*world);
}

// A target on the true centre of `button`, pushing against its normal.
ArmTarget TrueTarget(const ArmSimWorld& world, int button) {
  ArmTarget t;
  const ArmSimButton* b = world.FindButton(button);
  EXPECT_NE(b, nullptr);
  t.position_m = b->center;
  t.approach = -b->normal;
  t.stamp_s = 1;
  return t;
}

// Steps the arm every control period from `*t` for `seconds`; with `heartbeats`, the server's
// heartbeat arrives every 0.25 s.
void Drive(ArmSimulator* arm, double* t, double seconds, bool heartbeats = true) {
  const double period = arm->options().control_period_s;
  int64_t seq = 0;
  double next_heartbeat = *t;
  for (double end = *t + seconds; *t < end; *t += period) {
    if (heartbeats && *t >= next_heartbeat) {
      arm->OnLine(HeartbeatLine(seq++, *t, !arm->stopped()), *t);
      next_heartbeat += 0.25;
    }
    arm->Step(*t);
  }
}

TEST(ServerLines, ReadsEveryMessageTheServerWrites) {
  ArmTarget target;
  target.stamp_s = 12.5;
  target.position_m = {0.5, -0.03, 0.3};
  target.approach = {0, 0, 2};  // Normalised by the reader... after the writer's own output.
  target.approach = target.approach.normalized();
  target.uncertainty_m = 0.002;
  target.source_frames = {41, 42};
  StatusOr<ServerLine> t = ParseServerLine(TargetLine(7, 100.25, target));
  ASSERT_TRUE(t.ok()) << t.status().ToString();
  EXPECT_EQ(t->type, ServerLine::Type::kTarget);
  EXPECT_EQ(t->seq, 7);
  EXPECT_NEAR(t->stamp_s, 100.25, 1e-6);
  EXPECT_NEAR((t->target.position_m - target.position_m).norm(), 0, 1e-9);
  EXPECT_NEAR((t->target.approach - target.approach).norm(), 0, 1e-9);
  EXPECT_EQ(t->target.source_frames, target.source_frames);
  StatusOr<ServerLine> h = ParseServerLine(HeartbeatLine(8, 101, false));
  ASSERT_TRUE(h.ok()) << h.status().ToString();
  EXPECT_EQ(h->type, ServerLine::Type::kHeartbeat);
  EXPECT_FALSE(h->targets_enabled);
  StatusOr<ServerLine> s = ParseServerLine(StopLine(9, 102, "operator \"now\""));
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_EQ(s->type, ServerLine::Type::kStop);
  EXPECT_EQ(s->reason, "operator \"now\"");
}

TEST(ServerLines, NamesWhatIsWrongWithABadLine) {
  const std::pair<const char*, const char*> cases[] = {
      {"", "not a JSON object"},
      {"garbage", "not a JSON object"},
      {R"({"version":2,"type":"target","seq":1,"stamp":1})", "frame_stamp"},
      {R"({"version":3,"type":"stop","seq":1,"stamp":1})", "version"},
      {R"({"version":2,"type":"dance","seq":1,"stamp":1})", "unknown \"type\""},
      {R"({"version":2,"type":"heartbeat","seq":1,"stamp":1})", "targets_enabled"},
      {R"({"version":2,"type":"stop","seq":1,"stamp":1} x)", "text after"},
      {R"({"version":2,"version":2,"type":"stop","seq":1,"stamp":1})", "duplicate"},
      {R"({"version":2,"type":"target","seq":1,"stamp":1,"frame_stamp":1,"frame_id":"arm_base",)"
       R"("position_m":[1,2],"approach":[1,0,0]})",
       "position_m"},
      {R"({"version":2,"type":"target","seq":1,"stamp":1,"frame_stamp":1,"frame_id":"arm_base",)"
       R"("position_m":[1,2,3],"approach":[0,0,0]})",
       "approach"},
      {R"({"version":2,"type":"stop","seq":1,"stamp":1e999})", "stamp"},
  };
  for (const auto& [line, what] : cases) {
    StatusOr<ServerLine> parsed = ParseServerLine(line);
    ASSERT_FALSE(parsed.ok()) << line;
    EXPECT_NE(parsed.status().message().find(what), std::string::npos)
        << line << " -> " << parsed.status().message();
  }
}

TEST(ArmSimWorld, ThePlanStartsLookingAtItsButtonFromTheStartDistance) {
  const ArmSimOptions o = FastOptions();
  const ArmSimWorld world = World(o);
  ASSERT_EQ(world.buttons.size(), 12u);
  const ArmSimButton* b = world.FindButton(world.plan_button);
  ASSERT_NE(b, nullptr);
  const Eigen::Isometry3d camera = world.PlanPose(0) * world.end_effector_from_camera;
  const Eigen::Vector3d in_camera = camera.inverse() * b->center;
  EXPECT_NEAR(in_camera.z(), o.start_distance_m, 1e-9);
  EXPECT_NEAR(in_camera.head<2>().norm(), 0, 1e-9);
  const Eigen::Isometry3d end = world.PlanPose(o.plan_s) * world.end_effector_from_camera;
  EXPECT_NEAR((end.inverse() * b->center).z(), o.approach_end_m, 1e-9);
  // The tool axis points into the panel, as the target's approach does.
  EXPECT_NEAR(world.PlanPose(0).linear().col(2).dot(-b->normal), 1, 1e-9);
  EXPECT_LT((world.PlanPose(0).linear() - ToolOrientation(-b->normal)).norm(), 1e-9);
}

TEST(ArmSimulator, FliesThePlanThenPressesTheTargetAtABoundedSpeed) {
  const ArmSimOptions o = FastOptions();
  ArmSimulator arm(o, World(o));
  const ArmTarget target = TrueTarget(arm.world(), 3);
  double t = 1000;
  arm.Start(t);
  EXPECT_EQ(arm.phase(), ArmSimPhase::kHold);
  Drive(&arm, &t, 0.1);
  EXPECT_EQ(arm.phase(), ArmSimPhase::kHold);
  arm.OnLine(TargetLine(0, t, target), t);  // During the plan: followed once it is done.
  Drive(&arm, &t, 0.5);
  EXPECT_EQ(arm.phase(), ArmSimPhase::kSideways);
  Drive(&arm, &t, 1.2);
  EXPECT_EQ(arm.phase(), ArmSimPhase::kApproach);
  for (int i = 0; i < 3000 && !arm.Finished(t); ++i) Drive(&arm, &t, 0.05);
  ASSERT_TRUE(arm.Finished(t));
  const ArmSimOutcome out = arm.Outcome();
  EXPECT_EQ(out.nearest_button, 3);
  EXPECT_LT(out.distance_mm, 0.1);
  EXPECT_LT(out.approach_error_deg, 0.1);
  // Never faster than the limit after the plan; it passed the standoff point.
  bool at_standoff = false;
  const Eigen::Vector3d standoff = target.position_m - o.standoff_m * target.approach;
  double following = 0;
  for (const ArmSimEvent& e : arm.events()) {
    if (e.what.rfind("moving to the standoff", 0) == 0 && following == 0) following = e.time_s;
  }
  ASSERT_GT(following, 0);
  for (size_t i = 1; i < arm.steps().size(); ++i) {
    if (arm.steps()[i - 1].time_s < following) continue;
    const double step = (arm.steps()[i].position - arm.steps()[i - 1].position).norm();
    EXPECT_LE(step, o.max_speed_mps * o.control_period_s * 1.0001) << i;
    at_standoff = at_standoff || (arm.steps()[i].position - standoff).norm() < 1e-6;
  }
  EXPECT_TRUE(at_standoff);
  bool logged_reached = false;
  for (const ArmSimEvent& e : arm.events()) logged_reached |= e.what.rfind("reached", 0) == 0;
  EXPECT_TRUE(logged_reached);
}

TEST(ArmSimulator, AStopFreezesTheArmUntilANewTarget) {
  const ArmSimOptions o = FastOptions();
  ArmSimulator arm(o, World(o));
  double t = 0;
  arm.Start(t);
  arm.OnLine(TargetLine(0, t, TrueTarget(arm.world(), 8)), t);
  Drive(&arm, &t, o.hold_s + o.plan_s + 0.3);
  ASSERT_EQ(arm.phase(), ArmSimPhase::kToStandoff);
  arm.OnLine(StopLine(1, t, "operator"), t);
  const Eigen::Vector3d frozen = arm.pose().translation();
  for (int i = 0; i < 40; ++i) {
    Drive(&arm, &t, 0.05);
    EXPECT_EQ(arm.pose().translation(), frozen);
  }
  EXPECT_TRUE(arm.stopped());
  EXPECT_FALSE(arm.Finished(t));
  arm.OnLine(TargetLine(50, t, TrueTarget(arm.world(), 8)), t);  // The operator started again.
  Drive(&arm, &t, 0.1);
  EXPECT_FALSE(arm.stopped());
  EXPECT_NE(arm.pose().translation(), frozen);
}

TEST(ArmSimulator, HoldsWhenTheLinkIsSilentAndGoesOnWhenItSpeaks) {
  const ArmSimOptions o = FastOptions();
  ArmSimulator arm(o, World(o));
  double t = 0;
  arm.Start(t);
  Drive(&arm, &t, o.hold_s + 0.2, false);  // Sideways: moving.
  Drive(&arm, &t, 3 * o.heartbeat_s, false);
  ASSERT_TRUE(arm.holding());
  const Eigen::Vector3d held = arm.pose().translation();
  Drive(&arm, &t, 1, false);
  EXPECT_EQ(arm.pose().translation(), held);
  arm.OnLine(HeartbeatLine(0, t, true), t);
  Drive(&arm, &t, 0.1);
  EXPECT_FALSE(arm.holding());
  EXPECT_NE(arm.pose().translation(), held);
}

TEST(ArmSimulator, CountsAndNamesMalformedLinesWithoutActingOnThem) {
  const ArmSimOptions o = FastOptions();
  ArmSimulator arm(o, World(o));
  double t = 0;
  arm.Start(t);
  ArmTarget wrong_frame = TrueTarget(arm.world(), 2);
  wrong_frame.frame_id = "map";
  const std::string lines[] = {"",
                               "{",
                               "\x01\x02\xff",
                               std::string(5000, '['),
                               R"({"version":2,"type":"stop","seq":1})",
                               TargetLine(3, t, wrong_frame)};
  for (const std::string& line : lines) arm.OnLine(line, t);
  EXPECT_EQ(arm.counts().at("malformed"), 6);
  EXPECT_FALSE(arm.stopped());
  EXPECT_FALSE(arm.target().has_value());
  int64_t named = 0;
  for (const auto& [reason, count] : arm.malformed()) {
    EXPECT_EQ(reason.rfind("server line: ", 0), 0u) << reason;
    named += count;
  }
  EXPECT_EQ(named, 6);
  EXPECT_TRUE(arm.malformed().count("server line: \"stamp\" must be a finite number"));
  EXPECT_TRUE(arm.malformed().count("server line: \"frame_id\" 'map' is not arm_base"));
}

// The session over real TCP: the arm connects with the token, streams its pose, presses the
// published target; a second arm is stopped on its way and moves no more after the stop line.
class ArmSimSession : public ::testing::Test {
 protected:
  void SetUp() override {
    ArmServerOptions so;
    so.port = 0;
    so.token = "secret";
    StatusOr<std::unique_ptr<ArmServer>> server =
        ArmServer::Start(so, [this](const ArmPoseMessage& pose) { last_pose_s_ = pose.stamp_s; });
    ASSERT_TRUE(server.ok()) << server.status().ToString();
    server_ = std::move(*server);
  }
  bool WaitForArm() {
    for (int i = 0; i < 5000 && server_->Stats().authorised < 1; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return server_->Stats().authorised == 1;
  }
  std::unique_ptr<ArmServer> server_;
  std::atomic<double> last_pose_s_{0};
};

TEST_F(ArmSimSession, PressesThePublishedTargetOverTcp) {
  const ArmSimOptions o = FastOptions();
  ArmSimulator arm(o, World(o));
  const ArmTarget target = TrueTarget(arm.world(), 5);
  StatusOr<ArmSimSessionResult> result = Unavailable("not run");
  std::thread session(
      [&] { result = RunArmSimSession("127.0.0.1", server_->port(), "secret", &arm); });
  ASSERT_TRUE(WaitForArm());
  server_->PublishTarget(target);
  session.join();
  ASSERT_TRUE(result.ok()) << result.status().ToString();
  EXPECT_EQ(result->end_reason, "finished");
  EXPECT_GT(result->poses_sent, 100);
  // The server took the stream: every pose, none refused (wall-clock stamps, in order). The
  // server reads the last lines after the arm has hung up: wait for them (bounded).
  const auto taken = [&] {
    const auto stats = server_->Stats();
    return stats.poses_received + stats.poses_over_rate;
  };
  for (int i = 0; i < 2500 && taken() < result->poses_sent; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  EXPECT_EQ(taken(), result->poses_sent);
  EXPECT_EQ(server_->Stats().poses_refused, 0) << server_->Stats().last_pose_error;
  EXPECT_NEAR(last_pose_s_.load(), WallClockS(), 60);
  EXPECT_EQ(result->outcome.nearest_button, 5);
  EXPECT_LT(result->outcome.distance_mm, 0.1);
  EXPECT_LT(result->outcome.approach_error_deg, 0.1);
  EXPECT_EQ(arm.counts().count("malformed"), 0u);
  EXPECT_GE(arm.counts().at("targets"), 1);
}

TEST_F(ArmSimSession, NothingMovesAfterTheStopLineArrived) {
  ArmSimOptions o = FastOptions();
  o.max_speed_mps = 0.02;  // Slow: the stop comes while it moves to the standoff.
  ArmSimulator arm(o, World(o));
  std::atomic<int> phase{-1};
  StatusOr<ArmSimSessionResult> result = Unavailable("not run");
  std::thread session([&] {
    result = RunArmSimSession("127.0.0.1", server_->port(), "secret", &arm, nullptr,
                              [&](double, const Eigen::Isometry3d&) { phase = int(arm.phase()); });
  });
  ASSERT_TRUE(WaitForArm());
  server_->PublishTarget(TrueTarget(arm.world(), 10));
  while (phase.load() != int(ArmSimPhase::kToStandoff)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // Moving.
  server_->PublishStop("operator");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // Still streaming its pose.
  server_->SendStopAndClose("test over");
  session.join();
  ASSERT_TRUE(result.ok()) << result.status().ToString();
  EXPECT_EQ(result->end_reason, "closed");
  ASSERT_TRUE(arm.last_stop_s().has_value());
  ASSERT_TRUE(arm.stopped());
  // The first stop's arrival: every step from then on is where the arm stood.
  double first_stop = 0;
  for (const ArmSimEvent& e : arm.events()) {
    if (e.what.rfind("stopped", 0) == 0 && first_stop == 0) first_stop = e.time_s;
  }
  ASSERT_GT(first_stop, 0);
  const Eigen::Vector3d final = arm.pose().translation();
  int after = 0, moving_before = 0;
  for (size_t i = 1; i < arm.steps().size(); ++i) {
    const ArmSimStep& s = arm.steps()[i];
    if (s.time_s >= first_stop) {
      EXPECT_EQ(s.position, final) << "step at +" << s.time_s - first_stop << " s";
      ++after;
    } else if (s.position != arm.steps()[i - 1].position) {
      ++moving_before;
    }
  }
  EXPECT_GT(after, 10);
  EXPECT_GT(moving_before, 10);
  EXPECT_GT(arm.Outcome().distance_mm, 10);  // Stopped on its way, far from the button.
}

}  // namespace
}  // namespace sightline
