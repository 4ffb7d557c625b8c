#include "tests/ros/bag_test_writer.h"

#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/ros/ros_geometry.h"
#include "core/ros/ros_image.h"
#include "core/sim/simulator.h"
#include "tests/ros/raw_message.h"

namespace sightline::testing {
namespace {

// The simulator's clock starts at 0, before the earliest time a bag takes (ros::TIME_MIN).
constexpr double kSimBagEpochS = 1000.0;

tf2_msgs::TFMessage TfMessage(const Eigen::Isometry3d& pose, double stamp_s) {
  tf2_msgs::TFMessage msg;
  msg.transforms.push_back(TransformMessage(pose, stamp_s, "/world", "/camera"));
  return msg;
}

Status WriteImage(rosbag::Bag& bag, const std::string& topic, const cv::Mat& image,
                  double stamp_s) {
  StatusOr<sensor_msgs::Image> msg = EncodeRosImage(image, stamp_s, "camera");
  if (!msg.ok()) return msg.status();
  bag.write(topic, RosTimeFromSeconds(stamp_s), *msg);
  return Status::Ok();
}

cv::Mat DepthMillimetres(const cv::Mat& depth_m) {
  cv::Mat mm(depth_m.size(), CV_16UC1);
  for (int r = 0; r < depth_m.rows; ++r) {
    for (int c = 0; c < depth_m.cols; ++c) {
      const float d = depth_m.at<float>(r, c);
      mm.at<uint16_t>(r, c) = std::isfinite(d) ? static_cast<uint16_t>(std::lround(d * 1000)) : 0;
    }
  }
  return mm;
}

void SetCompression(rosbag::Bag& bag, const std::string& compression) {
  if (compression == "bz2") bag.setCompression(rosbag::compression::BZ2);
  if (compression == "lz4") bag.setCompression(rosbag::compression::LZ4);
}

// Frame i of the RGB-D and stereo sensors, written to the bag and kept in `out`.
Status WriteSimFrame(sim::Simulator& simulator, int i, const SimBagOptions& options,
                     const Trajectory& odometry, rosbag::Bag& bag, SimBag* out) {
  const double t = kSimBagEpochS + simulator.TimeOf(i);
  sim::SimulatedRgbd rgbd;
  SIGHTLINE_RETURN_IF_ERROR(simulator.RenderRgbd(i, &rgbd));
  out->times_s.push_back(t);
  out->color.push_back(rgbd.color);
  cv::Mat depth = options.depth_16u ? DepthMillimetres(rgbd.depth_m) : rgbd.depth_m;
  out->depth_m.push_back(rgbd.depth_m);
  out->camera_truth.Add(t, rgbd.world_from_camera);
  SIGHTLINE_RETURN_IF_ERROR(WriteImage(bag, "/camera/rgb/image_color", rgbd.color, t));
  SIGHTLINE_RETURN_IF_ERROR(WriteImage(bag, "/camera/depth/image", depth, t));
  const ros::Time stamp = RosTimeFromSeconds(t);
  bag.write("/camera/rgb/camera_info", stamp, RosInfoFromCamera(out->rgbd_camera, t, "camera"));
  bag.write("/tf", stamp, TfMessage(rgbd.world_from_camera, t));
  if (static_cast<size_t>(i) < odometry.size()) {
    const TimedPose& p = odometry.poses()[static_cast<size_t>(i)];
    const double odometry_t = kSimBagEpochS + p.time_s;
    if (options.odometry_on_tf) {
      tf2_msgs::TFMessage msg;
      msg.transforms.push_back(
          TransformMessage(p.world_from_sensor, odometry_t, "odom", "base_link"));
      bag.write("/tf", RosTimeFromSeconds(odometry_t), msg);
    } else {
      bag.write("/odom", RosTimeFromSeconds(odometry_t),
                OdometryMessage(p.world_from_sensor, odometry_t, "odom", "base_link"));
    }
    out->odometry.Add(odometry_t, p.world_from_sensor);
  }
  if (!options.stereo) return Status::Ok();
  sim::SimulatedStereo stereo;
  SIGHTLINE_RETURN_IF_ERROR(simulator.RenderStereo(i, &stereo));
  out->left.push_back(stereo.left);
  out->right.push_back(stereo.right);
  SIGHTLINE_RETURN_IF_ERROR(WriteImage(bag, "/stereo/left/image_raw", stereo.left, t));
  SIGHTLINE_RETURN_IF_ERROR(WriteImage(bag, "/stereo/right/image_raw", stereo.right, t));
  const StereoRig& rig = out->stereo_rig;
  bag.write("/stereo/left/camera_info", stamp, RosInfoFromCamera(rig.left, t, "left"));
  sensor_msgs::CameraInfo right = RosInfoFromCamera(rig.right, t, "right");
  right.P[3] = -rig.right.fx * rig.BaselineM();
  bag.write("/stereo/right/camera_info", stamp, right);
  return Status::Ok();
}

}  // namespace

StatusOr<SimBag> WriteSimBag(const std::string& path, const SimBagOptions& options) {
  sim::SimulationOptions sim_options = sim::SimulationOptions::ForScene("corridor");
  sim_options.frames = options.frames;
  sim_options.sensors = options.stereo ? "rgbd,stereo" : "rgbd";
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(sim_options);
  if (!simulator.ok()) return simulator.status();
  SimBag out;
  out.rgbd_camera = simulator->rgbd_camera();
  out.stereo_rig = simulator->stereo_rig();
  const Trajectory odometry = simulator->WheelOdometry();
  try {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    SetCompression(bag, options.compression);
    for (int i = 0; i < options.frames; ++i) {
      SIGHTLINE_RETURN_IF_ERROR(WriteSimFrame(*simulator, i, options, odometry, bag, &out));
    }
    bag.close();
  } catch (const std::exception& e) {
    return Internal(path + ": writing the bag failed: " + e.what());
  }
  return out;
}

Status WriteDefectiveBag(const std::string& path, const std::string& defect) {
  PinholeCamera camera;
  camera.width = 32, camera.height = 24, camera.fx = camera.fy = 30, camera.cx = 16, camera.cy = 12;
  try {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    for (int i = 0; i < 3; ++i) {
      const double t = 100.0 + 0.1 * i;
      cv::Mat image(24, 32, CV_8UC3, cv::Scalar(10 * i, 20, 30));
      StatusOr<sensor_msgs::Image> msg = EncodeRosImage(image, t, "cam");
      if (!msg.ok()) return msg.status();
      if (defect == "encoding" && i == 2) msg->encoding = "yuv422";
      bag.write("/cam/image_raw", RosTimeFromSeconds(t), *msg);
      if (defect == "two_images") bag.write("/cam2/image_raw", RosTimeFromSeconds(t), *msg);
      sensor_msgs::CameraInfo info = RosInfoFromCamera(camera, t, "cam");
      if (defect == "zero_info") {
        info = sensor_msgs::CameraInfo();
        info.header.stamp = RosTimeFromSeconds(t);
      }
      if (defect == "lying_info") {
        bag.write("/cam/camera_info", RosTimeFromSeconds(t), LyingCameraInfo(info));
      } else if (defect == "no_info") {
        bag.write("/other/info_a", RosTimeFromSeconds(t), info);
        bag.write("/other/info_b", RosTimeFromSeconds(t), info);
      } else {
        bag.write("/cam/camera_info", RosTimeFromSeconds(t), info);
      }
    }
    bag.close();
  } catch (const std::exception& e) {
    return Internal(path + ": writing the bag failed: " + e.what());
  }
  return Status::Ok();
}

}  // namespace sightline::testing
