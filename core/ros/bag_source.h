// A ROS bag (format 2.0, uncompressed, bz2 or lz4 chunks) as a Sightline source, read with
// rosbag. ROS-free header: the driver registry (C++20) includes it; ROS stays in the .cpp files.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/common/trajectory.h"
#include "core/io/recorded_source.h"
#include "core/io/rosbag_options.h"
#include "core/ros/bag_topics.h"

namespace sightline {

// Frames from a bag's topics, chosen by RosBagOptions (ChooseBagTopics): RGB-D (a colour and a
// depth topic paired by nearest stamp, as the TUM reader pairs its lists), stereo (left/right
// paired by stamp; the right CameraInfo's P gives the baseline), mono images or point clouds.
// Images: sensor_msgs/Image (mono8, rgb8, bgr8, rgba8, bgra8, 16UC1, mono16, 32FC1) and
// CompressedImage (jpeg, png); the camera from the image's CameraInfo topic. Frame times are the
// messages' header stamps. Ground truth: the pose of tf_child_frame in tf_parent_frame on /tf,
// or the bag's only /tf transform, else an Odometry topic whose name says ground_truth.
// Seekable: Open() indexes every frame's messages; Retrieve() decodes one frame.
//
// Errors name the bag, the topic and the message index within the topic:
// "tum.bag: /camera/depth/image message 3: unsupported encoding 'yuv422' (supported: ...)".
// Nothing rosbag throws leaves this class.
//
//   BagSource source("../shared/data/rosbags/tum_fr1_desk.bag");
//   if (Status s = source.Open(); !s.ok()) return s;
//   while (source.Grab().ok()) auto frame = source.Retrieve();  // RgbdFrame
class BagSource : public RecordedSource {
 public:
  explicit BagSource(std::string path, RosBagOptions options = RosBagOptions());
  ~BagSource() override;

  // rosbag is linked in: always Ok.
  static Status Available() { return Status::Ok(); }

  Status Open() override;
  void Close() override;

  // What Open() found: the bag's topics, and the topics the frames come from.
  const BagSummary& summary() const;
  const BagTopicChoice& choice() const;
  // The poses of choice().odometry (world_from_base in the odometry's frame); null when none.
  // Without an odometry topic, the poses of io.rosbag.base_frame in odom_frame on tf.
  const Trajectory* odometry() const override;
  // base_from_end_effector (io.rosbag.arm_base_frame -> end_effector_frame on tf) at the frames'
  // stamps, when tf names the end effector; null otherwise.
  const Trajectory* arm_poses() const override;

 protected:
  StatusOr<Frame> Load(int64_t index) override;
  std::string FrameFile(int64_t index) const override;

 private:
  struct Impl;
  // Open() and Load() without the catch of everything rosbag throws.
  Status OpenBag();
  StatusOr<Frame> LoadFrame(int64_t index);
  // Steps of OpenBag(): which messages make each frame; the cameras; ground truth and odometry.
  void PairFrames(SourceInfo* info);
  Status ReadCalibration(SourceInfo* info);
  Status ReadPoses(SourceInfo* info, std::optional<Trajectory>* ground_truth);
  Status ReadTfPoses(SourceInfo* info);
  const std::string path_;
  const RosBagOptions options_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sightline
