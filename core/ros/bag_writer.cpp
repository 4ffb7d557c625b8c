#include "core/ros/bag_writer.h"

#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>

#include "core/ros/ros_geometry.h"
#include "core/ros/ros_image.h"

namespace sightline {
struct BagWriter::Impl {
  std::string path;
  rosbag::Bag bag;
  bool open = false;

  // Writes `msg`, turning what rosbag throws into a Status naming the bag and topic.
  template <typename T>
  Status Write(const std::string& topic, double time_s, const T& msg) {
    if (!open) return FailedPrecondition(path + ": the bag is closed");
    const ros::Time stamp = RosTimeFromSeconds(time_s);
    if (stamp.isZero()) {
      return InvalidArgument(path + ": " + topic + ": time " + std::to_string(time_s) +
                             " s is before the earliest time a bag holds");
    }
    try {
      bag.write(topic, stamp, msg);
    } catch (const std::exception& e) {
      return Unavailable(path + ": writing " + topic + " failed: " + e.what());
    }
    return Status::Ok();
  }
};

BagWriter::BagWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

BagWriter::~BagWriter() { (void)Close(); }

StatusOr<std::unique_ptr<BagWriter>> BagWriter::Create(const std::string& path,
                                                       const std::string& compression) {
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  if (compression != "none" && compression != "bz2" && compression != "lz4") {
    return InvalidArgument("bag compression '" + compression + "' is not one of none, bz2, lz4");
  }
  try {
    impl->bag.open(path, rosbag::bagmode::Write);
    if (compression == "bz2") impl->bag.setCompression(rosbag::compression::BZ2);
    if (compression == "lz4") impl->bag.setCompression(rosbag::compression::LZ4);
  } catch (const std::exception& e) {
    return Unavailable(path + ": cannot create the bag: " + e.what());
  }
  impl->open = true;
  return std::unique_ptr<BagWriter>(new BagWriter(std::move(impl)));
}

Status BagWriter::WriteImage(const std::string& topic, double time_s, const cv::Mat& image,
                             const std::string& frame_id) {
  StatusOr<sensor_msgs::Image> msg = EncodeRosImage(image, time_s, frame_id);
  if (!msg.ok()) return msg.status().WithContext(impl_->path + ": " + topic);
  return impl_->Write(topic, time_s, *msg);
}

Status BagWriter::WriteCameraInfo(const std::string& topic, double time_s,
                                  const PinholeCamera& camera, const std::string& frame_id,
                                  double baseline_m) {
  sensor_msgs::CameraInfo info = RosInfoFromCamera(camera, time_s, frame_id);
  info.P[3] = -camera.fx * baseline_m;
  return impl_->Write(topic, time_s, info);
}

Status BagWriter::WriteOdometry(const std::string& topic, double time_s,
                                const Eigen::Isometry3d& pose, const std::string& frame,
                                const std::string& child_frame) {
  return impl_->Write(topic, time_s, OdometryMessage(pose, time_s, frame, child_frame));
}

Status BagWriter::WriteTransform(double time_s, const std::string& parent_frame,
                                 const std::string& child_frame, const Eigen::Isometry3d& pose,
                                 bool is_static) {
  tf2_msgs::TFMessage msg;
  msg.transforms.push_back(TransformMessage(pose, time_s, parent_frame, child_frame));
  return impl_->Write(is_static ? "/tf_static" : "/tf", time_s, msg);
}

Status BagWriter::WriteRgbdFrame(double time_s, const cv::Mat& color, const cv::Mat& depth_m,
                                 const PinholeCamera& camera) {
  if (!color.empty()) {
    SIGHTLINE_RETURN_IF_ERROR(WriteImage("/camera/rgb/image_color", time_s, color, kRgbdFrameId));
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteImage("/camera/depth/image", time_s, depth_m, kRgbdFrameId));
  return WriteCameraInfo("/camera/rgb/camera_info", time_s, camera, kRgbdFrameId);
}

Status BagWriter::WriteStereoFrame(double time_s, const cv::Mat& left, const cv::Mat& right,
                                   const StereoRig& rig) {
  SIGHTLINE_RETURN_IF_ERROR(WriteImage("/stereo/left/image_raw", time_s, left, kLeftFrameId));
  SIGHTLINE_RETURN_IF_ERROR(WriteImage("/stereo/right/image_raw", time_s, right, kRightFrameId));
  SIGHTLINE_RETURN_IF_ERROR(
      WriteCameraInfo("/stereo/left/camera_info", time_s, rig.left, kLeftFrameId));
  return WriteCameraInfo("/stereo/right/camera_info", time_s, rig.right, kRightFrameId,
                         rig.BaselineM());
}

Status BagWriter::WriteMonoFrame(double time_s, const cv::Mat& image, const PinholeCamera& camera) {
  SIGHTLINE_RETURN_IF_ERROR(WriteImage("/mono/image_raw", time_s, image, kMonoFrameId));
  return WriteCameraInfo("/mono/camera_info", time_s, camera, kMonoFrameId);
}

Status BagWriter::Close() {
  if (!impl_ || !impl_->open) return Status::Ok();
  impl_->open = false;
  try {
    impl_->bag.close();
  } catch (const std::exception& e) {
    return Unavailable(impl_->path + ": closing the bag failed: " + e.what());
  }
  return Status::Ok();
}

}  // namespace sightline
