// Writes ROS bags (format 2.0) with rosbag: images, CameraInfo, odometry and tf transforms from
// Sightline's values. ROS-free header (pimpl); what rosbag throws comes back as a Status.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "core/common/camera.h"
#include "core/common/status.h"

namespace sightline {

//   StatusOr<std::unique_ptr<BagWriter>> bag = BagWriter::Create("x.bag", "lz4");
//   (*bag)->WriteImage("/camera/rgb/image_color", t, color, "camera_rgb");
//   SIGHTLINE_RETURN_IF_ERROR((*bag)->Close());
class BagWriter {
 public:
  // `compression`: "none", "bz2" or "lz4". InvalidArgument for another; Unavailable naming the
  // path when the file cannot be created.
  static StatusOr<std::unique_ptr<BagWriter>> Create(const std::string& path,
                                                     const std::string& compression = "none");
  ~BagWriter();

  // An Image message (mono8, bgr8, 16UC1 or 32FC1 from the matrix's type) stamped `time_s`.
  Status WriteImage(const std::string& topic, double time_s, const cv::Mat& image,
                    const std::string& frame_id);
  // A CameraInfo for `camera`; `baseline_m` > 0 makes it a right camera (P[3] = -fx * baseline).
  Status WriteCameraInfo(const std::string& topic, double time_s, const PinholeCamera& camera,
                         const std::string& frame_id, double baseline_m = 0);
  // nav_msgs/Odometry: the pose of `child_frame` in `frame`.
  Status WriteOdometry(const std::string& topic, double time_s, const Eigen::Isometry3d& pose,
                       const std::string& frame, const std::string& child_frame);
  // One transform on /tf (on /tf_static when `is_static`): the pose of `child_frame` in
  // `parent_frame`.
  Status WriteTransform(double time_s, const std::string& parent_frame,
                        const std::string& child_frame, const Eigen::Isometry3d& pose,
                        bool is_static = false);
  // One frame in Sightline's bag layout (the simulator's and the recorder's bags, TUM's topic
  // names), images and camera_info stamped `time_s`, with the frame ids below:
  //   RGB-D   /camera/rgb/image_color (bgr8; skipped when empty), /camera/depth/image (32FC1
  //           metres), /camera/rgb/camera_info
  //   stereo  /stereo/{left,right}/image_raw and /stereo/{left,right}/camera_info (the right
  //           one's P carries the baseline)
  //   mono    /mono/image_raw, /mono/camera_info
  static constexpr const char* kRgbdFrameId = "camera_rgb_optical_frame";
  static constexpr const char* kLeftFrameId = "stereo_left";
  static constexpr const char* kRightFrameId = "stereo_right";
  static constexpr const char* kMonoFrameId = "mono_camera";
  Status WriteRgbdFrame(double time_s, const cv::Mat& color, const cv::Mat& depth_m,
                        const PinholeCamera& camera);
  Status WriteStereoFrame(double time_s, const cv::Mat& left, const cv::Mat& right,
                          const StereoRig& rig);
  Status WriteMonoFrame(double time_s, const cv::Mat& image, const PinholeCamera& camera);
  // Writes the index; the bag is complete after it. Also done by the destructor.
  Status Close();

 private:
  struct Impl;
  explicit BagWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace sightline
