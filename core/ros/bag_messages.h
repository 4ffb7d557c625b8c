// The ROS side of the rosbag reader: opening a bag without letting an exception out, its table
// of contents, stamps read without decoding a message, and PointCloud2 / Odometry / tf poses as
// Sightline values. Only core/ros's .cpp files include this header (it pulls ROS headers).
#pragma once

#include <geometry_msgs/Transform.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/PointCloud2.h>

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/common/trajectory.h"
#include "core/ros/bag_topics.h"
#include "core/ros/tf_buffer.h"

namespace sightline {

// The header's stamp of any message that starts with a std_msgs/Header, read without decoding
// the rest (rosbag deserializes straight from the chunk it keeps decompressed).
struct RosStampOnly {
  uint32_t seq = 0;
  ros::Time stamp;
  std::string frame_id;
};

// Opens `path` for reading after ReadBagFileLayout() found it sound. ParseError "x.bag: rosbag
// cannot read it: <reason>" for anything rosbag throws.
StatusOr<std::unique_ptr<rosbag::Bag>> OpenBagForReading(const std::string& path,
                                                         BagFileLayout* layout);

// The table of contents of an open bag (topics sorted by name, image encodings from each image
// topic's first message). Errors name the bag and the topic.
StatusOr<BagSummary> SummarizeBag(const rosbag::Bag& bag, const std::string& path,
                                  const BagFileLayout& layout);

// The stamp of a message: its header's, or the time it was recorded when the header's is zero
// or the type has no header.
double MessageStampS(const rosbag::MessageInstance& message);

// A PointCloud2 with float32 x, y, z (and an optional packed rgb field) as a point cloud;
// organized when height > 1. InvalidArgument naming the field for other layouts.
StatusOr<PointCloud> CloudFromRos(const sensor_msgs::PointCloud2& msg);

// A geometry_msgs pose or transform as an isometry; InvalidArgument for a zero or non-finite
// quaternion or translation.
StatusOr<Eigen::Isometry3d> IsometryFromRos(const geometry_msgs::Vector3& t,
                                            const geometry_msgs::Quaternion& q);
StatusOr<Eigen::Isometry3d> IsometryFromRos(const geometry_msgs::Point& t,
                                            const geometry_msgs::Quaternion& q);

}  // namespace sightline

namespace ros {
namespace message_traits {
template <>
struct MD5Sum<sightline::RosStampOnly> {
  static const char* value() { return "*"; }
  static const char* value(const sightline::RosStampOnly&) { return "*"; }
};
template <>
struct DataType<sightline::RosStampOnly> {
  static const char* value() { return "*"; }
  static const char* value(const sightline::RosStampOnly&) { return "*"; }
};
template <>
struct Definition<sightline::RosStampOnly> {
  static const char* value() { return ""; }
  static const char* value(const sightline::RosStampOnly&) { return ""; }
};
}  // namespace message_traits
namespace serialization {
template <>
struct Serializer<sightline::RosStampOnly> {
  template <typename Stream>
  inline static void read(Stream& stream, sightline::RosStampOnly& m) {
    stream.next(m.seq);
    stream.next(m.stamp);
    stream.next(m.frame_id);
  }
};
}  // namespace serialization
}  // namespace ros

namespace sightline {

// The poses of a nav_msgs/Odometry topic (pose of child_frame_id in header.frame_id), at their
// header stamps, in time order. Errors name the bag, topic and message index.
StatusOr<Trajectory> ReadBagOdometry(const rosbag::Bag& bag, const std::string& path,
                                     const std::string& topic);

// The ground truth of a bag from its /tf (tf2_msgs/TFMessage) topics: the pose of
// options.tf_child_frame in options.tf_parent_frame when they are given (InvalidArgument listing
// the bag's transforms when there is no such transform), else the only parent -> child pair on
// the dynamic tf topics (not counting the odometry's and the arm's: odom_frame -> base_frame,
// arm_base_frame -> end_effector_frame), or among several the one whose child is `camera_frame`
// (the images' header frame_id); nullopt when there is none or no rule picks one (a note then says
// which options choose). Frame names compare without a leading '/'.
StatusOr<std::optional<Trajectory>> ReadBagTfGroundTruth(const rosbag::Bag& bag,
                                                         const BagSummary& summary,
                                                         const RosBagOptions& options,
                                                         const std::string& camera_frame,
                                                         std::vector<std::string>* notes);

// Every transform of the bag's /tf and /tf_static (tf2_msgs/TFMessage) topics into `buffer`
// (topics whose name says tf_static as static transforms). Errors name the bag, topic, message.
Status ReadBagTfBuffer(const rosbag::Bag& bag, const BagSummary& summary, TfBuffer* buffer);

// The pose of `child` in `parent` at each of `stamps` from `buffer`, skipping stamps tf does not
// cover (the first such lookup's message in *first_gap). Without either frame in the buffer:
// InvalidArgument "x.bag: tf has no frame 'base_link' (io.rosbag.base_frame); its frames: ...".
StatusOr<Trajectory> TfPosesAtStamps(const TfBuffer& buffer, const std::string& path,
                                     const std::string& parent, const std::string& parent_key,
                                     const std::string& child, const std::string& child_key,
                                     const std::vector<double>& stamps, std::string* first_gap);

// The header frame_id of a topic's first message ("" when none).
std::string FirstFrameId(const rosbag::Bag& bag, const std::string& topic);

}  // namespace sightline
