#include "core/ros/tf_buffer.h"

#include <algorithm>
#include <cstdio>
#include <set>

namespace sightline {
namespace {

std::string StampText(double stamp_s) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3f s", stamp_s);
  return text;
}

Eigen::Isometry3d Interpolate(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double f) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  const Eigen::Quaterniond qa(a.rotation()), qb(b.rotation());
  out.linear() = qa.slerp(f, qb).normalized().toRotationMatrix();
  out.translation() = (1 - f) * a.translation() + f * b.translation();
  return out;
}

}  // namespace

std::string TfFrameName(const std::string& frame) {
  return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame;
}

TfBuffer::TfBuffer(double max_gap_s) : max_gap_s_(max_gap_s) {}

void TfBuffer::Add(const std::string& parent, const std::string& child, double stamp_s,
                   const Eigen::Isometry3d& parent_from_child, bool is_static) {
  std::lock_guard<std::mutex> lock(mutex_);
  Edge& edge = edges_[TfFrameName(child)];
  const std::string p = TfFrameName(parent);
  if (edge.parent != p || edge.is_static != is_static) {
    edge = Edge();
    edge.parent = p;
    edge.is_static = is_static;
  }
  if (is_static) {
    edge.static_pose = parent_from_child;
  } else {
    edge.samples[stamp_s] = parent_from_child;
  }
}

bool TfBuffer::HasFrame(const std::string& frame) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::string f = TfFrameName(frame);
  if (edges_.count(f) > 0) return true;
  for (const auto& [child, edge] : edges_) {
    if (edge.parent == f) return true;
  }
  return false;
}

std::vector<std::string> TfBuffer::Frames() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::set<std::string> frames;
  for (const auto& [child, edge] : edges_) {
    frames.insert(child);
    frames.insert(edge.parent);
  }
  return {frames.begin(), frames.end()};
}

std::vector<std::string> TfBuffer::Ancestors(const std::string& frame) const {
  std::vector<std::string> out{frame};
  for (auto it = edges_.find(frame); it != edges_.end(); it = edges_.find(it->second.parent)) {
    if (std::find(out.begin(), out.end(), it->second.parent) != out.end()) break;  // A loop.
    out.push_back(it->second.parent);
  }
  return out;
}

StatusOr<Eigen::Isometry3d> TfBuffer::EdgeAt(const std::string& child, const Edge& edge,
                                             double stamp_s, const std::string& asked) const {
  if (edge.is_static) return edge.static_pose;
  const std::string what =
      asked + " at " + StampText(stamp_s) + ": the transform " + edge.parent + " -> " + child;
  if (edge.samples.empty()) return NotFound(what + " has no samples");
  const double first = edge.samples.begin()->first, last = edge.samples.rbegin()->first;
  if (stamp_s < first || stamp_s > last) {
    return OutOfRange(what + " is known only from " + StampText(first) + " to " + StampText(last));
  }
  auto after = edge.samples.lower_bound(stamp_s);
  if (after->first == stamp_s) return after->second;
  auto before = std::prev(after);
  const double gap = after->first - before->first;
  if (gap > max_gap_s_) {
    return OutOfRange(what + " has samples " + StampText(gap) + " apart there (" +
                      StampText(before->first) + ", " + StampText(after->first) +
                      "), more than the largest gap " + StampText(max_gap_s_));
  }
  return Interpolate(before->second, after->second, (stamp_s - before->first) / gap);
}

StatusOr<Eigen::Isometry3d> TfBuffer::Lookup(const std::string& parent, const std::string& child,
                                             double stamp_s) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::string p = TfFrameName(parent), c = TfFrameName(child);
  const std::string asked = "tf " + p + " -> " + c;
  for (const std::string& f : {p, c}) {
    bool known = edges_.count(f) > 0;
    for (const auto& [name, edge] : edges_) known = known || edge.parent == f;
    if (!known) return NotFound(asked + ": no transform names the frame '" + f + "'");
  }
  const std::vector<std::string> up_c = Ancestors(c), up_p = Ancestors(p);
  size_t ic = 0, ip = up_p.size();
  for (; ic < up_c.size(); ++ic) {
    auto it = std::find(up_p.begin(), up_p.end(), up_c[ic]);
    if (it != up_p.end()) {
      ip = size_t(it - up_p.begin());
      break;
    }
  }
  if (ic == up_c.size()) {
    return NotFound(asked + ": the frames are not connected (" + c + "'s root is " + up_c.back() +
                    ", " + p + "'s is " + up_p.back() + ")");
  }
  // ancestor_from_child and ancestor_from_parent, composed edge by edge.
  auto chain = [&](const std::vector<std::string>& up, size_t n) -> StatusOr<Eigen::Isometry3d> {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    for (size_t i = 0; i < n; ++i) {
      StatusOr<Eigen::Isometry3d> edge = EdgeAt(up[i], edges_.at(up[i]), stamp_s, asked);
      if (!edge.ok()) return edge.status();
      pose = *edge * pose;
    }
    return pose;
  };
  StatusOr<Eigen::Isometry3d> from_child = chain(up_c, ic);
  if (!from_child.ok()) return from_child.status();
  StatusOr<Eigen::Isometry3d> from_parent = chain(up_p, ip);
  if (!from_parent.ok()) return from_parent.status();
  return Eigen::Isometry3d(from_parent->inverse() * *from_child);
}

}  // namespace sightline
