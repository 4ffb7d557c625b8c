// The button pipeline on ROS: the operator's commands arrive as topics and reach the pipeline
// through ButtonCommands (as the GUI's operator panel's do); targets leave only as the
// pipeline's gate lets them out (the same gate as the arm-target server's).
//
// Subscribed (the node's namespace):
//   button_tap     geometry_msgs/PointStamped  the operator's tap: point.x, point.y the pixel,
//                                               header.stamp the stamp of the image tapped on
//   button_confirm std_msgs/Empty              the operator's Yes to the candidate
//   button_cancel  std_msgs/Empty              forgets the candidate or target
//   button_stop    std_msgs/String             STOP (latched until button_start); data = reason
//   button_start   std_msgs/Empty              lifts STOP
#pragma once

#include <ros/node_handle.h>

#include <memory>

#include "app/node/node_publishers.h"
#include "core/pipeline/button_result.h"

namespace sightline::node {

// The images the pipeline saw lately: sensor time -> frame id (stream index), so that a tap's
// image stamp names its frame. Thread-safe (the loop adds, the tap callback looks up).
class SeenStamps;

// Operator topics and the button's publishers (its SLAM's too: odom, map_points, keyframes).
std::unique_ptr<ResultPublisher> MakeButtonPublisher(const StatisticTable& table,
                                                     ros::NodeHandle& nh, const RosFrames& frames,
                                                     std::shared_ptr<ButtonCommands> commands);

}  // namespace sightline::node
