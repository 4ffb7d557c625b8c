// Writes ROS bags for the rosbag reader's tests with rosbag::Bag (bagmode::Write): simulator
// frames in the topic layout of a ROS camera driver, and bags with one deliberate defect.
// ROS-free header: the tests themselves stay C++20; bag_test_writer.cpp is C++17.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/common/trajectory.h"

namespace sightline::testing {

// What a simulated bag holds, for comparing what is read back.
struct SimBag {
  std::vector<double> times_s;       // Header stamps of frame i (all topics).
  std::vector<cv::Mat> color;        // CV_8UC3 BGR.
  std::vector<cv::Mat> depth_m;      // CV_32FC1 metres, NaN = none.
  std::vector<cv::Mat> left, right;  // CV_8UC1.
  PinholeCamera rgbd_camera;
  StereoRig stereo_rig;
  Trajectory camera_truth;  // world_from_camera of the RGB-D camera, on /tf world -> camera.
  Trajectory odometry;      // The robot's wheel odometry, on /odom (or /tf odom -> base_link).
};

// How to write it.
struct SimBagOptions {
  int frames = 6;
  bool depth_16u = false;            // Depth as 16UC1 millimetres instead of 32FC1 metres.
  std::string compression = "none";  // "none", "bz2", "lz4".
  bool stereo = true;                // Also /stereo/left|right/image_raw and camera_info.
  bool odometry_on_tf = false;       // Odometry as /tf odom -> base_link instead of on /odom.
};

// Renders the simulator's corridor and writes /camera/rgb/image_color (bgr8),
// /camera/depth/image, /camera/rgb/camera_info, /odom (nav_msgs/Odometry), /tf (world ->
// camera) and, with `stereo`, /stereo/left/image_raw, /stereo/right/image_raw (mono8) with
// their camera_info (the right P[3] = -fx * baseline).
StatusOr<SimBag> WriteSimBag(const std::string& path, const SimBagOptions& options);

// A mono bag /cam/image_raw (3 frames, 32x24) + /cam/camera_info with one defect:
// "encoding": message 2 of the images has encoding 'yuv422';
// "zero_info": the CameraInfo is all zeros;
// "no_info": no CameraInfo topic at all (the camera info is on /other/info_a and /other/info_b);
// "lying_info": every CameraInfo's distortion claims 0xfffffff0 doubles (a few hundred bytes);
// "two_images": a second image topic /cam2/image_raw and no left/right in the names.
Status WriteDefectiveBag(const std::string& path, const std::string& defect);

}  // namespace sightline::testing
