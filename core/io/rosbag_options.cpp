#include "core/io/rosbag_options.h"

namespace sightline {

bool RosBagOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error) *error = message;
    return false;
  };
  if (tf_parent_frame.empty() != tf_child_frame.empty()) {
    return fail("io.rosbag.tf_parent_frame and io.rosbag.tf_child_frame must be given together");
  }
  if (!(pair_tolerance_ms >= 0)) return fail("io.rosbag.pair_tolerance_ms must be >= 0");
  if (!(tf_max_gap_s > 0)) return fail("io.rosbag.tf_max_gap_s must be > 0");
  for (const auto& [key, frame] :
       {std::pair<const char*, const std::string*>{"odom_frame", &odom_frame},
        {"base_frame", &base_frame},
        {"arm_base_frame", &arm_base_frame},
        {"end_effector_frame", &end_effector_frame}}) {
    if (frame->empty()) return fail(std::string("io.rosbag.") + key + " must name a tf frame");
  }
  if (kind == "stereo" && !image_topic.empty() && image_topic == right_image_topic) {
    return fail("io.rosbag.image_topic and right_image_topic are the same topic '" + image_topic +
                "'");
  }
  return true;
}

OptionTable<RosBagOptions> RosBagOptions::Describe() {
  return OptionTable<RosBagOptions>("io.rosbag")
      .Choice("kind", &RosBagOptions::kind, {"auto", "rgbd", "stereo", "mono", "cloud"},
              "Kind of frames read from a ROS bag; auto picks RGB-D, then stereo, then mono, "
              "then point clouds, as the bag's topics allow.")
      .String("image_topic", &RosBagOptions::image_topic,
              "ROS bag: the colour, left or mono image topic (Image or CompressedImage); empty "
              "picks it when the bag leaves no doubt.")
      .String("depth_topic", &RosBagOptions::depth_topic,
              "ROS bag: the depth image topic (16UC1 millimetres or 32FC1 metres); empty picks "
              "it when the bag leaves no doubt.")
      .String("camera_info_topic", &RosBagOptions::camera_info_topic,
              "ROS bag: the CameraInfo topic of the image topic; empty looks beside the image "
              "topic, then takes the bag's only CameraInfo topic.")
      .String("right_image_topic", &RosBagOptions::right_image_topic,
              "ROS bag: the right image topic of a stereo pair; empty picks the topic whose name "
              "says right beside one that says left.")
      .String("right_camera_info_topic", &RosBagOptions::right_camera_info_topic,
              "ROS bag: the right camera's CameraInfo topic; its projection matrix P gives the "
              "stereo baseline.")
      .String("cloud_topic", &RosBagOptions::cloud_topic,
              "ROS bag: the PointCloud2 topic read as point-cloud frames.")
      .String("odometry_topic", &RosBagOptions::odometry_topic,
              "ROS bag: the nav_msgs/Odometry topic; empty takes the bag's only one.")
      .String("tf_parent_frame", &RosBagOptions::tf_parent_frame,
              "ROS bag: ground truth is the pose of tf_child_frame in this tf frame; empty uses "
              "the bag's only transform chain on /tf.")
      .String("tf_child_frame", &RosBagOptions::tf_child_frame,
              "ROS bag: the camera's tf frame whose pose in tf_parent_frame is the ground truth.")
      .Double("pair_tolerance_ms", &RosBagOptions::pair_tolerance_ms, "ms", 0, 1000, 1,
              "ROS bag: largest stamp difference of a colour/depth or left/right pair; images "
              "without a partner are skipped.")
      .String("odom_frame", &RosBagOptions::odom_frame,
              "ROS bag: the tf frame of the odometry; without an odometry topic, the pose of "
              "base_frame in it on /tf is the platform's odometry.")
      .String("base_frame", &RosBagOptions::base_frame,
              "ROS bag: the platform's tf frame whose pose in odom_frame is the odometry.")
      .String("arm_base_frame", &RosBagOptions::arm_base_frame,
              "ROS bag: the arm's base tf frame; the pose of end_effector_frame in it is the "
              "arm's pose when there is no arm_poses.txt.")
      .String("end_effector_frame", &RosBagOptions::end_effector_frame,
              "ROS bag: the arm's end-effector tf frame.")
      .Double("tf_max_gap_s", &RosBagOptions::tf_max_gap_s, "s", 0.001, 60, 0.1,
              "ROS bag: largest time between the two tf samples a pose at a frame's stamp is "
              "interpolated between; frames in a longer gap get no pose.");
}

}  // namespace sightline
