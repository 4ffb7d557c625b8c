// A tf tree in memory: transforms of /tf and /tf_static by (parent, child), looked up as a chain
// at a stamp. ROS-free (Eigen values; frame names compare without a leading '/'), so the bag
// reader and the live ros:// source share it; thread-safe (the live source's callbacks add while
// its reader looks up).
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

//   TfBuffer tf(0.5);
//   tf.Add("odom", "base_link", 10.0, odom_from_base, /*is_static=*/false);
//   StatusOr<Eigen::Isometry3d> pose = tf.Lookup("odom", "base_link", 10.05);
class TfBuffer {
 public:
  // `max_gap_s`: the largest time between the two samples a dynamic transform is interpolated
  // between.
  explicit TfBuffer(double max_gap_s = 0.5);

  // The pose of `child` in `parent` at `stamp_s`. A static transform holds at every time (the
  // latest one given wins). A child has one parent: a transform naming another parent replaces
  // the child's edge.
  void Add(const std::string& parent, const std::string& child, double stamp_s,
           const Eigen::Isometry3d& parent_from_child, bool is_static);

  // Whether any transform names `frame` as parent or child.
  bool HasFrame(const std::string& frame) const;
  // Every frame, in name order.
  std::vector<std::string> Frames() const;

  // parent_from_child at `stamp_s` through the tree (up from both frames to their common
  // ancestor). Dynamic edges interpolate between the samples bracketing the stamp: translation
  // linearly, rotation by slerp. NotFound when a frame is unknown or the two are not connected;
  // OutOfRange when the stamp is outside an edge's samples or its bracketing samples are more
  // than max_gap_s apart. Messages name the frames asked for, the edge and the stamp.
  StatusOr<Eigen::Isometry3d> Lookup(const std::string& parent, const std::string& child,
                                     double stamp_s) const;

 private:
  struct Edge {
    std::string parent;
    bool is_static = false;
    Eigen::Isometry3d static_pose = Eigen::Isometry3d::Identity();
    std::map<double, Eigen::Isometry3d> samples;  // By stamp.
  };
  // The frames from `frame` up to its root, `frame` first.
  std::vector<std::string> Ancestors(const std::string& frame) const;
  StatusOr<Eigen::Isometry3d> EdgeAt(const std::string& child, const Edge& edge, double stamp_s,
                                     const std::string& asked) const;

  const double max_gap_s_;
  mutable std::mutex mutex_;
  std::map<std::string, Edge> edges_;  // By child frame.
};

// `frame` without a leading '/'.
std::string TfFrameName(const std::string& frame);

}  // namespace sightline
