#include "core/mono/loop_closer.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace sightline {

Eigen::Isometry3d MapCorrection::CorrectPose(const Eigen::Isometry3d& camera_from_map) const {
  // x_camera' = scale * x_camera: the camera sees the same scene in the corrected units.
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = camera_from_map.rotation() * rotation.transpose();
  out.translation() = scale * camera_from_map.translation() - out.linear() * translation;
  return out;
}

MapCorrection MapCorrection::Partial(double fraction, const Eigen::Vector3d& centre) const {
  MapCorrection out;
  out.scale = std::pow(scale, fraction);
  out.rotation = Eigen::Quaterniond::Identity()
                     .slerp(fraction, Eigen::Quaterniond(rotation))
                     .normalized()
                     .toRotationMatrix();
  out.translation =
      centre + fraction * (Apply(centre) - centre) - out.scale * out.rotation * centre;
  return out;
}

LoopCloser::LoopCloser(const MonoMappingOptions& mapping, const MonoTrackingOptions& tracking,
                       const PinholeCamera& camera, double scale_factor)
    : options_(mapping), tracker_(tracking, camera, scale_factor) {}

namespace {

// The optical axis in map coordinates.
Eigen::Vector3d AxisOf(const KeyFrame& k) {
  return k.camera_from_map.rotation().row(2).transpose();
}

double MedianDepth(const SlamMap& map, const KeyFrame& k) {
  std::vector<double> depths;
  for (int64_t id : k.point_ids) {
    const MapPoint* p = id >= 0 ? map.FindPoint(id) : nullptr;
    if (p != nullptr) depths.push_back((k.camera_from_map * p->position).z());
  }
  if (depths.size() < 10) return 0;
  std::nth_element(depths.begin(), depths.begin() + depths.size() / 2, depths.end());
  return depths[depths.size() / 2];
}

}  // namespace

std::optional<LoopMatch> LoopCloser::Detect(const SlamMap& map, const KeyFrame& keyframe) const {
  const int64_t oldest_new = keyframe.id - options_.loop_min_age;  // Older ids are "old".
  if (options_.loop_search_radius <= 0 || oldest_new <= 0) return std::nullopt;
  int old_points = 0;
  for (int64_t id : keyframe.point_ids) {
    const MapPoint* p = id >= 0 ? map.FindPoint(id) : nullptr;
    if (p != nullptr && p->first_keyframe < oldest_new) ++old_points;
  }
  if (old_points >= options_.loop_min_inliers / 2) return std::nullopt;  // Tracks the old map.
  const double depth = MedianDepth(map, keyframe);
  if (depth <= 0) return std::nullopt;
  const Eigen::Vector3d centre = keyframe.CentreInMap(), axis = AxisOf(keyframe);
  // A revisit is a return after a long way round: the path since the old keyframe must be
  // kPathFactor times the search radius (a camera moving on along a corridor still sees what
  // older keyframes saw, and is no revisit).
  constexpr double kPathFactor = 5.0;
  const auto& keyframes = map.keyframes();
  std::vector<double> path_to_current(keyframe.id + 1, 0);
  for (int64_t k = keyframe.id - 1; k >= 0; --k) {
    path_to_current[k] = path_to_current[k + 1] +
                         (keyframes[k + 1]->CentreInMap() - keyframes[k]->CentreInMap()).norm();
  }
  const double radius = options_.loop_search_radius * depth;
  std::vector<std::pair<double, const KeyFrame*>> candidates;
  for (const auto& k : keyframes) {
    if (k->id >= oldest_new) break;
    const double distance = (k->CentreInMap() - centre).norm();
    if (distance > radius || path_to_current[k->id] < kPathFactor * radius) continue;
    if (AxisOf(*k).dot(axis) < std::cos(45.0 * M_PI / 180.0)) continue;
    candidates.emplace_back(distance, k.get());
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  constexpr int kCandidates = 3, kNeighbourhood = 5;
  for (int c = 0; c < std::min<int>(kCandidates, candidates.size()); ++c) {
    const KeyFrame& partner = *candidates[c].second;
    std::vector<LocalPoint> seen, around;
    std::set<int64_t> ids;
    for (int64_t k = std::max<int64_t>(0, partner.id - kNeighbourhood);
         k <= std::min(oldest_new - 1, partner.id + kNeighbourhood); ++k) {
      for (int64_t id : map.keyframes()[k]->point_ids) {
        if (id >= 0) ids.insert(id);
      }
    }
    for (int64_t id : ids) {
      const MapPoint* p = map.FindPoint(id);
      if (p != nullptr && p->first_keyframe < oldest_new) {
        around.push_back({id, p->position, p->descriptor});
        if (p->observations.count(partner.id)) seen.push_back(around.back());
      }
    }
    TrackOutcome outcome;
    if (!tracker_.Relocalise(keyframe.features, partner, seen, around, &outcome) ||
        outcome.inliers < options_.loop_min_inliers) {
      continue;
    }
    // Scale: the depth of the old points over that of the new points at the same keypoints.
    LoopMatch loop;
    std::vector<double> ratios;
    for (const PointMatch& m : outcome.matches) {
      if (!m.inlier) continue;
      loop.matches.emplace_back(m.keypoint, m.point);
      const int64_t mine = keyframe.point_ids[m.keypoint];
      const MapPoint* p = mine >= 0 && mine != m.point ? map.FindPoint(mine) : nullptr;
      const MapPoint* q = map.FindPoint(m.point);
      if (p == nullptr || q == nullptr) continue;
      const double z_new = (keyframe.camera_from_map * p->position).z();
      const double z_old = (outcome.camera_from_map * q->position).z();
      if (z_new > 0 && z_old > 0) ratios.push_back(z_old / z_new);
    }
    if (ratios.size() < 10) continue;
    std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
    const double s = ratios[ratios.size() / 2];
    // x_old = old_from_camera(s * camera_from_new(x)).
    const Eigen::Isometry3d& cur = keyframe.camera_from_map;
    const Eigen::Isometry3d& old = outcome.camera_from_map;
    loop.correction.scale = s;
    loop.correction.rotation = old.rotation().transpose() * cur.rotation();
    loop.correction.translation =
        old.rotation().transpose() * (s * cur.translation() - old.translation());
    loop.keyframe = keyframe.id;
    loop.partner = partner.id;
    loop.inliers = outcome.inliers;
    return loop;
  }
  return std::nullopt;
}

int LoopCloser::Apply(const LoopMatch& loop, SlamMap* map) const {
  // The drift grew along the path since the partner: each keyframe gets the share of the
  // correction of its share of that path.
  const auto& keyframes = map->keyframes();
  std::vector<double> along(keyframes.size(), 0);
  for (int64_t k = loop.partner + 1; k <= loop.keyframe; ++k) {
    along[k] =
        along[k - 1] + (keyframes[k]->CentreInMap() - keyframes[k - 1]->CentreInMap()).norm();
  }
  const double total = along[loop.keyframe];
  std::vector<MapCorrection> corrections(keyframes.size());
  for (int64_t k = loop.partner + 1; k <= loop.keyframe; ++k) {
    const double fraction = total > 0 ? along[k] / total : 1.0;
    corrections[k] = loop.correction.Partial(fraction, keyframes[k]->CentreInMap());
  }
  for (auto& [id, p] : map->points()) {
    if (p.first_keyframe > loop.partner && p.first_keyframe <= loop.keyframe) {
      p.position = corrections[p.first_keyframe].Apply(p.position);
    }
  }
  for (int64_t k = loop.partner + 1; k <= loop.keyframe; ++k) {
    keyframes[k]->camera_from_map = corrections[k].CorrectPose(keyframes[k]->camera_from_map);
  }
  // The new keyframe's points become the old points they matched.
  int merged = 0;
  KeyFrame* current = map->FindKeyFrame(loop.keyframe);
  for (const auto& [keypoint, old_id] : loop.matches) {
    if (map->FindPoint(old_id) == nullptr) continue;
    const int64_t mine = current->point_ids[keypoint];
    if (mine == old_id) continue;
    std::map<int64_t, int> observations;
    if (const MapPoint* p = mine >= 0 ? map->FindPoint(mine) : nullptr) {
      observations = p->observations;
      map->RemovePoint(mine);
    }
    observations[loop.keyframe] = keypoint;
    for (const auto& [k, index] : observations) map->AddObservation(old_id, k, index);
    ++merged;
  }
  return merged;
}

}  // namespace sightline
