#include "core/mono/metric_motion.h"

#include <map>

namespace sightline {

std::vector<ScalePair> DisplacementPairs(const std::vector<DualPose>& frames, int interval_frames) {
  std::vector<ScalePair> pairs;
  if (interval_frames < 1) return pairs;
  std::map<int64_t, const DualPose*> by_frame;
  for (const DualPose& f : frames) {
    if (f.map_from_camera && f.metric_from_camera) by_frame[f.frame] = &f;
  }
  if (by_frame.empty()) return pairs;
  const int64_t first = by_frame.begin()->first, last = by_frame.rbegin()->first;
  for (int64_t i = first; i + interval_frames <= last; i += interval_frames) {
    auto a = by_frame.find(i), b = by_frame.find(i + interval_frames);
    if (a == by_frame.end() || b == by_frame.end()) continue;
    const Eigen::Isometry3d& ma = *a->second->map_from_camera;
    const Eigen::Isometry3d& mb = *b->second->map_from_camera;
    const Eigen::Isometry3d& ya = *a->second->metric_from_camera;
    const Eigen::Isometry3d& yb = *b->second->metric_from_camera;
    ScalePair p;
    p.map_displacement = ma.rotation().transpose() * (mb.translation() - ma.translation());
    p.metric_displacement = ya.rotation().transpose() * (yb.translation() - ya.translation());
    pairs.push_back(p);
  }
  return pairs;
}

}  // namespace sightline
