#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <map>

#include "core/ros/bag_messages.h"
#include "core/ros/message_check.h"

namespace sightline {
namespace {

std::string FrameName(const std::string& frame) {
  return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
}

using FramePair = std::pair<std::string, std::string>;  // (parent, child) without leading '/'.

std::string PairText(const FramePair& pair) { return pair.first + " -> " + pair.second; }

Status AtMessage(const Status& status, const std::string& path, const std::string& topic,
                 int64_t index) {
  return status.WithContext(path + ": " + topic + " message " + std::to_string(index));
}

// Calls `take(parent, child, stamp, pose, is_static)` for every transform of the bag's tf topics
// (/tf_static too unless `dynamic_only`), in bag order; a transform without a stamp takes its
// message's record time. Errors name the bag, the topic and the message.
template <typename Take>
Status ForEachBagTransform(const rosbag::Bag& bag, const BagSummary& summary, bool dynamic_only,
                           Take take) {
  for (const BagTopic* topic : summary.OfType(kRosTfType)) {
    const bool is_static = topic->name.find("tf_static") != std::string::npos;
    if (is_static && dynamic_only) continue;
    int64_t index = 0;
    for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(topic->name))) {
      auto msg = InstantiateChecked<tf2_msgs::TFMessage>(m);
      if (!msg) {
        return ParseError(summary.path + ": " + topic->name + " message " + std::to_string(index) +
                          " is not a tf2_msgs/TFMessage");
      }
      for (const geometry_msgs::TransformStamped& t : msg->transforms) {
        StatusOr<Eigen::Isometry3d> pose =
            IsometryFromRos(t.transform.translation, t.transform.rotation);
        if (!pose.ok()) return AtMessage(pose.status(), summary.path, topic->name, index);
        const double stamp = t.header.stamp.isZero() ? m.getTime().toSec() : t.header.stamp.toSec();
        take(t.header.frame_id, t.child_frame_id, stamp, *pose, is_static);
      }
      ++index;
    }
  }
  return Status::Ok();
}

// Every transform on the bag's dynamic tf topics (not /tf_static), by frame pair.
StatusOr<std::map<FramePair, Trajectory>> ReadTransforms(const rosbag::Bag& bag,
                                                         const BagSummary& summary) {
  std::map<FramePair, Trajectory> edges;
  SIGHTLINE_RETURN_IF_ERROR(
      ForEachBagTransform(bag, summary, /*dynamic_only=*/true,
                          [&](const std::string& parent, const std::string& child, double stamp,
                              const Eigen::Isometry3d& pose, bool) {
                            edges[{FrameName(parent), FrameName(child)}].Add(stamp, pose);
                          }));
  for (auto& [pair, trajectory] : edges) {
    std::stable_sort(trajectory.mutable_poses().begin(), trajectory.mutable_poses().end(),
                     [](const TimedPose& a, const TimedPose& b) { return a.time_s < b.time_s; });
  }
  return edges;
}

std::string PairsText(const std::map<FramePair, Trajectory>& edges) {
  std::string text;
  for (const auto& [pair, trajectory] : edges) {
    text += (text.empty() ? "" : ", ") + PairText(pair) + " (" + std::to_string(trajectory.size()) +
            ")";
  }
  return text.empty() ? "none" : text;
}

}  // namespace

StatusOr<Trajectory> ReadBagOdometry(const rosbag::Bag& bag, const std::string& path,
                                     const std::string& topic) {
  Trajectory odometry;
  int64_t index = 0;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(topic))) {
    auto msg = InstantiateChecked<nav_msgs::Odometry>(m);
    if (!msg) {
      return ParseError(path + ": " + topic + " message " + std::to_string(index) +
                        " is not a nav_msgs/Odometry");
    }
    StatusOr<Eigen::Isometry3d> pose =
        IsometryFromRos(msg->pose.pose.position, msg->pose.pose.orientation);
    if (!pose.ok()) return AtMessage(pose.status(), path, topic, index);
    odometry.Add(msg->header.stamp.isZero() ? m.getTime().toSec() : msg->header.stamp.toSec(),
                 *pose);
    ++index;
  }
  std::stable_sort(odometry.mutable_poses().begin(), odometry.mutable_poses().end(),
                   [](const TimedPose& a, const TimedPose& b) { return a.time_s < b.time_s; });
  return odometry;
}

StatusOr<std::optional<Trajectory>> ReadBagTfGroundTruth(const rosbag::Bag& bag,
                                                         const BagSummary& summary,
                                                         const RosBagOptions& options,
                                                         const std::string& camera_frame,
                                                         std::vector<std::string>* notes) {
  StatusOr<std::map<FramePair, Trajectory>> edges = ReadTransforms(bag, summary);
  if (!edges.ok()) return edges.status();
  if (options.tf_parent_frame.empty()) {
    // The platform's odometry and the arm's pose are not a camera's ground truth.
    edges->erase({FrameName(options.odom_frame), FrameName(options.base_frame)});
    edges->erase({FrameName(options.arm_base_frame), FrameName(options.end_effector_frame)});
  }
  if (!options.tf_parent_frame.empty()) {
    const FramePair wanted{FrameName(options.tf_parent_frame), FrameName(options.tf_child_frame)};
    auto it = edges->find(wanted);
    if (it == edges->end()) {
      return InvalidArgument(summary.path + ": no transform " + PairText(wanted) +
                             " on /tf (io.rosbag.tf_parent_frame / tf_child_frame); the bag's " +
                             "transforms: " + PairsText(*edges));
    }
    notes->push_back("ground truth: tf " + PairText(wanted) + " (" +
                     std::to_string(it->second.size()) + " poses)");
    return std::optional<Trajectory>(it->second);
  }
  if (edges->size() == 1) {
    notes->push_back("ground truth: tf " + PairText(edges->begin()->first) + " (" +
                     std::to_string(edges->begin()->second.size()) +
                     " poses; the bag's only transform)");
    return std::optional<Trajectory>(edges->begin()->second);
  }
  for (const auto& [pair, trajectory] : *edges) {
    if (!camera_frame.empty() && pair.second == FrameName(camera_frame)) {
      notes->push_back("ground truth: tf " + PairText(pair) + " (" +
                       std::to_string(trajectory.size()) + " poses; the images' frame)");
      return std::optional<Trajectory>(trajectory);
    }
  }
  if (edges->size() > 1) {
    notes->push_back("no ground truth: several tf transforms (" + PairsText(*edges) +
                     "); choose with --set io.rosbag.tf_parent_frame=A --set "
                     "io.rosbag.tf_child_frame=B");
  }
  return std::optional<Trajectory>();
}

Status ReadBagTfBuffer(const rosbag::Bag& bag, const BagSummary& summary, TfBuffer* buffer) {
  return ForEachBagTransform(bag, summary, /*dynamic_only=*/false,
                             [&](const std::string& parent, const std::string& child, double stamp,
                                 const Eigen::Isometry3d& pose, bool is_static) {
                               buffer->Add(parent, child, stamp, pose, is_static);
                             });
}

StatusOr<Trajectory> TfPosesAtStamps(const TfBuffer& buffer, const std::string& path,
                                     const std::string& parent, const std::string& parent_key,
                                     const std::string& child, const std::string& child_key,
                                     const std::vector<double>& stamps, std::string* first_gap) {
  for (const auto& [frame, key] : {std::pair{parent, parent_key}, std::pair{child, child_key}}) {
    if (buffer.HasFrame(frame)) continue;
    std::string frames;
    for (const std::string& f : buffer.Frames()) frames += (frames.empty() ? "" : ", ") + f;
    return InvalidArgument(path + ": tf has no frame '" + FrameName(frame) + "' (" + key +
                           "); its frames: " + (frames.empty() ? "none" : frames));
  }
  Trajectory poses;
  for (double stamp : stamps) {
    StatusOr<Eigen::Isometry3d> pose = buffer.Lookup(parent, child, stamp);
    if (pose.ok()) {
      poses.Add(stamp, *pose);
    } else if (first_gap->empty()) {
      *first_gap = pose.status().message();
    }
  }
  return poses;
}

std::string FirstFrameId(const rosbag::Bag& bag, const std::string& topic) {
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(topic))) {
    boost::shared_ptr<RosStampOnly> header = m.instantiate<RosStampOnly>();
    return header ? header->frame_id : "";
  }
  return "";
}

}  // namespace sightline
