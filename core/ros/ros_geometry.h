// Poses as ROS 1 messages: tf transforms and nav_msgs/Odometry, shared by the bag writer and the
// node's publishers. Only core/ros and the ROS front ends include this header (it pulls ROS's
// message headers; its translation units are C++17).
#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>

#include <Eigen/Geometry>
#include <string>

namespace sightline {

// The transform `parent_from_child` as a tf message (header.frame_id = parent).
geometry_msgs::TransformStamped TransformMessage(const Eigen::Isometry3d& parent_from_child,
                                                 double stamp_s, const std::string& parent,
                                                 const std::string& child);
// A pose as nav_msgs/Odometry of `child` in `parent` (no twist, covariance left unknown: -1 on
// the diagonal's first element as REP 145 suggests for "not given").
nav_msgs::Odometry OdometryMessage(const Eigen::Isometry3d& parent_from_child, double stamp_s,
                                   const std::string& parent, const std::string& child);

}  // namespace sightline
