// The live ros:// source: its URI, and frames published on a private master arriving synced,
// decoded and stamped, with the images that find no partner dropped and counted.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "core/io/dataset.h"
#include "core/ros/ros_geometry.h"
#include "core/ros/ros_image.h"
#include "core/ros/ros_live_source.h"
#include "tests/ros/raw_message.h"
#include "tests/ros/ros_test_util.h"
#include "tests/ros/roscore_fixture.h"

namespace sightline {
namespace {

TEST(RosLiveUri, RgbdTopicsAndDefaults) {
  StatusOr<RosLiveOptions> o =
      ParseRosLiveUri("ros://?image=/camera/rgb/image_color&depth=/camera/depth/image");
  ASSERT_TRUE(o.ok()) << o.status().ToString();
  EXPECT_EQ(o->kind(), SourceKind::kRgbd);
  EXPECT_EQ(o->image, "/camera/rgb/image_color");
  EXPECT_EQ(o->depth, "/camera/depth/image");
  EXPECT_EQ(o->info, "/camera/rgb/camera_info");  // Beside the image topic.
  EXPECT_FALSE(o->exact);
  EXPECT_DOUBLE_EQ(o->slop_s, 0.02);
  EXPECT_EQ(o->queue, 4);
}

TEST(RosLiveUri, StereoAndSyncKeys) {
  StatusOr<RosLiveOptions> o = ParseRosLiveUri(
      "ros://?left=/s/left/image_rect&right=/s/right/image_rect&sync=exact&queue=2&wait=1.5");
  ASSERT_TRUE(o.ok()) << o.status().ToString();
  EXPECT_EQ(o->kind(), SourceKind::kStereo);
  EXPECT_EQ(o->left_info, "/s/left/camera_info");
  EXPECT_EQ(o->right_info, "/s/right/camera_info");
  EXPECT_TRUE(o->exact);
  EXPECT_EQ(o->queue, 2);
  EXPECT_DOUBLE_EQ(o->wait_s, 1.5);
  EXPECT_EQ(ParseRosLiveUri("ros://?image=/a/b").value().kind(), SourceKind::kMono);
}

TEST(RosLiveUri, ErrorsNameTheKey) {
  const auto message = [](const std::string& uri) {
    return ParseRosLiveUri(uri).status().message();
  };
  EXPECT_NE(message("ros://?image=/a&colour=/b").find("'colour'"), std::string::npos);
  EXPECT_NE(message("ros://?image=/a&sync=fast").find("sync"), std::string::npos);
  EXPECT_NE(message("ros://?image=/a&slop=-1").find("slop"), std::string::npos);
  EXPECT_NE(message("ros://?left=/a").find("right="), std::string::npos);
  EXPECT_NE(message("ros://?depth=/d").find("image="), std::string::npos);
  EXPECT_FALSE(ParseRosLiveUri("ros://?image=/a&queue=0").ok());
}

TEST(RosLiveUri, TfKeys) {
  StatusOr<RosLiveOptions> o = ParseRosLiveUri(
      "ros://?image=/a/image&odom_frame=map&base_frame=robot&arm_base_frame=arm&"
      "end_effector_frame=tool&tf_wait=2&tf_gap=0.25");
  ASSERT_TRUE(o.ok()) << o.status().ToString();
  EXPECT_EQ(o->odom_frame, "map");
  EXPECT_EQ(o->base_frame, "robot");
  EXPECT_EQ(o->arm_base_frame, "arm");
  EXPECT_EQ(o->end_effector_frame, "tool");
  EXPECT_DOUBLE_EQ(o->tf_wait_s, 2);
  EXPECT_DOUBLE_EQ(o->tf_gap_s, 0.25);
  const StatusOr<RosLiveOptions> defaults = ParseRosLiveUri("ros://?image=/a/image");
  EXPECT_EQ(defaults->odom_frame, "odom");
  EXPECT_EQ(defaults->end_effector_frame, "end_effector");
  EXPECT_NE(ParseRosLiveUri("ros://?image=/a&tf_gap=0").status().message().find("tf_gap"),
            std::string::npos);
  EXPECT_NE(ParseRosLiveUri("ros://?image=/a&base_frame=").status().message().find("base_frame"),
            std::string::npos);
}

TEST(RosLiveSource, NeedsARosNode) {
  RosLiveSource source(ParseRosLiveUri("ros://?image=/a/image").value());
  if (ros::isInitialized()) GTEST_SKIP() << "this process is already a ROS node";
  EXPECT_EQ(source.Open().code(), StatusCode::kFailedPrecondition);
}

// A colour image whose pixels encode `k`, and a depth image of k/10 + 1 metres.
cv::Mat Colour(int k) { return cv::Mat(48, 64, CV_8UC3, cv::Scalar(k, 2 * k, 3 * k)); }
cv::Mat Depth(int k) { return cv::Mat(48, 64, CV_32FC1, cv::Scalar(1 + 0.1 * k)); }

class RosLive : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    master_ = new testing::RoscoreFixture();
    error_ = new std::string(master_->Start());
    if (!error_->empty()) return;
    master_->ExportEnv();
    int argc = 0;
    ros::init(argc, nullptr, "sightline_live_test",
              ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
    ros::start();
  }
  static void TearDownTestSuite() {
    ros::shutdown();
    delete master_;
    delete error_;
  }
  void SetUp() override { ASSERT_TRUE(error_->empty()) << *error_; }
  static testing::RoscoreFixture* master_;
  static std::string* error_;
};
testing::RoscoreFixture* RosLive::master_ = nullptr;
std::string* RosLive::error_ = nullptr;

TEST_F(RosLive, RgbdFramesArriveSyncedDecodedAndStamped) {
  ros::NodeHandle nh;
  ros::Publisher image = nh.advertise<sensor_msgs::Image>("/live/rgb/image", 10);
  ros::Publisher depth = nh.advertise<sensor_msgs::Image>("/live/depth/image", 10);
  ros::Publisher info = nh.advertise<sensor_msgs::CameraInfo>("/live/rgb/camera_info", 1, true);
  PinholeCamera camera;
  camera.width = 64;
  camera.height = 48;
  camera.fx = camera.fy = 50;
  camera.cx = 32;
  camera.cy = 24;
  info.publish(RosInfoFromCamera(camera, 0, "camera"));
  StatusOr<RosLiveOptions> options =
      ParseRosLiveUri("ros://?image=/live/rgb/image&depth=/live/depth/image&slop=0.01&queue=50");
  ASSERT_TRUE(options.ok());
  RosLiveSource source(*options);
  ASSERT_TRUE(source.Open().ok());
  EXPECT_EQ(source.info().kind, SourceKind::kRgbd);
  ASSERT_TRUE(source.info().rgbd.has_value());
  EXPECT_DOUBLE_EQ(source.info().rgbd->color.fx, 50);
  EXPECT_TRUE(source.info().live);
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while ((image.getNumSubscribers() == 0 || depth.getNumSubscribers() == 0) &&
         std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_GT(depth.getNumSubscribers(), 0u);
  // Frames 0..9 at 10 Hz; the depth of each comes 4 ms after its colour (approximate sync),
  // and frame 5's depth is missing (its colour finds no partner).
  for (int k = 0; k < 10; ++k) {
    const double t = 100 + 0.1 * k;
    image.publish(EncodeRosImage(Colour(k), t, "camera").value());
    if (k != 5) depth.publish(EncodeRosImage(Depth(k), t + 0.004, "camera").value());
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::vector<int> seen;
  for (int i = 0; i < 9; ++i) {
    ASSERT_TRUE(source.Grab().ok());
    StatusOr<Frame> frame = source.Retrieve();
    ASSERT_TRUE(frame.ok()) << frame.status().ToString();
    const RgbdFrame& rgbd = std::get<RgbdFrame>(*frame);
    const int k = static_cast<int>(std::lround((rgbd.stamp.sensor_time_s - 100) / 0.1));
    EXPECT_NEAR(rgbd.stamp.sensor_time_s, 100 + 0.1 * k, 1e-6);
    EXPECT_EQ(rgbd.stamp.sequence_id, i);
    EXPECT_EQ(rgbd.color.at<cv::Vec3b>(10, 10), cv::Vec3b(k, 2 * k, 3 * k));
    EXPECT_NEAR(rgbd.depth_m.at<float>(10, 10), 1 + 0.1 * k, 1e-5);  // Its own depth.
    seen.push_back(k);
  }
  const std::vector<int> expected = {0, 1, 2, 3, 4, 6, 7, 8, 9};
  EXPECT_EQ(seen, expected);
  const RosLiveStats stats = source.Stats();
  EXPECT_EQ(stats.frames, 9);
  EXPECT_EQ(stats.unpaired, 1);  // Frame 5's colour.
  EXPECT_EQ(stats.queue_overflows, 0);
}

TEST_F(RosLive, ExactSyncDropsApproximatePairsAndTheQueueIsBounded) {
  ros::NodeHandle nh;
  ros::Publisher image = nh.advertise<sensor_msgs::Image>("/exact/rgb/image", 50);
  ros::Publisher depth = nh.advertise<sensor_msgs::Image>("/exact/depth/image", 50);
  ros::Publisher info = nh.advertise<sensor_msgs::CameraInfo>("/exact/rgb/camera_info", 1, true);
  PinholeCamera camera;
  camera.width = 64;
  camera.height = 48;
  camera.fx = camera.fy = 50;
  camera.cx = 32;
  camera.cy = 24;
  info.publish(RosInfoFromCamera(camera, 0, "camera"));
  RosLiveSource source(
      ParseRosLiveUri("ros://?image=/exact/rgb/image&depth=/exact/depth/image&sync=exact&queue=3")
          .value());
  ASSERT_TRUE(source.Open().ok());
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while ((image.getNumSubscribers() == 0 || depth.getNumSubscribers() == 0) &&
         std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  // Ten exact pairs, then one pair 1 ms apart (not exact), nobody grabbing meanwhile.
  for (int k = 0; k < 11; ++k) {
    const double t = 200 + 0.1 * k;
    image.publish(EncodeRosImage(Colour(k), t, "camera").value());
    depth.publish(EncodeRosImage(Depth(k), t + (k == 10 ? 0.001 : 0), "camera").value());
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  // Only the newest three exact pairs waited; the seven older ones were dropped and counted.
  std::vector<int> seen;
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(source.Grab().ok());
    const RgbdFrame rgbd = std::get<RgbdFrame>(source.Retrieve().value());
    seen.push_back(static_cast<int>(std::lround((rgbd.stamp.sensor_time_s - 200) / 0.1)));
  }
  EXPECT_EQ(seen, std::vector<int>({7, 8, 9}));
  const RosLiveStats stats = source.Stats();
  EXPECT_EQ(stats.queue_overflows, 7);
  EXPECT_GE(stats.unpaired, 1);  // Frame 10's colour (or depth) found no exact partner.
}

// A publisher whose CameraInfo claims 0xfffffff0 doubles of distortion in a few hundred bytes:
// the source refuses it before roscpp would allocate 34 GB for it, says so when no usable
// CameraInfo came, and takes the next good one from the same publisher.
TEST_F(RosLive, AMessageThatLiesAboutItsLengthIsRefusedAndNamed) {
  ros::NodeHandle nh;
  ros::Publisher info =
      nh.advertise<testing::RawMessage<sensor_msgs::CameraInfo>>("/lie/camera_info", 1, true);
  PinholeCamera camera;
  camera.width = 64;
  camera.height = 48;
  camera.fx = camera.fy = 50;
  camera.cx = 32;
  camera.cy = 24;
  const sensor_msgs::CameraInfo good = RosInfoFromCamera(camera, 0, "camera");
  info.publish(testing::LyingCameraInfo(good));
  {
    RosLiveSource source(ParseRosLiveUri("ros://?image=/lie/image&wait=2").value());
    const Status opened = source.Open();
    ASSERT_EQ(opened.code(), StatusCode::kUnavailable) << opened.ToString();
    EXPECT_NE(opened.message().find("messages refused, the last: /lie/camera_info: "
                                    "sensor_msgs/CameraInfo: field D declares 4294967280"),
              std::string::npos)
        << opened.ToString();
    EXPECT_GE(source.Stats().refused, 1);
  }
  testing::RawMessage<sensor_msgs::CameraInfo> raw;
  raw.bytes = testing::SerializedBytes(good);
  info.publish(raw);
  RosLiveSource source(ParseRosLiveUri("ros://?image=/lie/image&wait=10").value());
  ASSERT_TRUE(source.Open().ok());
  ASSERT_TRUE(source.info().camera.has_value());
  EXPECT_DOUBLE_EQ(source.info().camera->fx, 50);
  EXPECT_EQ(source.Stats().refused, 0);
}

// Bags and live topics build frames by one rule: a pair of one size, RGB-D colour as BGR, a
// stereo right image of the left's type.
TEST(FrameFromRosImages, PairsOfOneSizeWithColourAsBgrAndStereoOfOneType) {
  FrameStamp stamp;
  stamp.sequence_id = 3;
  const cv::Mat gray(4, 6, CV_8UC1, cv::Scalar(7));
  const cv::Mat bgr(4, 6, CV_8UC3, cv::Scalar(1, 2, 3));
  const cv::Mat depth(4, 6, CV_32FC1, cv::Scalar(1.5f));
  StatusOr<Frame> rgbd = FrameFromRosImages(SourceKind::kRgbd, stamp, gray, depth, "a", "b");
  ASSERT_TRUE(rgbd.ok());
  EXPECT_EQ(std::get<RgbdFrame>(*rgbd).color.type(), CV_8UC3);
  EXPECT_EQ(std::get<RgbdFrame>(*rgbd).stamp.sequence_id, 3);
  StatusOr<Frame> stereo = FrameFromRosImages(SourceKind::kStereo, stamp, gray, bgr, "a", "b");
  ASSERT_TRUE(stereo.ok());
  EXPECT_EQ(std::get<StereoFrame>(*stereo).right.type(), CV_8UC1);
  StatusOr<Frame> bad = FrameFromRosImages(SourceKind::kRgbd, stamp, bgr, cv::Mat(5, 6, CV_32FC1),
                                           "/cam/image", "ros:// /cam/depth");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().code(), StatusCode::kParseError);
  EXPECT_EQ(bad.status().message(), "ros:// /cam/depth: image is 6x5 but /cam/image is 6x4");
  StatusOr<Frame> mono = FrameFromRosImages(SourceKind::kMono, stamp, bgr, cv::Mat(), "a", "b");
  ASSERT_TRUE(mono.ok());
  EXPECT_EQ(std::get<MonoFrame>(*mono).image.cols, 6);
}

// Mono frames between the samples of a published /tf (odom -> base_link moving, base_link ->
// arm_mount on /tf_static, arm_mount -> end_effector moving): the source's odometry and arm poses
// are the chains interpolated at the frames' stamps.
TEST_F(RosLive, OdometryAndArmPosesFromTfAtTheFrameStamps) {
  ros::NodeHandle nh;
  ros::Publisher image = nh.advertise<sensor_msgs::Image>("/tfcam/image", 20);
  ros::Publisher info = nh.advertise<sensor_msgs::CameraInfo>("/tfcam/camera_info", 1, true);
  ros::Publisher tf = nh.advertise<tf2_msgs::TFMessage>("/tf", 100);
  ros::Publisher tf_static = nh.advertise<tf2_msgs::TFMessage>("/tf_static", 1, true);
  PinholeCamera camera;
  camera.width = 64, camera.height = 48, camera.fx = camera.fy = 50, camera.cx = 32, camera.cy = 24;
  info.publish(RosInfoFromCamera(camera, 0, "camera"));
  Eigen::Isometry3d base_from_mount = Eigen::Isometry3d::Identity();
  base_from_mount.translation() = Eigen::Vector3d(0.1, 0, 0.5);
  base_from_mount.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  tf2_msgs::TFMessage fixed;
  fixed.transforms.push_back(TransformMessage(base_from_mount, 200, "base_link", "arm_mount"));
  tf_static.publish(fixed);
  auto odom_from_base = [](double t) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(2.0 * (t - 200), 1, 0);
    return pose;
  };
  auto mount_from_ee = [](double t) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0, 0.5 * (t - 200), 0.2);
    return pose;
  };
  RosLiveSource source(
      ParseRosLiveUri("ros://?image=/tfcam/image&arm_base_frame=base_link&queue=20&tf_wait=10")
          .value());
  ASSERT_TRUE(source.Open().ok());
  // The button pipeline takes the arm's poses frame by frame from this channel.
  EXPECT_EQ(source.info().arm_pose_channel,
            "tf base_link -> end_effector (ros:// arm_base_frame, end_effector_frame)");
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while ((image.getNumSubscribers() == 0 || tf.getNumSubscribers() == 0 ||
          tf_static.getNumSubscribers() == 0) &&
         std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_GT(tf.getNumSubscribers(), 0u);
  // tf at 20 Hz over 200..200.6 s, then frames at 200.025 + 0.1 k (between two samples).
  for (int i = 0; i <= 12; ++i) {
    const double t = 200 + 0.05 * i;
    tf2_msgs::TFMessage msg;
    msg.transforms.push_back(TransformMessage(odom_from_base(t), t, "odom", "base_link"));
    msg.transforms.push_back(TransformMessage(mount_from_ee(t), t, "arm_mount", "end_effector"));
    tf.publish(msg);
  }
  // tf and images travel on separate connections: let tf name its frames first (the source only
  // waits for frames tf has named, so that cameras without tf never stall).
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  for (int k = 0; k < 5; ++k) {
    image.publish(
        EncodeRosImage(cv::Mat(48, 64, CV_8UC1, cv::Scalar(k)), 200.025 + 0.1 * k, "camera")
            .value());
  }
  std::vector<double> stamps;
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(source.Grab().ok());
    StatusOr<Frame> frame = source.Retrieve();
    ASSERT_TRUE(frame.ok()) << frame.status().ToString();
    stamps.push_back(std::get<MonoFrame>(*frame).stamp.sensor_time_s);
  }
  ASSERT_NE(source.odometry(), nullptr);
  ASSERT_NE(source.arm_poses(), nullptr);
  ASSERT_EQ(source.odometry()->size(), 5u);
  ASSERT_EQ(source.arm_poses()->size(), 5u);
  for (size_t i = 0; i < 5; ++i) {
    const TimedPose& odom = source.odometry()->poses()[i];
    const TimedPose& arm = source.arm_poses()->poses()[i];
    EXPECT_NEAR(odom.time_s, stamps[i], 1e-9);
    EXPECT_NEAR(arm.time_s, stamps[i], 1e-9);
    EXPECT_TRUE(odom.world_from_sensor.isApprox(odom_from_base(stamps[i]), 1e-6)) << i;
    EXPECT_TRUE(arm.world_from_sensor.isApprox(base_from_mount * mount_from_ee(stamps[i]), 1e-6))
        << i;
  }
  EXPECT_EQ(source.Stats().tf_missing, 0);
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

// sightline-cli is not a ROS node, yet `record` (and `run`) take ros:// sources: it joins the
// master as a client. Five synced RGB-D frames published here are recorded and read back with
// their pixels; without a master it says where it looked.
TEST_F(RosLive, TheCliRecordsLiveTopicsAsAClient) {
  ros::NodeHandle nh;
  ros::Publisher image = nh.advertise<sensor_msgs::Image>("/cli/rgb/image", 20);
  ros::Publisher depth = nh.advertise<sensor_msgs::Image>("/cli/depth/image", 20);
  ros::Publisher info = nh.advertise<sensor_msgs::CameraInfo>("/cli/rgb/camera_info", 1, true);
  PinholeCamera camera;
  camera.width = 64;
  camera.height = 48;
  camera.fx = camera.fy = 50;
  camera.cx = 32;
  camera.cy = 24;
  info.publish(RosInfoFromCamera(camera, 0, "camera"));
  const std::string out = ::testing::TempDir() + "/cli_ros_record";
  std::filesystem::remove_all(out);
  std::atomic<bool> done{false};
  testing::ProcessResult recorded;
  std::thread cli([&] {
    recorded = testing::RunProcess(
        testing::CliPath() +
        " record 'ros://?image=/cli/rgb/image&depth=/cli/depth/image&queue=50' --out " + out +
        " --frames 5");
    done = true;
  });
  // Publish frames at 10 Hz until the recorder has its five (it subscribes when it starts).
  for (int k = 1; !done && k < 600; ++k) {
    const double t = 200 + 0.1 * k;
    image.publish(EncodeRosImage(Colour(k % 40), t, "camera").value());
    depth.publish(EncodeRosImage(Depth(k % 40), t, "camera").value());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  cli.join();
  ASSERT_EQ(recorded.exit_code, 0) << recorded.out;
  StatusOr<std::unique_ptr<Source>> back = OpenDataset(out);
  ASSERT_TRUE(back.ok()) << back.status().ToString() << "\n" << recorded.out;
  EXPECT_EQ((*back)->info().kind, SourceKind::kRgbd);
  int frames = 0;
  while ((*back)->Grab().ok()) {
    StatusOr<Frame> frame = (*back)->Retrieve();
    ASSERT_TRUE(frame.ok()) << frame.status().ToString();
    const auto& rgbd = std::get<RgbdFrame>(*frame);
    // Colour(k) has blue k, green 2k, red 3k; depth k/10 + 1 m: the pair belongs together.
    const cv::Vec3b bgr = rgbd.color.at<cv::Vec3b>(10, 10);
    const int k = bgr[0];
    EXPECT_EQ(bgr[1], 2 * k);
    EXPECT_NEAR(rgbd.depth_m.at<float>(10, 10), 1 + 0.1 * k, 0.002);
    ++frames;
  }
  EXPECT_EQ(frames, 5) << recorded.out;

  // Without a master: the error names the master it asked.
  const testing::ProcessResult no_master = testing::RunProcess(
      "ROS_MASTER_URI=http://127.0.0.1:9 " + testing::CliPath() +
      " record 'ros://?image=/cli/rgb/image' --out " + out + "_none --frames 1");
  EXPECT_EQ(no_master.exit_code, 1) << no_master.out;
  EXPECT_NE(no_master.out.find("no ROS master answers at http://127.0.0.1:9"), std::string::npos)
      << no_master.out;
}

}  // namespace
}  // namespace sightline
