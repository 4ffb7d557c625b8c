// RosRemote against real masters (each test its own roscore on its own port) and a real
// sightline-node on a simulator-written bag: the map and the odometry arrive, a master that goes
// and comes back is noticed and the latched map arrives again, the operator's commands reach the
// button topics with their stamps, and bad options are named.
#include "core/ros/ros_remote.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PointStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <signal.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <thread>

#include "core/pipeline/button_result.h"
#include "core/ros/ros_publish.h"
#include "tests/ros/raw_message.h"
#include "tests/ros/ros_test_util.h"
#include "tests/ros/roscore_fixture.h"

namespace sightline {
namespace {

using testing::ChildProcess;
using testing::RoscoreFixture;

// Everything a RosRemote handed out, for the test thread.
class Received {
 public:
  RosRemote::Callback callback() {
    return [this](std::shared_ptr<const RemoteUpdate> u) {
      std::lock_guard<std::mutex> lock(mutex_);
      updates_.push_back(std::move(u));
    };
  }
  std::vector<std::shared_ptr<const RemoteUpdate>> Of(RemoteUpdate::Kind kind) const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::shared_ptr<const RemoteUpdate>> out;
    for (const auto& u : updates_) {
      if (u->kind == kind) out.push_back(u);
    }
    return out;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<std::shared_ptr<const RemoteUpdate>> updates_;
};

template <typename Pred>
bool WaitFor(Pred ready, double timeout_s) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return ready();
}

// A 30-frame corridor drive written by the simulator as a bag, made once per process.
std::string CorridorBag() {
  static const std::string bag = [] {
    const std::string dir = testing::TempDir("ros_remote_corridor_bag");
    const std::string path = dir + "/corridor.bag";
    if (std::filesystem::exists(path)) return path;
    const auto r = testing::RunProcess(
        testing::CliPath() + " simulate corridor --format bag --out " + dir +
        " --frames 30 --seed 3 --sensors rgbd --quiet --set sim.rgbd.resolution=320x240"
        " --set sim.rate_hz=5 --set sim.motion.speed_mps=1");
    return r.exit_code == 0 && std::filesystem::exists(path) ? path : std::string();
  }();
  return bag;
}

// A master, this process's environment pointed at it (ROS_IP for this process's own URI).
std::string StartMaster(RoscoreFixture* master) {
  const std::string error = master->Start();
  if (error.empty()) master->ExportEnv();
  return error;
}

TEST(RosRemoteOptions, BadUriAndNamespaceAreNamed) {
  std::string error;
  EXPECT_TRUE((RosRemoteOptions{"http://robot:11311", "/"}.IsValid(&error))) << error;
  EXPECT_TRUE((RosRemoteOptions{"http://10.0.0.2:11311/", "/robot1"}.IsValid(&error))) << error;
  EXPECT_FALSE((RosRemoteOptions{"robot:11311", "/"}.IsValid(&error)));
  EXPECT_NE(error.find("'robot:11311'"), std::string::npos) << error;
  EXPECT_FALSE((RosRemoteOptions{"http://robot:99999", "/"}.IsValid(&error)));
  EXPECT_NE(error.find("'99999'"), std::string::npos) << error;
  EXPECT_FALSE((RosRemoteOptions{"http://robot", "/"}.IsValid(&error)));
  EXPECT_NE(error.find("'http://robot'"), std::string::npos) << error;
  EXPECT_FALSE((RosRemoteOptions{"http://robot:11311", "/robot 1"}.IsValid(&error)));
  EXPECT_NE(error.find("'/robot 1'"), std::string::npos) << error;
  RosRemote remote(nullptr);
  const Status s = remote.Connect({"http://ro bot:11311", "/"});
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(s.message().find("'http://ro bot:11311'"), std::string::npos) << s.message();
  EXPECT_FALSE(remote.connected());
}

TEST(RosRemote, ReceivesTheMapAndOdometryOfANodeOnASimulatedBag) {
  const std::string bag = CorridorBag();
  ASSERT_FALSE(bag.empty());
  RoscoreFixture master;
  const std::string error = StartMaster(&master);
  ASSERT_TRUE(error.empty()) << error;
  const std::string out = testing::TempDir("ros_remote_node");
  const std::string log = testing::TempDir("ros_remote_node_log") + "/node.log";
  // The remote connects first and the node plays the bag at its recorded rate: odometry is not
  // latched, so frames published before the subscription reached the node would be missed.
  Received received;
  RosRemote remote(received.callback());
  ASSERT_TRUE(remote.Connect({master.uri(), "/"}).ok());
  ASSERT_TRUE(WaitFor([&] { return remote.connected(); }, 10));
  ChildProcess node;
  ASSERT_TRUE(node.Start(master.Env() + testing::NodePath() + " --pipeline mapping --source " +
                             bag + " --out " + out + " --rate recorded --linger -1",
                         log));
  // The run ends and writes its map; the latched map then is the final one.
  ASSERT_TRUE(WaitFor([&] { return std::filesystem::exists(out + "/map.pgm"); }, 180))
      << testing::ReadTextFile(log);
  const testing::MapServerMap truth = testing::ReadMapServerMap(out);
  ASSERT_FALSE(truth.gray.empty());
  auto final_map = [&] {
    const auto maps = received.Of(RemoteUpdate::Kind::kMap);
    return !maps.empty() && maps.back()->map.width == truth.gray.cols &&
           maps.back()->map.height == truth.gray.rows;
  };
  ASSERT_TRUE(WaitFor(final_map, 20)) << testing::ReadTextFile(log);
  const RemoteMap& map = received.Of(RemoteUpdate::Kind::kMap).back()->map;
  EXPECT_NEAR(map.resolution_m, truth.resolution, 1e-6);
  EXPECT_NEAR(map.origin.x(), truth.origin.x(), 1e-6);
  int known = 0, occupied = 0;
  for (int8_t c : map.cells) {
    known += c >= 0;
    occupied += c == 100;
  }
  EXPECT_GT(known, static_cast<int>(map.cells.size() / 20));
  EXPECT_GT(occupied, 10);

  // Odometry: base_link in odom, one per frame seen, moving forward at about 1 m/s.
  const auto odom = received.Of(RemoteUpdate::Kind::kOdometry);
  ASSERT_GE(odom.size(), 5u);
  EXPECT_EQ(odom.back()->pose.parent_frame, "odom");
  EXPECT_EQ(odom.back()->pose.child_frame, "base_link");
  const double dt = odom.back()->stamp_s - odom.front()->stamp_s;
  const double dist = (odom.back()->pose.parent_from_child.translation() -
                       odom.front()->pose.parent_from_child.translation())
                          .head<2>()
                          .norm();
  ASSERT_GT(dt, 0.5);
  EXPECT_NEAR(dist / dt, 1.0, 0.25);
  remote.Disconnect();
  EXPECT_FALSE(remote.connected());
}

TEST(RosRemote, SeesTheMasterGoAndComeBackAndGetsTheLatchedMapAgain) {
  const std::string bag = CorridorBag();
  ASSERT_FALSE(bag.empty());
  RoscoreFixture master;
  const std::string error = StartMaster(&master);
  ASSERT_TRUE(error.empty()) << error;
  const std::string out = testing::TempDir("ros_remote_restart");
  const std::string log = testing::TempDir("ros_remote_restart_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(node.Start(master.Env() + testing::NodePath() + " --pipeline mapping --source " +
                             bag + " --out " + out + " --rate max --linger -1",
                         log));
  ASSERT_TRUE(WaitFor([&] { return std::filesystem::exists(out + "/map.pgm"); }, 180))
      << testing::ReadTextFile(log);
  Received received;
  RosRemote remote(received.callback());
  ASSERT_TRUE(remote.Connect({master.uri(), "/"}).ok());
  ASSERT_TRUE(WaitFor([&] { return !received.Of(RemoteUpdate::Kind::kMap).empty(); }, 20))
      << testing::ReadTextFile(log);
  const size_t maps_before = received.Of(RemoteUpdate::Kind::kMap).size();

  const int port = master.port();
  master.Stop();
  ASSERT_TRUE(WaitFor([&] { return !remote.connected(); }, 10));
  ASSERT_EQ(master.Start(60, port), "");
  ASSERT_TRUE(WaitFor([&] { return remote.connected(); }, 10));
  // The node registers anew, the remote subscribes anew: the latched map arrives again.
  ASSERT_TRUE(
      WaitFor([&] { return received.Of(RemoteUpdate::Kind::kMap).size() > maps_before; }, 20))
      << testing::ReadTextFile(log);
  const auto maps = received.Of(RemoteUpdate::Kind::kMap);
  EXPECT_EQ(maps.back()->map.cells, maps.front()->map.cells);
  EXPECT_NE(testing::ReadTextFile(log).find("registered anew"), std::string::npos);
  // The connection changes in order: up, down, up.
  const auto changes = received.Of(RemoteUpdate::Kind::kConnection);
  ASSERT_EQ(changes.size(), 3u);
  EXPECT_TRUE(changes[0]->connected);
  EXPECT_FALSE(changes[1]->connected);
  EXPECT_TRUE(changes[2]->connected);
  EXPECT_EQ(changes[2]->master_uri, master.uri());
  remote.Disconnect();
}

// What arrives on the node's button topics (subscribed here as sightline-node does).
struct ButtonInbox {
  std::mutex mutex;
  std::vector<geometry_msgs::PointStamped> taps;
  std::vector<std::string> stops;
  int confirms = 0, cancels = 0;
};

TEST(RosRemote, TapConfirmCancelAndStopReachTheButtonTopicsWithTheirStamps) {
  RoscoreFixture master;
  const std::string error = StartMaster(&master);
  ASSERT_TRUE(error.empty()) << error;
  Received received;
  RosRemote remote(received.callback());
  // Without a master nothing is sent, and the reason says so.
  EXPECT_EQ(remote.SendTap(1, 2, 3).code(), StatusCode::kUnavailable);
  ASSERT_TRUE(remote.Connect({master.uri(), "/robot1"}).ok());
  ASSERT_TRUE(WaitFor([&] { return remote.connected(); }, 10));
  // No node yet: named.
  const Status none = remote.SendTap(1, 2, 3);
  EXPECT_EQ(none.code(), StatusCode::kUnavailable);
  EXPECT_NE(none.message().find("/robot1/button_tap"), std::string::npos) << none.message();

  ButtonInbox inbox;
  ros::NodeHandle nh("/robot1");
  ros::CallbackQueue queue;
  nh.setCallbackQueue(&queue);
  ros::AsyncSpinner spinner(1, &queue);
  spinner.start();
  std::vector<ros::Subscriber> subs;
  subs.push_back(nh.subscribe<geometry_msgs::PointStamped>(
      "button_tap", 10, [&](const geometry_msgs::PointStamped::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(inbox.mutex);
        inbox.taps.push_back(*m);
      }));
  subs.push_back(
      nh.subscribe<std_msgs::Empty>("button_confirm", 10, [&](const std_msgs::Empty::ConstPtr&) {
        std::lock_guard<std::mutex> lock(inbox.mutex);
        ++inbox.confirms;
      }));
  subs.push_back(
      nh.subscribe<std_msgs::Empty>("button_cancel", 10, [&](const std_msgs::Empty::ConstPtr&) {
        std::lock_guard<std::mutex> lock(inbox.mutex);
        ++inbox.cancels;
      }));
  subs.push_back(
      nh.subscribe<std_msgs::String>("button_stop", 10, [&](const std_msgs::String::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(inbox.mutex);
        inbox.stops.push_back(m->data);
      }));
  ASSERT_TRUE(WaitFor([&] { return remote.SendTap(161.5, 120.25, 1700000012.345678).ok(); }, 10));
  ASSERT_TRUE(WaitFor([&] { return remote.SendConfirm().ok(); }, 10));
  ASSERT_TRUE(WaitFor([&] { return remote.SendCancel().ok(); }, 10));
  ASSERT_TRUE(WaitFor([&] { return remote.SendStop("operator pressed STOP").ok(); }, 10));
  ASSERT_TRUE(WaitFor(
      [&] {
        std::lock_guard<std::mutex> lock(inbox.mutex);
        return !inbox.taps.empty() && inbox.confirms > 0 && inbox.cancels > 0 &&
               !inbox.stops.empty();
      },
      10));
  std::lock_guard<std::mutex> lock(inbox.mutex);
  EXPECT_DOUBLE_EQ(inbox.taps[0].point.x, 161.5);
  EXPECT_DOUBLE_EQ(inbox.taps[0].point.y, 120.25);
  EXPECT_EQ(inbox.taps[0].header.stamp.sec, 1700000012u);
  EXPECT_NEAR(inbox.taps[0].header.stamp.nsec, 345678000u, 1000);
  EXPECT_EQ(inbox.stops[0], "operator pressed STOP");
  spinner.stop();
  subs.clear();
  remote.Disconnect();
}

// What arrives on button_stop for a subscriber made now (this process, as a node would).
class StopListener {
 public:
  explicit StopListener(const std::string& ns) : nh_(ns) {
    nh_.setCallbackQueue(&queue_);
    spinner_.start();
    sub_ = nh_.subscribe<std_msgs::String>("button_stop", 10,
                                           [this](const std_msgs::String::ConstPtr& m) {
                                             std::lock_guard<std::mutex> lock(mutex_);
                                             stops_.push_back(m->data);
                                           });
    start_sub_ = nh_.subscribe<std_msgs::Empty>(
        "button_start", 10, [this](const std_msgs::Empty::ConstPtr&) { ++starts_; });
  }
  ~StopListener() {
    spinner_.stop();
    sub_.shutdown();
    start_sub_.shutdown();
  }
  std::vector<std::string> stops() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return stops_;
  }
  int publishers() const { return static_cast<int>(sub_.getNumPublishers()); }
  int starts() const { return starts_.load(); }

 private:
  ros::NodeHandle nh_;
  ros::CallbackQueue queue_;
  ros::AsyncSpinner spinner_{1, &queue_};
  ros::Subscriber sub_, start_sub_;
  std::atomic<int> starts_{0};
  mutable std::mutex mutex_;
  std::vector<std::string> stops_;
};

// STOP is never dropped: with no node listening it is kept (latched) and reaches the node that
// subscribes later; Start forgets it, so a node after that gets none.
TEST(RosRemote, StopIsKeptForANodeThatSubscribesLaterUntilStart) {
  RoscoreFixture master;
  const std::string error = StartMaster(&master);
  ASSERT_TRUE(error.empty()) << error;
  RosRemote remote(nullptr);
  // Before any connection: kept, and said so.
  const Status early = remote.SendStop("before connecting");
  EXPECT_EQ(early.code(), StatusCode::kUnavailable);
  EXPECT_NE(early.message().find("STOP kept"), std::string::npos) << early.message();
  EXPECT_TRUE(remote.stop_latched());
  ASSERT_TRUE(remote.Connect({master.uri(), "/robot2"}).ok());
  ASSERT_TRUE(WaitFor([&] { return remote.connected(); }, 10));
  {
    StopListener node("/robot2");
    ASSERT_TRUE(WaitFor([&] { return !node.stops().empty(); }, 10));
    EXPECT_EQ(node.stops().front(), "before connecting");
  }
  const Status later = remote.SendStop("operator");
  EXPECT_EQ(later.code(), StatusCode::kUnavailable);  // No node now; kept for the next one.
  EXPECT_NE(later.message().find("/robot2/button_stop"), std::string::npos) << later.message();
  {
    StopListener node("/robot2");
    ASSERT_TRUE(WaitFor([&] { return !node.stops().empty(); }, 10));
    EXPECT_EQ(node.stops().back(), "operator");
    EXPECT_TRUE(remote.SendStop("again").ok());  // A node listens: sent, Ok.
    // The latched "operator" may come twice (once per publisher link roscpp opens); "again"
    // must follow it, and nothing else may come.
    ASSERT_TRUE(WaitFor([&] { return node.stops().back() == "again"; }, 10));
    for (const std::string& stop : node.stops()) EXPECT_TRUE(stop == "operator" || stop == "again");
  }
  // A START that reaches no node lifts nothing.
  const Status unheard = remote.SendStart();
  EXPECT_EQ(unheard.code(), StatusCode::kUnavailable);
  EXPECT_NE(unheard.message().find("STOP kept"), std::string::npos) << unheard.message();
  EXPECT_TRUE(remote.stop_latched());
  {
    StopListener node("/robot2");
    ASSERT_TRUE(WaitFor([&] { return remote.SendStart().ok(); }, 10));
    ASSERT_TRUE(WaitFor([&] { return node.starts() > 0; }, 10));
  }
  EXPECT_FALSE(remote.stop_latched());
  {
    StopListener node("/robot2");
    ASSERT_TRUE(WaitFor([&] { return node.publishers() > 0; }, 10));
    // A latched STOP would come first on the link, before anything published after it.
    ASSERT_TRUE(WaitFor([&] { return remote.SendStop("marker").ok(); }, 10));
    ASSERT_TRUE(WaitFor([&] { return !node.stops().empty(); }, 10));
    EXPECT_EQ(node.stops().front(), "marker");
    EXPECT_TRUE(remote.SendStart().ok());
  }
  remote.Disconnect();
}

// STOP pressed while the master is gone is sent when it comes back, to a node that registers with
// the new master.
TEST(RosRemote, StopSentWithoutAMasterReachesTheNodeWhenTheMasterComesBack) {
  RoscoreFixture master;
  const std::string error = StartMaster(&master);
  ASSERT_TRUE(error.empty()) << error;
  RosRemote remote(nullptr);
  ASSERT_TRUE(remote.Connect({master.uri(), "/"}).ok());
  ASSERT_TRUE(WaitFor([&] { return remote.connected(); }, 10));
  const int port = master.port();
  master.Stop();
  ASSERT_TRUE(WaitFor([&] { return !remote.connected(); }, 10));
  const Status kept = remote.SendStop("operator, master gone");
  EXPECT_EQ(kept.code(), StatusCode::kUnavailable);
  ASSERT_EQ(master.Start(60, port), "");
  ASSERT_TRUE(WaitFor([&] { return remote.connected(); }, 10));
  StopListener node("/");
  ASSERT_TRUE(WaitFor([&] { return !node.stops().empty(); }, 10));
  EXPECT_EQ(node.stops().back(), "operator, master gone");
  remote.Disconnect();
}

// The fixture behind the master-gone tests: a roscore that cannot shut down (here frozen with
// SIGSTOP, on a loaded machine slow) is killed with its rosmaster and rosout, which roslaunch
// starts in sessions of their own; otherwise the master would go on answering after Stop().
TEST(RoscoreFixture, AStuckRoscoreLeavesNoMasterAnswering) {
  RoscoreFixture master;
  const std::string error = StartMaster(&master);
  ASSERT_TRUE(error.empty()) << error;
  ASSERT_TRUE(testing::MasterAnswers(master.port()));
  ASSERT_EQ(kill(master.pid(), SIGSTOP), 0);
  master.Stop();
  EXPECT_FALSE(testing::MasterAnswers(master.port()));
  EXPECT_EQ(master.Start(60, master.port()), "");  // The port is free for a new master.
}

// A map that claims more cells than its bytes hold is refused and counted, not decoded; the next
// good map from the same publisher arrives.
TEST(RosRemote, AMessageThatLiesAboutItsLengthIsRefusedAndCounted) {
  RoscoreFixture master;
  const std::string error = StartMaster(&master);
  ASSERT_TRUE(error.empty()) << error;
  Received received;
  RosRemote remote(received.callback());
  ASSERT_TRUE(remote.Connect({master.uri(), "/robot2"}).ok());
  ASSERT_TRUE(WaitFor([&] { return remote.connected(); }, 10));
  ros::NodeHandle nh("/robot2");
  ros::Publisher map =
      nh.advertise<testing::RawMessage<nav_msgs::OccupancyGrid>>("map", 1, /*latch=*/true);
  nav_msgs::OccupancyGrid grid;
  grid.header.frame_id = "map";
  grid.info.width = 4;
  grid.info.height = 2;
  grid.info.resolution = 0.05f;
  grid.data.assign(8, 0);
  testing::RawMessage<nav_msgs::OccupancyGrid> lie;
  lie.bytes = testing::SerializedBytes(grid);
  // header (seq, stamp, frame_id "map"), info (load time, resolution, width, height, origin: 7
  // float64), then the count of `data`.
  testing::PutUint32(&lie.bytes, 4 + 8 + 4 + 3 + 8 + 4 + 4 + 4 + 56, 0xfffffff0u);
  map.publish(lie);
  ASSERT_TRUE(WaitFor([&] { return remote.refused_messages() >= 1; }, 20));
  EXPECT_NE(remote.last_refused().find(
                "/robot2/map: nav_msgs/OccupancyGrid: field data declares 4294967280 int8 values"),
            std::string::npos)
      << remote.last_refused();
  EXPECT_TRUE(received.Of(RemoteUpdate::Kind::kMap).empty());
  testing::RawMessage<nav_msgs::OccupancyGrid> good;
  good.bytes = testing::SerializedBytes(grid);
  map.publish(good);
  ASSERT_TRUE(WaitFor([&] { return !received.Of(RemoteUpdate::Kind::kMap).empty(); }, 20));
  EXPECT_EQ(received.Of(RemoteUpdate::Kind::kMap).back()->map.width, 4);
  remote.Disconnect();
}

// The gate's answer to a tap reaches the panel's side as the node wrote it; a stamp that is not a
// number reads as 0 (no tap of the panel has that stamp), never as a crash or a wrong stamp.
TEST(RosRemote, TheGatesTapAnswerArrivesWithTheTappedPicturesStamp) {
  RoscoreFixture master;
  const std::string error = StartMaster(&master);
  ASSERT_TRUE(error.empty()) << error;
  Received received;
  RosRemote remote(received.callback());
  ASSERT_TRUE(remote.Connect({master.uri(), "/robot3"}).ok());
  ASSERT_TRUE(WaitFor([&] { return remote.connected(); }, 10));
  ros::NodeHandle nh("/robot3");
  ros::Publisher diagnostics = nh.advertise<diagnostic_msgs::DiagnosticArray>("diagnostics", 10);
  ButtonFrameResult frame;
  frame.stamp.sensor_time_s = 1700000013.5;
  frame.tap_answered = true;
  frame.tap_stamp_s = 1700000012.345678;
  frame.tap_status = FailedPrecondition("tap on frame 7 refused");
  frame.tap_refused = TapRefusal::kTooOld;
  diagnostic_msgs::DiagnosticArray array;
  array.status.push_back(ButtonGateStatus(frame));
  ASSERT_TRUE(WaitFor([&] { return diagnostics.getNumSubscribers() > 0; }, 20));
  diagnostics.publish(array);
  ASSERT_TRUE(WaitFor([&] { return !received.Of(RemoteUpdate::Kind::kGate).empty(); }, 20));
  const RemoteGate gate = received.Of(RemoteUpdate::Kind::kGate).front()->gate;
  EXPECT_EQ(gate.tap, "too_old");
  EXPECT_NEAR(gate.tap_stamp_s, 1700000012.345678, 1e-6);
  EXPECT_EQ(gate.state, "idle");
  // A gate without a tap's answer, and one whose stamp is not a number.
  frame.tap_answered = false;
  array.status = {ButtonGateStatus(frame)};
  diagnostics.publish(array);
  frame.tap_answered = true;
  array.status = {ButtonGateStatus(frame)};
  for (auto& kv : array.status[0].values) {
    if (kv.key == "tap_stamp") kv.value = "12.5e";
  }
  diagnostics.publish(array);
  ASSERT_TRUE(WaitFor([&] { return received.Of(RemoteUpdate::Kind::kGate).size() >= 3; }, 20));
  const auto gates = received.Of(RemoteUpdate::Kind::kGate);
  ASSERT_EQ(gates.size(), 3u);
  const RemoteGate& silent = gates[1]->gate;
  EXPECT_EQ(silent.tap, "");
  EXPECT_EQ(silent.tap_stamp_s, 0);
  const RemoteGate& garbled = gates.back()->gate;
  EXPECT_EQ(garbled.tap, "too_old");
  EXPECT_EQ(garbled.tap_stamp_s, 0);
  // A found button's outline arrives as the node wrote it; one that is not an outline is named
  // and dropped (the panel then marks the tapped spot).
  frame.tap_status = Status::Ok();
  frame.tap_refused = TapRefusal::kNone;
  frame.candidate_outline = {{100, 80}, {120, 81}, {110, 99}};
  const char* const bad[] = {"100,80 120", "100,80 120,81", "1,2 3,4 5,6x", "1,2 3,4 99999999,6"};
  array.status = {ButtonGateStatus(frame)};
  diagnostics.publish(array);
  for (const char* text : bad) {
    array.status = {ButtonGateStatus(frame)};
    for (auto& kv : array.status[0].values) {
      if (kv.key == "candidate") kv.value = text;
    }
    diagnostics.publish(array);
  }
  // The tracked button's ring, and rings that are none.
  frame.tap_answered = false;
  frame.picker.state = PickerState::kTracking;
  frame.picker.track.found = true;
  frame.picker.track.center = {50.5, 60};
  frame.picker.track.radius_px = 7;
  array.status = {ButtonGateStatus(frame)};
  diagnostics.publish(array);
  const char* const bad_rings[] = {"1,2", "1,2,-3", "nan,2,3", "1,2,3,4", "1;2;3"};
  for (const char* text : bad_rings) {
    for (auto& kv : array.status[0].values) {
      if (kv.key == "ring") kv.value = text;
    }
    diagnostics.publish(array);
  }
  ASSERT_TRUE(WaitFor([&] { return received.Of(RemoteUpdate::Kind::kGate).size() >= 14; }, 20));
  const auto all = received.Of(RemoteUpdate::Kind::kGate);
  ASSERT_EQ(all.size(), 14u);
  ASSERT_TRUE(all[8]->gate.ring.has_value());
  EXPECT_EQ(*all[8]->gate.ring, cv::Point3d(50.5, 60, 7));
  for (size_t i = 9; i < all.size(); ++i) EXPECT_FALSE(all[i]->gate.ring) << bad_rings[i - 9];
  EXPECT_EQ(all[3]->gate.tap, "found");
  EXPECT_EQ(all[3]->gate.candidate, frame.candidate_outline);
  EXPECT_EQ(all[3]->gate.bad_candidate, "");
  for (size_t i = 4; i < 8; ++i) {
    EXPECT_TRUE(all[i]->gate.candidate.empty()) << bad[i - 4];
    EXPECT_NE(all[i]->gate.bad_candidate.find("'candidate'"), std::string::npos)
        << bad[i - 4] << ": " << all[i]->gate.bad_candidate;
  }
  remote.Disconnect();
}

}  // namespace
}  // namespace sightline
