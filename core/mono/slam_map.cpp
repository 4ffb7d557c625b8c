#include "core/mono/slam_map.h"

#include <algorithm>
#include <cmath>

namespace sightline {

std::vector<int> FrameFeatures::InWindow(double u, double v, double radius) const {
  std::vector<int> out;
  InWindow(u, v, radius, &out);
  return out;
}

void FrameFeatures::InWindow(double u, double v, double radius, std::vector<int>* out) const {
  out->clear();
  if (grid.empty()) return;
  const int c0 = std::max(0, static_cast<int>(std::floor((u - radius) / cell_px)));
  const int c1 = std::min(grid_columns - 1, static_cast<int>(std::floor((u + radius) / cell_px)));
  const int r0 = std::max(0, static_cast<int>(std::floor((v - radius) / cell_px)));
  const int r1 = std::min(grid_rows - 1, static_cast<int>(std::floor((v + radius) / cell_px)));
  const double r2 = radius * radius;
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      for (int i : grid[r * grid_columns + c]) {
        const double du = pixels[i].x() - u, dv = pixels[i].y() - v;
        if (du * du + dv * dv <= r2) out->push_back(i);
      }
    }
  }
}

int64_t SlamMap::AddPoint(MapPoint point) {
  point.id = next_point_id_++;
  const int64_t id = point.id;
  points_.emplace(id, std::move(point));
  return id;
}

int64_t SlamMap::AddKeyFrame(std::shared_ptr<KeyFrame> keyframe) {
  keyframe->id = next_keyframe_id_++;
  if (keyframe->point_ids.size() != keyframe->features.size()) {
    keyframe->point_ids.assign(keyframe->features.size(), -1);
  }
  keyframes_.push_back(std::move(keyframe));
  return keyframes_.back()->id;
}

MapPoint* SlamMap::FindPoint(int64_t id) {
  auto it = points_.find(id);
  return it == points_.end() ? nullptr : &it->second;
}

const MapPoint* SlamMap::FindPoint(int64_t id) const {
  auto it = points_.find(id);
  return it == points_.end() ? nullptr : &it->second;
}

KeyFrame* SlamMap::FindKeyFrame(int64_t id) {
  // Ids are assigned in order and keyframes are never removed, so the id is the index.
  if (id < 0 || id >= static_cast<int64_t>(keyframes_.size())) return nullptr;
  return keyframes_[id].get();
}

void SlamMap::AddObservation(int64_t point, int64_t keyframe, int index) {
  MapPoint* p = FindPoint(point);
  KeyFrame* k = FindKeyFrame(keyframe);
  if (p == nullptr || k == nullptr || index < 0 || index >= static_cast<int>(k->point_ids.size())) {
    return;
  }
  if (k->point_ids[index] >= 0 && k->point_ids[index] != point) return;  // Keypoint taken.
  if (p->observations.count(keyframe)) return;  // One observation per keyframe.
  k->point_ids[index] = point;
  p->observations[keyframe] = index;
}

void SlamMap::RemovePoint(int64_t point) {
  MapPoint* p = FindPoint(point);
  if (p == nullptr) return;
  for (const auto& [keyframe, index] : p->observations) {
    KeyFrame* k = FindKeyFrame(keyframe);
    if (k != nullptr && k->point_ids[index] == point) k->point_ids[index] = -1;
  }
  points_.erase(point);
}

void SlamMap::RemoveObservation(int64_t point, int64_t keyframe) {
  MapPoint* p = FindPoint(point);
  if (p == nullptr) return;
  auto it = p->observations.find(keyframe);
  if (it == p->observations.end()) return;
  KeyFrame* k = FindKeyFrame(keyframe);
  if (k != nullptr && k->point_ids[it->second] == point) k->point_ids[it->second] = -1;
  p->observations.erase(it);
  if (p->observations.size() < 2) RemovePoint(point);
}

void SlamMap::Clear() {
  points_.clear();
  keyframes_.clear();
  next_point_id_ = 0;
  next_keyframe_id_ = 0;
}

std::shared_ptr<const MapSnapshot> SnapshotOf(const SlamMap& map) {
  auto snapshot = std::make_shared<MapSnapshot>();
  snapshot->points.reserve(map.points().size());
  for (const auto& [id, p] : map.points()) {
    snapshot->points.push_back(
        {id, p.position, p.first_keyframe, static_cast<int>(p.observations.size())});
  }
  std::sort(snapshot->points.begin(), snapshot->points.end(),
            [](const MapSnapshot::Point& a, const MapSnapshot::Point& b) { return a.id < b.id; });
  for (const auto& k : map.keyframes()) {
    const int seen = static_cast<int>(std::count_if(k->point_ids.begin(), k->point_ids.end(),
                                                    [](int64_t id) { return id >= 0; }));
    snapshot->keyframes.push_back(
        {k->id, k->frame_index, k->time_s, k->camera_from_map.inverse(), seen});
  }
  return snapshot;
}

}  // namespace sightline
