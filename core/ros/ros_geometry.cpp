#include "core/ros/ros_geometry.h"

#include "core/ros/ros_image.h"

namespace sightline {
namespace {

geometry_msgs::Quaternion QuaternionMessage(const Eigen::Matrix3d& rotation) {
  const Eigen::Quaterniond q(rotation);
  geometry_msgs::Quaternion out;
  out.x = q.x();
  out.y = q.y();
  out.z = q.z();
  out.w = q.w();
  return out;
}

}  // namespace

geometry_msgs::TransformStamped TransformMessage(const Eigen::Isometry3d& parent_from_child,
                                                 double stamp_s, const std::string& parent,
                                                 const std::string& child) {
  geometry_msgs::TransformStamped out;
  out.header.stamp = RosTimeFromSeconds(stamp_s);
  out.header.frame_id = parent;
  out.child_frame_id = child;
  const Eigen::Vector3d t = parent_from_child.translation();
  out.transform.translation.x = t.x();
  out.transform.translation.y = t.y();
  out.transform.translation.z = t.z();
  out.transform.rotation = QuaternionMessage(parent_from_child.rotation());
  return out;
}

nav_msgs::Odometry OdometryMessage(const Eigen::Isometry3d& parent_from_child, double stamp_s,
                                   const std::string& parent, const std::string& child) {
  nav_msgs::Odometry out;
  out.header.stamp = RosTimeFromSeconds(stamp_s);
  out.header.frame_id = parent;
  out.child_frame_id = child;
  const Eigen::Vector3d t = parent_from_child.translation();
  out.pose.pose.position.x = t.x();
  out.pose.pose.position.y = t.y();
  out.pose.pose.position.z = t.z();
  out.pose.pose.orientation = QuaternionMessage(parent_from_child.rotation());
  out.pose.covariance[0] = -1;  // Not estimated.
  out.twist.covariance[0] = -1;
  return out;
}

}  // namespace sightline
