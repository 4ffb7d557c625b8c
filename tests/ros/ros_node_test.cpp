// sightline-node against its own master: a C++ subscriber receives what the node publishes on a
// simulated recording and checks it against the headless run (same pipeline, same frames). The
// master dying mid-run is reported and the run's results are kept.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Empty.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <thread>

#include "core/common/trajectory.h"
#include "core/io/dataset.h"
#include "core/io/hand_eye_file.h"
#include "core/pipeline/button_pipeline.h"
#include "core/ros/ros_geometry.h"
#include "core/ros/ros_image.h"
#include "tests/ros/ros_test_util.h"
#include "tests/ros/roscore_fixture.h"

namespace sightline {
namespace {

using testing::ChildProcess;
using testing::RoscoreFixture;

// What a subscriber received, guarded for the spinner's thread.
template <typename Msg>
class Inbox {
 public:
  void Take(const boost::shared_ptr<const Msg>& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    messages_.push_back(*msg);
  }
  std::vector<Msg> messages() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return messages_;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<Msg> messages_;
};

// One master for the suite, and this process as a ROS node on it.
class RosNode : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    master_ = new RoscoreFixture();
    error_ = new std::string(master_->Start());
    if (!error_->empty()) return;
    master_->ExportEnv();
    int argc = 0;
    ros::init(argc, nullptr, "sightline_test",
              ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
    spinner_ = new ros::AsyncSpinner(1);
    spinner_->start();
  }
  static void TearDownTestSuite() {
    if (spinner_ != nullptr) spinner_->stop();
    ros::shutdown();
    delete spinner_;
    delete master_;
    delete error_;
  }
  void SetUp() override { ASSERT_TRUE(error_->empty()) << *error_; }

  // Starts sightline-node with `args`; its output goes to `log`.
  static bool StartNode(ChildProcess* node, const std::string& args, const std::string& log) {
    return node->Start(master_->Env() + testing::NodePath() + " " + args, log);
  }
  // Waits until `ready` holds or `timeout_s` passed.
  template <typename Pred>
  static bool WaitFor(Pred ready, double timeout_s) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (std::chrono::steady_clock::now() < end) {
      if (ready()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return ready();
  }

  static RoscoreFixture* master_;
  static std::string* error_;
  static ros::AsyncSpinner* spinner_;
};

RoscoreFixture* RosNode::master_ = nullptr;
std::string* RosNode::error_ = nullptr;
ros::AsyncSpinner* RosNode::spinner_ = nullptr;

int8_t MapServerValue(uint8_t v, double occupied, double free) {
  const double p = (255.0 - v) / 255.0;
  return p > occupied ? 100 : (p < free ? 0 : -1);
}

TEST_F(RosNode, MappingMapAndScanMatchTheHeadlessRun) {
  const std::string rec = testing::CorridorRgbd();
  ASSERT_FALSE(rec.empty());
  const std::string headless = testing::TempDir("ros_node_mapping_cli");
  const auto cli = testing::RunProcess(testing::CliPath() + " run mapping " + rec + " --out " +
                                       headless + " --quiet");
  ASSERT_EQ(cli.exit_code, 0) << cli.out;

  ros::NodeHandle nh;
  Inbox<nav_msgs::OccupancyGrid> maps;
  Inbox<sensor_msgs::LaserScan> scans;
  ros::Subscriber map_sub = nh.subscribe("/map", 5, &Inbox<nav_msgs::OccupancyGrid>::Take, &maps);
  ros::Subscriber scan_sub =
      nh.subscribe("/scan", 100, &Inbox<sensor_msgs::LaserScan>::Take, &scans);
  const std::string out = testing::TempDir("ros_node_mapping_node");
  const std::string log = testing::TempDir("ros_node_mapping_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(StartNode(
      &node, "--pipeline mapping --source " + rec + " --out " + out + " --rate recorded --linger 3",
      log));
  const int code = node.Wait(180);
  EXPECT_EQ(code, 0) << testing::ReadTextFile(log);
  const testing::MapServerMap files = testing::ReadMapServerMap(headless);
  ASSERT_FALSE(files.gray.empty());
  const auto trajectory = testing::ReadTumTrajectory(headless + "/trajectory.txt");
  ASSERT_EQ(trajectory.size(), 30u);
  const double last_time = trajectory.rbegin()->first;
  // The latched map reaches the subscriber; the newest is the last frame's.
  ASSERT_TRUE(WaitFor(
      [&] {
        const auto m = maps.messages();
        return !m.empty() && std::abs(m.back().header.stamp.toSec() - last_time) < 1e-3;
      },
      10))
      << testing::ReadTextFile(log);
  const nav_msgs::OccupancyGrid map = maps.messages().back();
  EXPECT_EQ(map.header.frame_id, "map");
  ASSERT_EQ(map.info.width, static_cast<uint32_t>(files.gray.cols));
  ASSERT_EQ(map.info.height, static_cast<uint32_t>(files.gray.rows));
  EXPECT_NEAR(map.info.resolution, files.resolution, 1e-6);
  EXPECT_NEAR(map.info.origin.position.x, files.origin.x(), 1e-5);
  EXPECT_NEAR(map.info.origin.position.y, files.origin.y(), 1e-5);
  int mismatches = 0;
  for (int row = 0; row < files.gray.rows; ++row) {
    for (int col = 0; col < files.gray.cols; ++col) {
      mismatches += map.data[(files.gray.rows - 1 - row) * files.gray.cols + col] !=
                    MapServerValue(files.gray.at<uint8_t>(row, col), files.occupied_thresh,
                                   files.free_thresh);
    }
  }
  EXPECT_EQ(mismatches, 0);
  // Scans come stamped with the frames' sensor times (those of the headless trajectory).
  const auto received = scans.messages();
  ASSERT_GE(received.size(), 10u);
  for (const auto& scan : received) {
    const auto row = trajectory.lower_bound(scan.header.stamp.toSec() - 1e-3);
    ASSERT_NE(row, trajectory.end());
    EXPECT_NEAR(row->first, scan.header.stamp.toSec(), 1e-3);
    EXPECT_EQ(scan.header.frame_id, "base_link");
  }
}

TEST_F(RosNode, StereoOdometryEqualsTheHeadlessTrajectory) {
  const std::string rec = testing::CorridorStereo();
  ASSERT_FALSE(rec.empty());
  const std::string headless = testing::TempDir("ros_node_stereo_cli");
  const auto cli = testing::RunProcess(testing::CliPath() + " run stereo-vo " + rec + " --out " +
                                       headless + " --quiet");
  ASSERT_EQ(cli.exit_code, 0) << cli.out;
  const auto trajectory = testing::ReadTumTrajectory(headless + "/trajectory.txt");
  ASSERT_EQ(trajectory.size(), 30u);

  ros::NodeHandle nh;
  Inbox<nav_msgs::Odometry> odoms;
  // Remapped by the node's arguments: odom:=/vo/odom.
  ros::Subscriber sub = nh.subscribe("/vo/odom", 100, &Inbox<nav_msgs::Odometry>::Take, &odoms);
  Inbox<sensor_msgs::PointCloud2> clouds;
  ros::Subscriber points_sub =
      nh.subscribe("/map_points", 100, &Inbox<sensor_msgs::PointCloud2>::Take, &clouds);
  Inbox<visualization_msgs::MarkerArray> keyframes;
  ros::Subscriber keyframes_sub =
      nh.subscribe("/keyframes", 100, &Inbox<visualization_msgs::MarkerArray>::Take, &keyframes);
  const std::string out = testing::TempDir("ros_node_stereo_node");
  const std::string log = testing::TempDir("ros_node_stereo_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(StartNode(
      &node,
      "--pipeline stereo-vo --source " + rec + " --out " + out + " --linger 1 odom:=/vo/odom",
      log));
  EXPECT_EQ(node.Wait(180), 0) << testing::ReadTextFile(log);
  const auto received = odoms.messages();
  // Frames published before the subscriber connected are missed; at 10 Hz most arrive.
  ASSERT_GE(received.size(), 15u) << testing::ReadTextFile(log);
  for (const auto& odom : received) {
    const auto row = trajectory.lower_bound(odom.header.stamp.toSec() - 1e-4);
    ASSERT_NE(row, trajectory.end());
    ASSERT_NEAR(row->first, odom.header.stamp.toSec(), 1e-4);
    const auto& v = row->second;
    const auto& p = odom.pose.pose.position;
    EXPECT_NEAR(p.x, v[0], 1e-6);
    EXPECT_NEAR(p.y, v[1], 1e-6);
    EXPECT_NEAR(p.z, v[2], 1e-6);
    const auto& o = odom.pose.pose.orientation;
    // q and -q are one rotation.
    const double dot = o.x * v[3] + o.y * v[4] + o.z * v[5] + o.w * v[6];
    EXPECT_NEAR(std::abs(dot), 1.0, 1e-6);
    EXPECT_EQ(odom.header.frame_id, "odom");
    EXPECT_EQ(odom.child_frame_id, "camera");
  }
  // The last pose: the drive moved (a real comparison, not identity against identity).
  EXPECT_GT(trajectory.rbegin()->second.head<3>().norm(), 0.5);

  // map_points: each frame's triangulated inliers in odom; back in that frame's camera (by the
  // headless pose of its stamp) every point lies in front of it, within the corridor's reach.
  const auto pose_at = [&](double stamp) {
    const auto row = trajectory.lower_bound(stamp - 1e-4);
    EXPECT_NE(row, trajectory.end());
    const auto& v = row->second;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::Quaterniond(v[6], v[3], v[4], v[5]).normalized().toRotationMatrix();
    pose.translation() = v.head<3>();
    return pose;
  };
  const auto received_clouds = clouds.messages();
  ASSERT_GE(received_clouds.size(), 15u);
  size_t most_points = 0;
  for (const auto& cloud : received_clouds) {
    EXPECT_EQ(cloud.header.frame_id, "odom");
    const Eigen::Isometry3d camera_from_odom = pose_at(cloud.header.stamp.toSec()).inverse();
    ASSERT_EQ(cloud.point_step % 4, 0u);
    const size_t n = cloud.width * cloud.height;
    most_points = std::max(most_points, n);
    for (size_t i = 0; i < n; ++i) {
      float xyz[3];
      std::memcpy(xyz, &cloud.data[i * cloud.point_step], sizeof(xyz));
      const Eigen::Vector3d p = camera_from_odom * Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
      EXPECT_GT(p.z(), 0.2) << "point " << i << " at " << cloud.header.stamp.toSec();
      EXPECT_LT(p.norm(), 60.0) << "point " << i << " at " << cloud.header.stamp.toSec();
    }
  }
  EXPECT_GE(most_points, 50u);

  // keyframes (latched, whole list each time): an arrow at the first pose and at every pose
  // 0.5 m or 15 deg away from the last arrow's, the same rule applied to the headless poses.
  std::vector<Eigen::Vector3d> expected_arrows;
  Eigen::Isometry3d last = Eigen::Isometry3d::Identity();
  for (const auto& [stamp, row] : trajectory) {
    const Eigen::Isometry3d pose = pose_at(stamp);
    const Eigen::Isometry3d step = last.inverse() * pose;
    if (expected_arrows.empty() || step.translation().norm() >= 0.5 ||
        Eigen::AngleAxisd(step.rotation()).angle() >= 15 * M_PI / 180) {
      expected_arrows.push_back(pose.translation());
      last = pose;
    }
  }
  ASSERT_GE(expected_arrows.size(), 2u);
  const auto arrays = keyframes.messages();
  ASSERT_FALSE(arrays.empty());
  const auto& markers = arrays.back().markers;
  ASSERT_EQ(markers.size(), expected_arrows.size() + 1);  // After the DELETEALL marker.
  EXPECT_EQ(markers[0].action, visualization_msgs::Marker::DELETEALL);
  for (size_t i = 0; i < expected_arrows.size(); ++i) {
    const auto& from = markers[i + 1].points.at(0);
    EXPECT_NEAR(from.x, expected_arrows[i].x(), 1e-5) << "arrow " << i;
    EXPECT_NEAR(from.y, expected_arrows[i].y(), 1e-5) << "arrow " << i;
    EXPECT_NEAR(from.z, expected_arrows[i].z(), 1e-5) << "arrow " << i;
  }
}

// sightline-node --pipeline mono-slam on the simulated stereo drive's left images: each tracked
// frame's pose on odom equals the headless run's pose of that frame (trajectory_map.txt, the
// SLAM map's frame, as published), and the map's points and keyframes arrive latched.
TEST_F(RosNode, MonoSlamOdometryAndMapEqualTheHeadlessRun) {
  const std::string rec = testing::CorridorStereo();
  ASSERT_FALSE(rec.empty());
  const std::string headless = testing::TempDir("ros_node_mono_cli");
  const auto cli = testing::RunProcess(testing::CliPath() + " run mono-slam " + rec + " --out " +
                                       headless + " --quiet");
  ASSERT_EQ(cli.exit_code, 0) << cli.out;
  const auto trajectory = testing::ReadTumTrajectory(headless + "/trajectory_map.txt");
  ASSERT_GE(trajectory.size(), 20u) << "the headless run should track most of the 30 frames";

  ros::NodeHandle nh;
  Inbox<nav_msgs::Odometry> odoms;
  ros::Subscriber sub = nh.subscribe("/odom", 100, &Inbox<nav_msgs::Odometry>::Take, &odoms);
  Inbox<sensor_msgs::PointCloud2> clouds;
  ros::Subscriber points_sub =
      nh.subscribe("/map_points", 100, &Inbox<sensor_msgs::PointCloud2>::Take, &clouds);
  Inbox<visualization_msgs::MarkerArray> keyframes;
  ros::Subscriber keyframes_sub =
      nh.subscribe("/keyframes", 100, &Inbox<visualization_msgs::MarkerArray>::Take, &keyframes);
  const std::string out = testing::TempDir("ros_node_mono_node");
  const std::string log = testing::TempDir("ros_node_mono_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(StartNode(
      &node,
      "--pipeline mono-slam --source " + rec + " --out " + out + " --rate recorded --linger 2",
      log));
  EXPECT_EQ(node.Wait(240), 0) << testing::ReadTextFile(log);
  // The node's own files equal the headless run's: the same pipeline object on the same frames.
  EXPECT_EQ(testing::ReadTextFile(out + "/trajectory_map.txt"),
            testing::ReadTextFile(headless + "/trajectory_map.txt"));
  const auto received = odoms.messages();
  // At the recorded 10 Hz a subscriber connected before the first tracked frame misses few.
  ASSERT_GE(received.size(), trajectory.size() / 2) << testing::ReadTextFile(log);
  for (const auto& odom : received) {
    const auto row = trajectory.lower_bound(odom.header.stamp.toSec() - 1e-4);
    ASSERT_NE(row, trajectory.end());
    ASSERT_NEAR(row->first, odom.header.stamp.toSec(), 1e-4);
    const auto& v = row->second;
    const auto& p = odom.pose.pose.position;
    // trajectory_map.txt holds 9 decimals.
    EXPECT_NEAR(p.x, v[0], 1e-6);
    EXPECT_NEAR(p.y, v[1], 1e-6);
    EXPECT_NEAR(p.z, v[2], 1e-6);
    const auto& o = odom.pose.pose.orientation;
    EXPECT_NEAR(std::abs(o.x * v[3] + o.y * v[4] + o.z * v[5] + o.w * v[6]), 1.0, 1e-6);
  }
  EXPECT_GT(trajectory.rbegin()->second.head<3>().norm(), 0.1) << "the camera moved";
  // The map: points in front of the last tracked camera's reach, and one arrow per keyframe.
  ASSERT_FALSE(clouds.messages().empty()) << testing::ReadTextFile(log);
  const auto& cloud = clouds.messages().back();
  EXPECT_GE(cloud.width * cloud.height, 50u);
  ASSERT_FALSE(keyframes.messages().empty());
  EXPECT_GE(keyframes.messages().back().markers.size(), 2u);
}

// mono-slam on a live ros:// mono topic (the stereo drive's left images and camera_info played
// by the test): the node's trajectory equals the headless run's on the recording.
TEST_F(RosNode, MonoSlamOnLiveTopicsEqualsTheHeadlessRun) {
  const std::string rec = testing::CorridorStereo();
  ASSERT_FALSE(rec.empty());
  const std::string headless = testing::TempDir("ros_node_mono_live_cli");
  const auto cli = testing::RunProcess(testing::CliPath() + " run mono-slam " + rec + " --out " +
                                       headless + " --quiet");
  ASSERT_EQ(cli.exit_code, 0) << cli.out;
  const auto expected = testing::ReadTumTrajectory(headless + "/trajectory_map.txt");
  ASSERT_GE(expected.size(), 20u);
  StatusOr<std::unique_ptr<Source>> dataset = OpenDataset(rec, SourceKind::kStereo);
  ASSERT_TRUE(dataset.ok()) << dataset.status().ToString();
  const StereoRig rig = *(*dataset)->info().stereo;

  ros::NodeHandle nh;
  ros::Publisher image = nh.advertise<sensor_msgs::Image>("/mono/image_rect", 50);
  ros::Publisher info = nh.advertise<sensor_msgs::CameraInfo>("/mono/camera_info", 1, true);
  info.publish(RosInfoFromCamera(rig.left, 0, "camera"));
  Inbox<nav_msgs::Odometry> odoms;
  ros::Subscriber sub = nh.subscribe("/odom", 100, &Inbox<nav_msgs::Odometry>::Take, &odoms);
  const std::string out = testing::TempDir("ros_node_mono_live");
  const std::string log = testing::TempDir("ros_node_mono_live_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(StartNode(
      &node,
      "--pipeline mono-slam --out " + out + " --source 'ros://?image=/mono/image_rect&queue=50'",
      log));
  ASSERT_TRUE(
      WaitFor([&] { return image.getNumSubscribers() > 0 && sub.getNumPublishers() > 0; }, 60))
      << testing::ReadTextFile(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  for (int k = 0; k < 30; ++k) {
    ASSERT_TRUE((*dataset)->Grab().ok());
    const StereoFrame frame = std::get<StereoFrame>((*dataset)->Retrieve().value());
    image.publish(EncodeRosImage(frame.left, frame.stamp.sensor_time_s, "camera").value());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  const double last_time = expected.rbegin()->first;
  ASSERT_TRUE(WaitFor(
      [&] {
        const auto m = odoms.messages();
        return !m.empty() && std::abs(m.back().header.stamp.toSec() - last_time) < 1e-3;
      },
      120))
      << odoms.messages().size() << " odometry messages\n"
      << testing::ReadTextFile(log);
  node.Interrupt();
  EXPECT_EQ(node.Wait(60), 130) << testing::ReadTextFile(log);
  const auto live = testing::ReadTumTrajectory(out + "/trajectory_map.txt");
  ASSERT_EQ(live.size(), expected.size()) << testing::ReadTextFile(log);
  for (auto a = expected.begin(), b = live.begin(); a != expected.end(); ++a, ++b) {
    EXPECT_NEAR(a->first, b->first, 1e-6);
    for (int i = 0; i < 7; ++i) EXPECT_NEAR(a->second[i], b->second[i], 1e-6) << a->first;
  }
  EXPECT_GT(expected.rbegin()->second.head<3>().norm(), 0.1) << "the camera moved";
}

// mobility on live ros:// RGB-D topics (the corridor drive played by the test): a scored cloud
// per frame, and the node's segments equal the headless run's on the recording.
TEST_F(RosNode, MobilityOnLiveTopicsEqualsTheHeadlessRun) {
  const std::string rec = testing::CorridorRgbd();
  ASSERT_FALSE(rec.empty());
  const std::string headless = testing::TempDir("ros_node_mobility_live_cli");
  const auto cli = testing::RunProcess(testing::CliPath() + " run mobility " + rec + " --out " +
                                       headless + " --quiet");
  ASSERT_TRUE(cli.exit_code == 0 || cli.exit_code == 3) << cli.out;
  const std::string expected = testing::ReadTextFile(headless + "/segments.csv");
  ASSERT_GT(std::count(expected.begin(), expected.end(), '\n'), 30) << "too few segments";
  StatusOr<std::unique_ptr<Source>> dataset = OpenDataset(rec, SourceKind::kRgbd);
  ASSERT_TRUE(dataset.ok()) << dataset.status().ToString();

  ros::NodeHandle nh;
  ros::Publisher color = nh.advertise<sensor_msgs::Image>("/mob/rgb/image", 50);
  ros::Publisher depth = nh.advertise<sensor_msgs::Image>("/mob/depth/image", 50);
  ros::Publisher info = nh.advertise<sensor_msgs::CameraInfo>("/mob/rgb/camera_info", 1, true);
  info.publish(RosInfoFromCamera((*dataset)->info().rgbd->color, 0, "camera"));
  Inbox<sensor_msgs::PointCloud2> clouds;
  ros::Subscriber sub =
      nh.subscribe("/mobility_cloud", 50, &Inbox<sensor_msgs::PointCloud2>::Take, &clouds);
  const std::string out = testing::TempDir("ros_node_mobility_live");
  const std::string log = testing::TempDir("ros_node_mobility_live_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(StartNode(&node,
                        "--pipeline mobility --out " + out +
                            " --source 'ros://?image=/mob/rgb/image&depth=/mob/depth/image&"
                            "sync=exact&queue=50'",
                        log));
  ASSERT_TRUE(WaitFor(
      [&] {
        return color.getNumSubscribers() > 0 && depth.getNumSubscribers() > 0 &&
               sub.getNumPublishers() > 0;
      },
      60))
      << testing::ReadTextFile(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  double last_time = 0;
  for (int k = 0; k < 30; ++k) {
    ASSERT_TRUE((*dataset)->Grab().ok());
    const RgbdFrame frame = std::get<RgbdFrame>((*dataset)->Retrieve().value());
    color.publish(EncodeRosImage(frame.color, frame.stamp.sensor_time_s, "camera").value());
    depth.publish(EncodeRosImage(frame.depth_m, frame.stamp.sensor_time_s, "camera").value());
    last_time = frame.stamp.sensor_time_s;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(WaitFor(
      [&] {
        const auto m = clouds.messages();
        return !m.empty() && std::abs(m.back().header.stamp.toSec() - last_time) < 1e-3;
      },
      120))
      << clouds.messages().size() << " clouds\n"
      << testing::ReadTextFile(log);
  node.Interrupt();
  EXPECT_EQ(node.Wait(60), 130) << testing::ReadTextFile(log);
  EXPECT_EQ(clouds.messages().size(), 30u);
  EXPECT_EQ(testing::ReadTextFile(out + "/segments.csv"), expected);
}

// sightline-node on live ros:// topics: the test plays the stereo recording onto image and
// camera_info topics; the odometry equals the headless run on the recording; Ctrl-C ends the
// live run as cancelled (exit 130) with its files written.
TEST_F(RosNode, StereoOnLiveTopicsEqualsTheHeadlessRun) {
  const std::string rec = testing::CorridorStereo();
  ASSERT_FALSE(rec.empty());
  const std::string headless = testing::TempDir("ros_node_live_cli");
  const auto cli = testing::RunProcess(testing::CliPath() + " run stereo-vo " + rec + " --out " +
                                       headless + " --quiet");
  ASSERT_EQ(cli.exit_code, 0) << cli.out;
  const auto trajectory = testing::ReadTumTrajectory(headless + "/trajectory.txt");
  ASSERT_EQ(trajectory.size(), 30u);
  StatusOr<std::unique_ptr<Source>> dataset = OpenDataset(rec, SourceKind::kStereo);
  ASSERT_TRUE(dataset.ok()) << dataset.status().ToString();
  ASSERT_TRUE((*dataset)->info().stereo.has_value());
  const StereoRig rig = *(*dataset)->info().stereo;

  ros::NodeHandle nh;
  ros::Publisher left = nh.advertise<sensor_msgs::Image>("/cam/left/image_rect", 50);
  ros::Publisher right = nh.advertise<sensor_msgs::Image>("/cam/right/image_rect", 50);
  ros::Publisher left_info =
      nh.advertise<sensor_msgs::CameraInfo>("/cam/left/camera_info", 1, true);
  ros::Publisher right_info =
      nh.advertise<sensor_msgs::CameraInfo>("/cam/right/camera_info", 1, true);
  left_info.publish(RosInfoFromCamera(rig.left, 0, "left"));
  sensor_msgs::CameraInfo info = RosInfoFromCamera(rig.right, 0, "right");
  info.P[3] = rig.right.fx * rig.right_from_left.translation().x();  // -fx * baseline.
  right_info.publish(info);
  Inbox<nav_msgs::Odometry> odoms;
  ros::Subscriber sub = nh.subscribe("/odom", 100, &Inbox<nav_msgs::Odometry>::Take, &odoms);
  const std::string out = testing::TempDir("ros_node_live");
  const std::string log = testing::TempDir("ros_node_live_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(StartNode(&node,
                        "--pipeline stereo-vo --out " + out +
                            " --source 'ros://?left=/cam/left/image_rect&right=/cam/right/"
                            "image_rect&sync=exact&queue=50'",
                        log));
  ASSERT_TRUE(WaitFor(
      [&] {
        return left.getNumSubscribers() > 0 && right.getNumSubscribers() > 0 &&
               sub.getNumPublishers() > 0;
      },
      60))
      << testing::ReadTextFile(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  for (int k = 0; k < 30; ++k) {
    ASSERT_TRUE((*dataset)->Grab().ok());
    const StereoFrame frame = std::get<StereoFrame>((*dataset)->Retrieve().value());
    left.publish(EncodeRosImage(frame.left, frame.stamp.sensor_time_s, "left").value());
    right.publish(EncodeRosImage(frame.right, frame.stamp.sensor_time_s, "right").value());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(WaitFor([&] { return odoms.messages().size() >= 30; }, 60))
      << odoms.messages().size() << " odometry messages\n"
      << testing::ReadTextFile(log);
  node.Interrupt();
  EXPECT_EQ(node.Wait(60), 130) << testing::ReadTextFile(log);
  EXPECT_NE(testing::ReadTextFile(log).find("30 frames"), std::string::npos)
      << testing::ReadTextFile(log);
  EXPECT_TRUE(std::filesystem::exists(out + "/trajectory.txt"));
  const auto received = odoms.messages();
  ASSERT_EQ(received.size(), 30u);
  for (const auto& odom : received) {
    const auto row = trajectory.lower_bound(odom.header.stamp.toSec() - 1e-4);
    ASSERT_NE(row, trajectory.end());
    ASSERT_NEAR(row->first, odom.header.stamp.toSec(), 1e-4);
    const auto& p = odom.pose.pose.position;
    EXPECT_NEAR(p.x, row->second[0], 1e-6);
    EXPECT_NEAR(p.y, row->second[1], 1e-6);
    EXPECT_NEAR(p.z, row->second[2], 1e-6);
  }
}

// sightline-node mapping on live ros:// RGB-D topics with the wheel odometry only on /tf (odom ->
// base_link): the node takes each frame's pose from tf and maps as the headless run does with
// odometry.txt (the recording without its walls, people and scene files, which a live run lacks).
TEST_F(RosNode, MappingOnLiveTopicsTakesTheOdometryFromTf) {
  const std::string rec = testing::CorridorRgbd();
  ASSERT_FALSE(rec.empty());
  const std::string copy = testing::TempDir("ros_node_tf_rec") + "/rec";
  std::filesystem::copy(rec, copy, std::filesystem::copy_options::recursive);
  for (const char* name : {"walls.csv", "people.csv", "scene.yaml"}) {
    std::filesystem::remove(copy + "/" + name);
  }
  const std::string headless = testing::TempDir("ros_node_tf_cli");
  const auto cli = testing::RunProcess(testing::CliPath() + " run mapping " + copy + " --out " +
                                       headless + " --quiet");
  ASSERT_TRUE(cli.exit_code == 0 || cli.exit_code == 3) << cli.out;
  const auto expected = testing::ReadTumTrajectory(headless + "/trajectory.txt");
  ASSERT_EQ(expected.size(), 30u);
  StatusOr<Trajectory> odometry = ReadTumTrajectory(copy + "/odometry.txt");
  ASSERT_TRUE(odometry.ok()) << odometry.status().ToString();
  StatusOr<std::unique_ptr<Source>> dataset = OpenDataset(copy, SourceKind::kRgbd);
  ASSERT_TRUE(dataset.ok()) << dataset.status().ToString();
  ASSERT_TRUE((*dataset)->info().rgbd.has_value());

  ros::NodeHandle nh;
  ros::Publisher color = nh.advertise<sensor_msgs::Image>("/live/rgb/image", 50);
  ros::Publisher depth = nh.advertise<sensor_msgs::Image>("/live/depth/image", 50);
  ros::Publisher info = nh.advertise<sensor_msgs::CameraInfo>("/live/rgb/camera_info", 1, true);
  ros::Publisher tf = nh.advertise<tf2_msgs::TFMessage>("/tf", 200);
  info.publish(RosInfoFromCamera((*dataset)->info().rgbd->color, 0, "camera"));
  Inbox<nav_msgs::OccupancyGrid> maps;
  ros::Subscriber sub = nh.subscribe("/map", 5, &Inbox<nav_msgs::OccupancyGrid>::Take, &maps);
  const std::string out = testing::TempDir("ros_node_tf");
  const std::string log = testing::TempDir("ros_node_tf_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(StartNode(&node,
                        "--pipeline mapping --out " + out +
                            " --source 'ros://?image=/live/rgb/image&depth=/live/depth/image&"
                            "sync=exact&queue=50&tf_wait=30'",
                        log));
  ASSERT_TRUE(WaitFor(
      [&] {
        return color.getNumSubscribers() > 0 && depth.getNumSubscribers() > 0 &&
               tf.getNumSubscribers() > 0 && sub.getNumPublishers() > 0;
      },
      60))
      << testing::ReadTextFile(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  for (const TimedPose& p : odometry->poses()) {
    tf2_msgs::TFMessage msg;
    msg.transforms.push_back(TransformMessage(p.world_from_sensor, p.time_s, "odom", "base_link"));
    tf.publish(msg);
  }
  for (int k = 0; k < 30; ++k) {
    ASSERT_TRUE((*dataset)->Grab().ok());
    const RgbdFrame frame = std::get<RgbdFrame>((*dataset)->Retrieve().value());
    color.publish(EncodeRosImage(frame.color, frame.stamp.sensor_time_s, "camera").value());
    depth.publish(EncodeRosImage(frame.depth_m, frame.stamp.sensor_time_s, "camera").value());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  // The map of the last frame arrives once the node has processed every frame.
  const double last_time = expected.rbegin()->first;
  ASSERT_TRUE(WaitFor(
      [&] {
        const auto m = maps.messages();
        return !m.empty() && std::abs(m.back().header.stamp.toSec() - last_time) < 1e-3;
      },
      120))
      << testing::ReadTextFile(log);
  node.Interrupt();
  EXPECT_EQ(node.Wait(60), 130) << testing::ReadTextFile(log);
  EXPECT_NE(testing::ReadTextFile(out + "/mapping_log.txt").find("live source's odometry"),
            std::string::npos)
      << testing::ReadTextFile(out + "/mapping_log.txt");
  const auto live = testing::ReadTumTrajectory(out + "/trajectory.txt");
  ASSERT_EQ(live.size(), expected.size());
  for (auto a = expected.begin(), b = live.begin(); a != expected.end(); ++a, ++b) {
    EXPECT_NEAR(a->first, b->first, 1e-4);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a->second[i], b->second[i], 1e-4) << a->first;
  }
  // The drive moved: a real comparison.
  EXPECT_GT((expected.rbegin()->second.head<3>() - expected.begin()->second.head<3>()).norm(), 1.0);
}

// mobility's scored cloud and score grid reach a subscriber with the documented fields, scores
// in [0, 1] (NaN unsegmented) and costs in [0, 100] or -1.
TEST_F(RosNode, MobilityCloudAndGridArrive) {
  const std::string rec = testing::TempDir("ros_node_terrain") + "/rec";
  const auto sim = testing::RunProcess(testing::CliPath() + " simulate terrain --out " + rec +
                                       " --frames 4 --quiet --set sim.rate_hz=2");
  ASSERT_EQ(sim.exit_code, 0) << sim.out;
  ros::NodeHandle nh;
  Inbox<sensor_msgs::PointCloud2> clouds;
  Inbox<nav_msgs::OccupancyGrid> grids;
  ros::Subscriber cloud_sub =
      nh.subscribe("/mobility_cloud", 10, &Inbox<sensor_msgs::PointCloud2>::Take, &clouds);
  ros::Subscriber grid_sub =
      nh.subscribe("/mobility_grid", 10, &Inbox<nav_msgs::OccupancyGrid>::Take, &grids);
  const std::string out = testing::TempDir("ros_node_mobility");
  const std::string log = testing::TempDir("ros_node_mobility_log") + "/node.log";
  ChildProcess node;
  // 4 frames 0.5 s apart at the recorded rate: the subscribers connect within the first.
  ASSERT_TRUE(StartNode(
      &node,
      "--pipeline mobility --source " + rec + " --out " + out + " --rate recorded --linger 2",
      log));
  EXPECT_EQ(node.Wait(180), 0) << testing::ReadTextFile(log);
  ASSERT_FALSE(clouds.messages().empty()) << testing::ReadTextFile(log);
  ASSERT_FALSE(grids.messages().empty());
  const sensor_msgs::PointCloud2 cloud = clouds.messages().back();
  ASSERT_EQ(cloud.fields.size(), 6u);
  const std::vector<std::string> names = {"x", "y", "z", "score_rule", "score_gpr", "segment"};
  for (size_t i = 0; i < names.size(); ++i) EXPECT_EQ(cloud.fields[i].name, names[i]);
  ASSERT_GT(cloud.width, 1000u);
  int scored = 0;
  for (uint32_t i = 0; i < cloud.width; ++i) {
    float v[5];
    int32_t segment = 0;
    std::memcpy(v, &cloud.data[i * cloud.point_step], sizeof(v));
    std::memcpy(&segment, &cloud.data[i * cloud.point_step + 20], sizeof(segment));
    if (segment < 0) continue;
    ++scored;
    EXPECT_GE(v[3], 0.0f);
    EXPECT_LE(v[3], 1.0f);
  }
  EXPECT_GT(scored, static_cast<int>(cloud.width) / 2);
  const nav_msgs::OccupancyGrid grid = grids.messages().back();
  EXPECT_EQ(grid.header.frame_id, "mobility_ground");
  int known = 0;
  for (int8_t c : grid.data) {
    EXPECT_TRUE(c == -1 || (c >= 0 && c <= 100));
    known += c >= 0;
  }
  EXPECT_GT(known, 100);
}

TEST_F(RosNode, PrivateParameterOverridesTheOption) {
  const std::string rec = testing::CorridorRgbd();
  ASSERT_FALSE(rec.empty());
  ros::param::set("/sightline_param/mapping/stitch/resolution_m", 0.1);
  ros::NodeHandle nh;
  Inbox<nav_msgs::OccupancyGrid> maps;
  ros::Subscriber sub = nh.subscribe("/param_map", 5, &Inbox<nav_msgs::OccupancyGrid>::Take, &maps);
  const std::string out = testing::TempDir("ros_node_param");
  const std::string log = testing::TempDir("ros_node_param_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(StartNode(&node,
                        "--pipeline mapping --source " + rec + " --out " + out +
                            " --rate max --linger 3 __name:=sightline_param map:=/param_map",
                        log));
  EXPECT_EQ(node.Wait(180), 0) << testing::ReadTextFile(log);
  ASSERT_TRUE(WaitFor([&] { return !maps.messages().empty(); }, 10)) << testing::ReadTextFile(log);
  EXPECT_NEAR(maps.messages().back().info.resolution, 0.1, 1e-6);
  EXPECT_NE(testing::ReadTextFile(log).find("parameter sets mapping.stitch.resolution_m=0.1"),
            std::string::npos);
  EXPECT_NEAR(testing::ReadMapServerMap(out).resolution, 0.1, 1e-6);
}

// The value of `key` in a diagnostics status, or "".
std::string DiagValue(const diagnostic_msgs::DiagnosticStatus& status, const std::string& key) {
  for (const auto& kv : status.values) {
    if (kv.key == key) return kv.value;
  }
  return "";
}

// The button pipeline on a simulated panel approach: the operator's tap (on an image the node
// published, named by its stamp) gives a candidate but no target until the operator confirms;
// then targets arrive in the arm base frame at the true button.
TEST_F(RosNode, ButtonTargetsOnlyAfterTheOperatorConfirms) {
  const std::string rec = testing::TempDir("ros_node_panel") + "/rec";
  const auto sim = testing::RunProcess(testing::CliPath() + " simulate panel --out " + rec +
                                       " --quiet --set sim.arm.sideways_m=0.12");
  ASSERT_EQ(sim.exit_code, 0) << sim.out;
  const StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(rec + "/buttons.csv");
  ASSERT_TRUE(buttons.ok()) << buttons.status().ToString();
  const TrueButton* target = nullptr;
  for (const TrueButton& b : *buttons) target = b.id == 5 ? &b : target;
  ASSERT_NE(target, nullptr);
  // The truth in the arm's base frame, where targets are.
  const StatusOr<HandEye> hand_eye = ReadHandEyeFile(rec + "/hand_eye.yaml");
  ASSERT_TRUE(hand_eye.ok()) << hand_eye.status().ToString();
  ASSERT_TRUE(hand_eye->world_from_base.has_value());
  const Eigen::Vector3d truth_in_base =
      hand_eye->world_from_base->inverse() * target->center_in_world;

  ros::NodeHandle nh;
  Inbox<geometry_msgs::PoseStamped> targets;
  Inbox<diagnostic_msgs::DiagnosticArray> diagnostics;
  ros::Subscriber target_sub =
      nh.subscribe("/button_target", 100, &Inbox<geometry_msgs::PoseStamped>::Take, &targets);
  ros::Subscriber diag_sub = nh.subscribe(
      "/diagnostics", 1000, &Inbox<diagnostic_msgs::DiagnosticArray>::Take, &diagnostics);
  Inbox<sensor_msgs::Image> button_images;
  ros::Subscriber image_sub =
      nh.subscribe("/button_image", 10, &Inbox<sensor_msgs::Image>::Take, &button_images);
  Inbox<sensor_msgs::CompressedImage> button_jpegs;
  ros::Subscriber jpeg_sub = nh.subscribe(
      "/button_image/compressed", 10, &Inbox<sensor_msgs::CompressedImage>::Take, &button_jpegs);
  ros::Publisher tap_pub = nh.advertise<geometry_msgs::PointStamped>("/button_tap", 1);
  ros::Publisher confirm_pub = nh.advertise<std_msgs::Empty>("/button_confirm", 1);
  const std::string out = testing::TempDir("ros_node_button");
  const std::string log = testing::TempDir("ros_node_button_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(StartNode(
      &node, "--pipeline button --source " + rec + " --out " + out + " --rate recorded --linger 1",
      log));
  ASSERT_TRUE(WaitFor([&] { return tap_pub.getNumSubscribers() > 0; }, 60));
  // The operator's panel taps on the image the node publishes (button_image, stamped with its
  // frame's time): the first one, a few pixels off the button's centre.
  int frame = -1;
  double shown_stamp = 0;
  sensor_msgs::Image shown;
  ASSERT_TRUE(WaitFor(
      [&] {
        const auto images = button_images.messages();
        if (images.empty()) return false;
        shown = images.front();
        shown_stamp = shown.header.stamp.toSec();
        for (const auto& array : diagnostics.messages()) {
          for (const auto& status : array.status) {
            if (status.name != "sightline/button") continue;
            if (std::abs(array.header.stamp.toSec() - shown_stamp) > 1e-6) continue;
            frame = std::stoi(DiagValue(status, "frame"));
            return true;
          }
        }
        return false;
      },
      60))
      << testing::ReadTextFile(log);
  ASSERT_LT(frame, static_cast<int>(target->pixel.size()));
  ASSERT_TRUE(target->visible[frame]);
  // The published image is the recording's frame, pixel for pixel; its JPEG is close to it.
  {
    StatusOr<std::unique_ptr<Source>> dataset = OpenDataset(rec, SourceKind::kMono);
    ASSERT_TRUE(dataset.ok()) << dataset.status().ToString();
    ASSERT_TRUE((*dataset)->Seek(frame).ok());
    ASSERT_TRUE((*dataset)->Grab().ok());
    const MonoFrame recorded = std::get<MonoFrame>((*dataset)->Retrieve().value());
    const StatusOr<cv::Mat> decoded = DecodeRosImage(shown, RosImageRole::kColor);
    ASSERT_TRUE(decoded.ok()) << decoded.status().ToString();
    ASSERT_EQ(decoded->size(), recorded.image.size());
    ASSERT_EQ(decoded->type(), recorded.image.type());
    EXPECT_EQ(cv::norm(*decoded, recorded.image, cv::NORM_INF), 0.0);
    ASSERT_TRUE(WaitFor([&] { return !button_jpegs.messages().empty(); }, 10));
    const auto jpeg = button_jpegs.messages().front();
    EXPECT_NE(jpeg.format.find("jpeg"), std::string::npos) << jpeg.format;
    const StatusOr<cv::Mat> unpacked = DecodeRosCompressedImage(jpeg);
    ASSERT_TRUE(unpacked.ok()) << unpacked.status().ToString();
    EXPECT_EQ(unpacked->size(), recorded.image.size());
  }
  geometry_msgs::PointStamped tap;
  tap.header.stamp = ros::Time(shown_stamp);
  tap.point.x = target->pixel[frame].x() + 2;
  tap.point.y = target->pixel[frame].y() - 2;
  tap_pub.publish(tap);
  // The candidate waits for the operator's Yes: the gate says "not confirmed", no target.
  ASSERT_TRUE(WaitFor(
      [&] {
        for (const auto& array : diagnostics.messages()) {
          for (const auto& status : array.status) {
            if (status.name == "sightline/button/gate" && DiagValue(status, "state") == "confirm")
              return true;
          }
        }
        return false;
      },
      30))
      << testing::ReadTextFile(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_TRUE(targets.messages().empty());
  ASSERT_TRUE(WaitFor([&] { return confirm_pub.getNumSubscribers() > 0; }, 10));
  confirm_pub.publish(std_msgs::Empty());
  EXPECT_EQ(node.Wait(180), 0) << testing::ReadTextFile(log);
  const auto received = targets.messages();
  ASSERT_FALSE(received.empty()) << testing::ReadTextFile(log);
  const auto& last = received.back();
  EXPECT_EQ(last.header.frame_id, "arm_base");
  const Eigen::Vector3d position(last.pose.position.x, last.pose.position.y, last.pose.position.z);
  // The CLI's run of this approach is within 3 mm; the tap here comes a little later.
  EXPECT_LT((position - truth_in_base).norm(), 0.005)
      << position.transpose() << " vs " << truth_in_base.transpose();
  // Every target came after the confirmation, from a frame after the tapped one.
  for (const auto& t : received) EXPECT_GT(t.header.stamp.toSec(), shown_stamp);
}

// The simulated panel approach of the button tests, made once per process ("" on failure).
std::string PanelRecording() {
  static const std::string rec = [] {
    const std::string dir = testing::TempDir("ros_node_live_panel") + "/rec";
    const auto sim = testing::RunProcess(testing::CliPath() + " simulate panel --out " + dir +
                                         " --quiet --set sim.arm.sideways_m=0.12");
    return sim.exit_code == 0 ? dir : std::string();
  }();
  return rec;
}

// A camera on the arm, live: the panel recording's images and camera_info on topics and the
// arm's pose on /tf (arm_base -> tool at each image's stamp), played frame by frame.
class LivePanel {
 public:
  explicit LivePanel(const std::string& rec, bool with_arm_tf) : with_arm_tf_(with_arm_tf) {
    StatusOr<std::unique_ptr<Source>> dataset = OpenDataset(rec, SourceKind::kMono);
    if (!dataset.ok()) {
      error_ = dataset.status().ToString();
      return;
    }
    dataset_ = std::move(*dataset);
    StatusOr<Trajectory> arm = sightline::ReadTumTrajectory(rec + "/arm_poses.txt");
    if (!arm.ok()) {
      error_ = arm.status().ToString();
      return;
    }
    arm_ = std::move(*arm);
    ros::NodeHandle nh;
    image_ = nh.advertise<sensor_msgs::Image>("/arm_cam/image", 200);
    info_ = nh.advertise<sensor_msgs::CameraInfo>("/arm_cam/camera_info", 1, true);
    tf_ = nh.advertise<tf2_msgs::TFMessage>("/tf", 500);
    info_.publish(RosInfoFromCamera(*dataset_->info().camera, 0, "camera"));
  }
  const std::string& error() const { return error_; }
  // The source the node runs on: every frame waits (no drops), tf waits for its stamp.
  static std::string Uri() {
    return "'ros://?image=/arm_cam/image&arm_base_frame=arm_base&end_effector_frame=tool&"
           "queue=1000&tf_wait=30'";
  }
  bool Connected() const { return image_.getNumSubscribers() > 0 && tf_.getNumSubscribers() > 0; }
  // Publishes the next frame (and before it, the arm's pose at its stamp); false at the end.
  bool Next(double* stamp_s = nullptr) {
    if (!dataset_->Grab().ok()) return false;
    StatusOr<Frame> frame = dataset_->Retrieve();
    if (!frame.ok()) return false;
    const MonoFrame& mono = std::get<MonoFrame>(*frame);
    const double t = mono.stamp.sensor_time_s;
    if (with_arm_tf_) {
      const std::optional<size_t> i = arm_.Nearest(t, 1e-6);
      if (i) {
        tf2_msgs::TFMessage msg;
        msg.transforms.push_back(
            TransformMessage(arm_.poses()[*i].world_from_sensor, t, "arm_base", "tool"));
        tf_.publish(msg);
        // tf and images travel on separate connections: the source waits for a frame's tf only
        // once tf has named the end effector, so the first pose goes well ahead.
        if (stamps_.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(500));
      } else {
        ++frames_without_arm_sample_;
      }
    }
    image_.publish(EncodeRosImage(mono.image, t, "camera").value());
    stamps_.push_back(t);
    if (stamp_s) *stamp_s = t;
    return true;
  }
  // The index of the frame published at `stamp_s`, or -1.
  int FrameAt(double stamp_s) const {
    for (size_t k = 0; k < stamps_.size(); ++k) {
      if (std::abs(stamps_[k] - stamp_s) < 1e-6) return static_cast<int>(k);
    }
    return -1;
  }
  int frames_without_arm_sample() const { return frames_without_arm_sample_; }

 private:
  bool with_arm_tf_;
  std::string error_;
  std::unique_ptr<Source> dataset_;
  Trajectory arm_;
  ros::Publisher image_, info_, tf_;
  std::vector<double> stamps_;
  int frames_without_arm_sample_ = 0;
};

// What the button tests on live topics send and watch: the operator's topics, the node's
// targets, images and gate diagnostics.
struct ButtonOperator {
  ButtonOperator() {
    ros::NodeHandle nh;
    target_sub =
        nh.subscribe("/button_target", 1000, &Inbox<geometry_msgs::PoseStamped>::Take, &targets);
    diag_sub = nh.subscribe("/diagnostics", 5000, &Inbox<diagnostic_msgs::DiagnosticArray>::Take,
                            &diagnostics);
    image_sub = nh.subscribe("/button_image", 10, &Inbox<sensor_msgs::Image>::Take, &button_images);
    tap_pub = nh.advertise<geometry_msgs::PointStamped>("/button_tap", 1);
    confirm_pub = nh.advertise<std_msgs::Empty>("/button_confirm", 1);
  }
  bool Connected() const {
    return tap_pub.getNumSubscribers() > 0 && confirm_pub.getNumSubscribers() > 0 &&
           target_sub.getNumPublishers() > 0 && image_sub.getNumPublishers() > 0;
  }
  // The gate's status of the frame at `stamp_s`, if it arrived.
  std::optional<diagnostic_msgs::DiagnosticStatus> Gate(double stamp_s) const {
    for (const auto& array : diagnostics.messages()) {
      if (std::abs(array.header.stamp.toSec() - stamp_s) > 1e-6) continue;
      for (const auto& status : array.status) {
        if (status.name == "sightline/button/gate") return status;
      }
    }
    return std::nullopt;
  }
  bool GateState(const std::string& state) const {
    for (const auto& array : diagnostics.messages()) {
      for (const auto& status : array.status) {
        if (status.name == "sightline/button/gate" && DiagValue(status, "state") == state)
          return true;
      }
    }
    return false;
  }
  bool ImageShown(double stamp_s) const {
    for (const auto& image : button_images.messages()) {
      if (std::abs(image.header.stamp.toSec() - stamp_s) < 1e-6) return true;
    }
    return false;
  }
  void Tap(double stamp_s, const Eigen::Vector2d& pixel) {
    geometry_msgs::PointStamped tap;
    tap.header.stamp = ros::Time(stamp_s);
    tap.point.x = pixel.x();
    tap.point.y = pixel.y();
    tap_pub.publish(tap);
  }

  Inbox<geometry_msgs::PoseStamped> targets;
  Inbox<diagnostic_msgs::DiagnosticArray> diagnostics;
  Inbox<sensor_msgs::Image> button_images;
  ros::Subscriber target_sub, diag_sub, image_sub;
  ros::Publisher tap_pub, confirm_pub;
};

// The button picker on a live camera on the arm (ros:// topics): the arm's pose comes from tf at
// each image's stamp, so the run is metric as on the recording, and after the operator's tap
// and Yes the targets arrive in the arm base frame at the true button, as close to it as the
// headless run on the recording (arm_poses.txt) gets.
TEST_F(RosNode, ButtonOnLiveTopicsTakesTheArmPoseFromTf) {
  const std::string rec = PanelRecording();
  ASSERT_FALSE(rec.empty());
  const StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(rec + "/buttons.csv");
  ASSERT_TRUE(buttons.ok()) << buttons.status().ToString();
  const TrueButton* target = nullptr;
  for (const TrueButton& b : *buttons) target = b.id == 5 ? &b : target;
  ASSERT_NE(target, nullptr);
  ASSERT_TRUE(target->visible.at(0));
  const StatusOr<HandEye> hand_eye = ReadHandEyeFile(rec + "/hand_eye.yaml");
  ASSERT_TRUE(hand_eye.ok()) << hand_eye.status().ToString();
  ASSERT_TRUE(hand_eye->world_from_base.has_value());
  const Eigen::Vector3d truth_in_base =
      hand_eye->world_from_base->inverse() * target->center_in_world;
  const Eigen::Vector2d tap_pixel = target->pixel[0] + Eigen::Vector2d(2, -2);

  // The headless run on the recording, tapped at the same pixel of frame 0.
  const std::string headless = testing::TempDir("ros_node_live_button_cli");
  char tap_arg[64];
  std::snprintf(tap_arg, sizeof(tap_arg), "%.3f,%.3f@0", tap_pixel.x(), tap_pixel.y());
  const auto cli = testing::RunProcess(testing::CliPath() + " run button " + rec + " --tap " +
                                       tap_arg + " --out " + headless + " --quiet");
  ASSERT_EQ(cli.exit_code, 0) << cli.out;
  const std::optional<double> headless_mm = testing::JsonNumber(
      testing::ReadTextFile(headless + "/metrics.json"), "accuracy", "final_error_mm");
  ASSERT_TRUE(headless_mm.has_value()) << testing::ReadTextFile(headless + "/metrics.json");

  LivePanel panel(rec, /*with_arm_tf=*/true);
  ASSERT_TRUE(panel.error().empty()) << panel.error();
  ButtonOperator op;
  const std::string out = testing::TempDir("ros_node_live_button");
  const std::string log = testing::TempDir("ros_node_live_button_log") + "/node.log";
  ChildProcess node;
  // A live camera's estimate older than button.gate.max_age_ms (host clock since the image
  // arrived) is not sent; on a loaded machine one frame's processing may take longer than the
  // default 200 ms, so the guard is widened here: this run checks the arm's poses, not latency.
  ASSERT_TRUE(StartNode(&node,
                        "--pipeline button --out " + out + " --source " + LivePanel::Uri() +
                            " --set mono.run.hand_eye=" + rec +
                            "/hand_eye.yaml --set button.gate.max_age_ms=10000",
                        log));
  ASSERT_TRUE(WaitFor([&] { return panel.Connected() && op.Connected(); }, 60))
      << testing::ReadTextFile(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  // Frame 0, shown to the operator, who taps on it; the tap is taken with the next frame.
  double first = 0;
  ASSERT_TRUE(panel.Next(&first));
  ASSERT_TRUE(WaitFor([&] { return op.ImageShown(first); }, 120)) << testing::ReadTextFile(log);
  op.Tap(first, tap_pixel);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_TRUE(panel.Next());
  ASSERT_TRUE(WaitFor([&] { return op.GateState("confirm"); }, 120)) << testing::ReadTextFile(log);
  EXPECT_TRUE(op.targets.messages().empty());
  op.confirm_pub.publish(std_msgs::Empty());
  // Frame by frame: each once the node has answered the one before, whatever the load.
  double last = 0;
  for (double t = 0; panel.Next(&t);) {
    last = t;
    ASSERT_TRUE(WaitFor([&] { return op.Gate(t).has_value(); }, 120)) << t << "\n"
                                                                      << testing::ReadTextFile(log);
  }
  EXPECT_EQ(panel.frames_without_arm_sample(), 0);
  node.Interrupt();
  EXPECT_EQ(node.Wait(120), 130) << testing::ReadTextFile(log);
  const auto received = op.targets.messages();
  ASSERT_FALSE(received.empty()) << testing::ReadTextFile(log) << "\n"
                                 << testing::ReadTextFile(out + "/button_notes.txt");
  const auto& final_target = received.back();
  EXPECT_EQ(final_target.header.frame_id, "arm_base");
  const Eigen::Vector3d position(final_target.pose.position.x, final_target.pose.position.y,
                                 final_target.pose.position.z);
  const double live_mm = 1e3 * (position - truth_in_base).norm();
  // The headless run is within 3 mm; the live one within the node's 5 mm and within 1 mm of it.
  EXPECT_LT(*headless_mm, 5.0);
  EXPECT_LT(live_mm, 5.0) << position.transpose() << " vs " << truth_in_base.transpose();
  EXPECT_NEAR(live_mm, *headless_mm, 1.0);
  std::printf("button on ros:// with the arm on tf: final error %.2f mm (headless %.2f mm)\n",
              live_mm, *headless_mm);
  for (const auto& t : received) EXPECT_GT(t.header.stamp.toSec(), first);
  const std::string notes = testing::ReadTextFile(out + "/button_notes.txt");
  EXPECT_NE(notes.find("metric scale source: the live source's arm poses, tf arm_base -> tool"),
            std::string::npos)
      << notes;
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  EXPECT_EQ(testing::JsonNumber(metrics, "counts", "metric_from_live_arm_poses"), 1.0) << metrics;
  EXPECT_EQ(testing::JsonNumber(metrics, "counts", "metric_scale"), 1.0) << metrics;
}

// The same live camera without the arm on tf: the run says which frames tf lacks (per frame in
// the gate's diagnostics, once on stderr, in the notes), tracks only and sends no target even
// after the operator's Yes.
TEST_F(RosNode, ButtonOnLiveTopicsWithoutTheEndEffectorOnTfSendsNoTarget) {
  const std::string rec = PanelRecording();
  ASSERT_FALSE(rec.empty());
  const StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(rec + "/buttons.csv");
  ASSERT_TRUE(buttons.ok()) << buttons.status().ToString();
  const TrueButton* target = nullptr;
  for (const TrueButton& b : *buttons) target = b.id == 5 ? &b : target;
  ASSERT_NE(target, nullptr);
  LivePanel panel(rec, /*with_arm_tf=*/false);
  ASSERT_TRUE(panel.error().empty()) << panel.error();
  ButtonOperator op;
  const std::string out = testing::TempDir("ros_node_live_button_no_tf");
  const std::string log = testing::TempDir("ros_node_live_button_no_tf_log") + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(StartNode(&node,
                        "--pipeline button --out " + out + " --source " + LivePanel::Uri() +
                            " --set mono.run.hand_eye=" + rec + "/hand_eye.yaml",
                        log));
  ASSERT_TRUE(WaitFor([&] { return panel.Connected() && op.Connected(); }, 60))
      << testing::ReadTextFile(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  double first = 0;
  ASSERT_TRUE(panel.Next(&first));
  ASSERT_TRUE(WaitFor([&] { return op.ImageShown(first); }, 120)) << testing::ReadTextFile(log);
  op.Tap(first, target->pixel[0] + Eigen::Vector2d(2, -2));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_TRUE(panel.Next());
  ASSERT_TRUE(WaitFor([&] { return op.GateState("confirm"); }, 120)) << testing::ReadTextFile(log);
  op.confirm_pub.publish(std_msgs::Empty());
  // Frame by frame: each once the node has answered the one before, whatever the load.
  double last = 0;
  for (double t = 0; panel.Next(&t);) {
    last = t;
    ASSERT_TRUE(WaitFor([&] { return op.Gate(t).has_value(); }, 120)) << t << "\n"
                                                                      << testing::ReadTextFile(log);
  }
  // The last frame's gate names the frames tf lacks and the frame's stamp.
  const diagnostic_msgs::DiagnosticStatus gate = *op.Gate(last);
  const std::string missing = DiagValue(gate, "arm_pose_missing");
  EXPECT_NE(missing.find("tf arm_base -> tool"), std::string::npos) << missing;
  char stamp[32];
  std::snprintf(stamp, sizeof(stamp), "%.6f s", last);
  EXPECT_NE(missing.find(stamp), std::string::npos) << missing;
  EXPECT_EQ(DiagValue(gate, "tracking_only"), "true");
  node.Interrupt();
  EXPECT_EQ(node.Wait(120), 130) << testing::ReadTextFile(log);
  EXPECT_TRUE(op.targets.messages().empty()) << testing::ReadTextFile(log);
  const std::string text = testing::ReadTextFile(log);
  EXPECT_NE(text.find("no arm pose at"), std::string::npos) << text;
  EXPECT_NE(text.find("tf arm_base -> tool"), std::string::npos) << text;
  const std::string notes = testing::ReadTextFile(out + "/button_notes.txt");
  EXPECT_NE(notes.find("the live source gave no arm pose"), std::string::npos) << notes;
  EXPECT_NE(notes.find("tool"), std::string::npos) << notes;
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  EXPECT_EQ(testing::JsonNumber(metrics, "counts", "metric_scale"), 0.0) << metrics;
  EXPECT_EQ(testing::JsonNumber(metrics, "counts", "frames_with_arm_pose"), 0.0) << metrics;
}

TEST(RosNodeMaster, MasterLostMidRunIsReportedAndResultsKept) {
  const std::string rec = testing::CorridorRgbd();
  ASSERT_FALSE(rec.empty());
  RoscoreFixture master;
  const std::string error = master.Start();
  ASSERT_TRUE(error.empty()) << error;
  const std::string out = testing::TempDir("ros_node_master_lost");
  const std::string log = testing::TempDir("ros_node_master_lost_log") + "/node.log";
  ChildProcess node;
  // 30 frames at 5 Hz: about 6 s at the recorded rate.
  ASSERT_TRUE(node.Start(master.Env() + testing::NodePath() + " --pipeline mapping --source " +
                             rec + " --out " + out + " --rate recorded --linger 0",
                         log));
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (testing::ReadTextFile(log).find("running on") == std::string::npos &&
         std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  master.Stop();
  const int code = node.Wait(120);
  const std::string text = testing::ReadTextFile(log);
  EXPECT_EQ(code, 4) << text;
  EXPECT_NE(text.find("does not answer"), std::string::npos) << text;
  EXPECT_NE(text.find("30 frames published"), std::string::npos) << text;
  EXPECT_TRUE(std::filesystem::exists(out + "/map.pgm"));
  EXPECT_NE(testing::ReadTextFile(out + "/metrics.json").find("\"frames\": 30"), std::string::npos);
}

}  // namespace
}  // namespace sightline
