// Settings of the rosbag reader (core/ros/bag_source.h), keys `io.rosbag.*`. Compiled also
// without ROS so that profiles stay valid in every build; declared with the sensor drivers'
// options (DeclareSensorOptions), and by every run on a .bag file.
#pragma once

#include <string>

#include "core/options/option_table.h"

namespace sightline {

// Which topics of a bag make the frames, the camera and the ground truth. An empty topic is
// chosen automatically when the bag leaves no doubt (see ChooseBagTopics in core/ros).
struct RosBagOptions {
  std::string kind = "auto";            // "auto", "rgbd", "stereo", "mono", "cloud".
  std::string image_topic;              // Colour / left / mono Image or CompressedImage.
  std::string depth_topic;              // Depth Image (16UC1 millimetres or 32FC1 metres).
  std::string camera_info_topic;        // CameraInfo of image_topic.
  std::string right_image_topic;        // Right image of a stereo pair.
  std::string right_camera_info_topic;  // CameraInfo of the right camera (P gives the baseline).
  std::string cloud_topic;              // PointCloud2 for point-cloud frames.
  std::string odometry_topic;           // nav_msgs/Odometry.
  std::string tf_parent_frame;          // Ground truth: pose of tf_child_frame in this frame.
  std::string tf_child_frame;           // Ground truth: the camera's tf frame.
  double pair_tolerance_ms = 20;        // Largest stamp difference of a colour/depth or L/R pair.
  // tf frames: odometry is odom_frame -> base_frame when no odometry topic is chosen; the arm's
  // pose is arm_base_frame -> end_effector_frame (base_from_end_effector).
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  std::string arm_base_frame = "base_link";
  std::string end_effector_frame = "end_effector";
  double tf_max_gap_s = 0.5;  // Largest time between two tf samples interpolated between.

  bool IsValid(std::string* error) const;
  static OptionTable<RosBagOptions> Describe();
};

}  // namespace sightline
