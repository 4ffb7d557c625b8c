#include "core/mono/local_mapper.h"

#include <cmath>
#include <set>
#include <unordered_map>

#include "core/mono/features.h"

namespace sightline {

LocalMapper::LocalMapper(const MonoMappingOptions& options, const PinholeCamera& camera,
                         double scale_factor, SlamMap* map, std::mutex* map_mutex)
    : options_(options),
      camera_(camera),
      scale_factor_(scale_factor),
      map_(map),
      mutex_(map_mutex) {}

namespace {

double Scale(double factor, const cv::KeyPoint& k) { return std::pow(factor, k.octave); }

Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

}  // namespace

KeyFrameStats LocalMapper::ProcessKeyFrame(const std::shared_ptr<KeyFrame>& keyframe) {
  KeyFrameStats stats;
  const double start = HostTimeS();
  KeyFrame* current = keyframe.get();
  std::vector<int64_t> matched = keyframe->point_ids;
  {
    std::lock_guard<std::mutex> lock(*mutex_);
    keyframe->point_ids.assign(keyframe->features.size(), -1);
    stats.keyframe = map_->AddKeyFrame(keyframe);
    for (size_t i = 0; i < matched.size(); ++i) {
      if (matched[i] >= 0) map_->AddObservation(matched[i], stats.keyframe, static_cast<int>(i));
    }
  }
  std::vector<KeyFrame*> neighbours;
  const auto& all = map_->keyframes();
  for (int k = static_cast<int>(all.size()) - 2;
       k >= 0 && static_cast<int>(neighbours.size()) < options_.neighbours; --k) {
    neighbours.push_back(all[k].get());
  }
  stats.fused = FuseNeighbourPoints(current, neighbours);
  for (KeyFrame* n : neighbours) stats.new_points += TriangulateWith(current, *n);
  const double ba_start = HostTimeS();
  stats.ba_outliers = LocalBundle(&stats);
  stats.bundle_ms = (HostTimeS() - ba_start) * 1000.0;
  stats.culled = Cull(stats.keyframe);
  MapChanged();
  stats.mapping_ms = (HostTimeS() - start) * 1000.0;
  return stats;
}

int LocalMapper::FuseNeighbourPoints(KeyFrame* current, const std::vector<KeyFrame*>& neighbours) {
  std::set<int64_t> candidates;
  for (const KeyFrame* n : neighbours) {
    for (int64_t id : n->point_ids) {
      if (id >= 0) candidates.insert(id);
    }
  }
  const FrameFeatures& f = current->features;
  std::vector<std::pair<int64_t, int>> found;
  std::vector<bool> taken(f.size(), false);
  for (size_t i = 0; i < current->point_ids.size(); ++i) taken[i] = current->point_ids[i] >= 0;
  for (int64_t id : candidates) {
    const MapPoint* p = map_->FindPoint(id);
    if (p == nullptr || p->observations.count(current->id)) continue;
    const Eigen::Vector3d x = current->camera_from_map * p->position;
    if (x.z() <= 0) continue;
    const Eigen::Vector2d uv = ProjectToPixel(camera_, x);
    int best = options_.max_descriptor_distance + 1, best_k = -1;
    const uint8_t* dp = p->descriptor.ptr<uint8_t>();
    for (int k : f.InWindow(uv.x(), uv.y(), 3.0 * options_.epipolar_px)) {
      if (taken[k]) continue;
      if ((f.pixels[k] - uv).norm() >
          options_.max_reprojection_px * Scale(scale_factor_, f.keypoints[k]))
        continue;
      const int d = DescriptorDistance(dp, f.descriptors.ptr<uint8_t>(k));
      if (d < best) {
        best = d;
        best_k = k;
      }
    }
    if (best_k >= 0) {
      taken[best_k] = true;
      found.emplace_back(id, best_k);
    }
  }
  std::lock_guard<std::mutex> lock(*mutex_);
  for (const auto& [id, k] : found) map_->AddObservation(id, current->id, k);
  return static_cast<int>(found.size());
}

int LocalMapper::TriangulateWith(KeyFrame* current, const KeyFrame& neighbour) {
  const FrameFeatures& a = current->features;
  const FrameFeatures& b = neighbour.features;
  const Eigen::Isometry3d b_from_a = neighbour.camera_from_map * current->camera_from_map.inverse();
  const Eigen::Vector3d centre_a = current->CentreInMap(), centre_b = neighbour.CentreInMap();
  if ((centre_a - centre_b).norm() < 1e-9) return 0;
  // Fundamental matrix from a to b: x_b^T F x_a = 0 in pixels.
  const Eigen::Matrix3d K = camera_.K();
  const Eigen::Matrix3d E = Skew(b_from_a.translation()) * b_from_a.rotation();
  const Eigen::Matrix3d F = K.inverse().transpose() * E * K.inverse();
  std::vector<bool> b_taken(b.size(), false);
  for (size_t j = 0; j < b.size(); ++j) b_taken[j] = neighbour.point_ids[j] >= 0;
  struct NewPoint {
    int a, b;
    Eigen::Vector3d x;
  };
  std::vector<NewPoint> created;
  for (size_t i = 0; i < a.size(); ++i) {
    if (current->point_ids[i] >= 0) continue;
    const Eigen::Vector3d line = F * a.pixels[i].homogeneous();
    const double norm = line.head<2>().norm();
    if (norm < 1e-12) continue;
    int best = options_.max_descriptor_distance + 1, second = 1 << 30, best_j = -1;
    const uint8_t* da = a.descriptors.ptr<uint8_t>(static_cast<int>(i));
    for (size_t j = 0; j < b.size(); ++j) {
      if (b_taken[j]) continue;
      const double distance = std::abs(line.dot(b.pixels[j].homogeneous())) / norm;
      if (distance > options_.epipolar_px * Scale(scale_factor_, b.keypoints[j])) continue;
      const int d = DescriptorDistance(da, b.descriptors.ptr<uint8_t>(static_cast<int>(j)));
      if (d < best) {
        second = best;
        best = d;
        best_j = static_cast<int>(j);
      } else if (d < second) {
        second = d;
      }
    }
    if (best_j < 0 || (second < (1 << 30) && best > 0.8 * second)) continue;
    Eigen::Vector3d x;
    if (!Triangulate(current->camera_from_map, neighbour.camera_from_map,
                     Normalised(camera_, a.pixels[i]), Normalised(camera_, b.pixels[best_j]), &x)) {
      continue;
    }
    if (!AcceptTriangulated(camera_, x, current->camera_from_map, neighbour.camera_from_map,
                            a.pixels[i], b.pixels[best_j], Scale(scale_factor_, a.keypoints[i]),
                            Scale(scale_factor_, b.keypoints[best_j]), options_.min_parallax_deg,
                            options_.max_reprojection_px)) {
      continue;
    }
    b_taken[best_j] = true;
    created.push_back({static_cast<int>(i), best_j, x});
  }
  std::lock_guard<std::mutex> lock(*mutex_);
  for (const NewPoint& n : created) {
    MapPoint p;
    p.position = n.x;
    p.descriptor = a.descriptors.row(n.a).clone();
    p.first_keyframe = current->id;
    const int64_t id = map_->AddPoint(std::move(p));
    map_->AddObservation(id, current->id, n.a);
    map_->AddObservation(id, neighbour.id, n.b);
  }
  return static_cast<int>(created.size());
}

int LocalMapper::LocalBundle(KeyFrameStats* stats) {
  const int n = static_cast<int>(map_->keyframes().size());
  IdleBundleStats window =
      AdjustWindow(std::max(0, n - options_.local_window), n, options_.ba_iterations);
  stats->bundle = window.bundle;
  return window.removed;
}

IdleBundleStats LocalMapper::AdjustWindow(int first_free, int end, int iterations,
                                          const std::function<bool()>& should_stop) {
  const auto& keyframes = map_->keyframes();
  IdleBundleStats stats;
  BundleProblem problem;
  std::unordered_map<int64_t, int> pose_index, point_index;
  auto add_pose = [&](const KeyFrame& k, bool fixed) {
    auto it = pose_index.find(k.id);
    if (it != pose_index.end()) return it->second;
    pose_index[k.id] = static_cast<int>(problem.poses.size());
    problem.poses.push_back({k.id, k.camera_from_map, fixed || k.id == 0});
    return static_cast<int>(problem.poses.size()) - 1;
  };
  for (int k = first_free; k < end; ++k) {
    add_pose(*keyframes[k], false);
    for (int64_t id : keyframes[k]->point_ids) {
      if (id < 0 || point_index.count(id)) continue;
      const MapPoint* p = map_->FindPoint(id);
      if (p == nullptr) continue;
      point_index[id] = static_cast<int>(problem.points.size());
      problem.points.push_back({id, p->position});
    }
  }
  // Observations behind their camera (left by a revisit's correction) would make the solver
  // fail on the whole window: they are dropped instead.
  std::vector<std::pair<int64_t, int64_t>> behind;
  for (const auto& point : problem.points) {
    const MapPoint* p = map_->FindPoint(point.id);
    for (const auto& [kf, index] : p->observations) {
      const KeyFrame& k = *keyframes[kf];
      if ((k.camera_from_map * point.position).z() <= 1e-6) {
        behind.emplace_back(point.id, kf);
        continue;
      }
      const int pose = add_pose(k, kf < first_free || kf >= end);
      problem.observations.push_back({pose, point_index[point.id], k.features.pixels[index],
                                      Scale(scale_factor_, k.features.keypoints[index])});
    }
  }
  stats.keyframes = end - first_free;
  stats.points = static_cast<int>(problem.points.size());
  stats.bundle = SolveBundle(camera_, &problem, iterations, options_.ba_huber_px, should_stop);
  std::lock_guard<std::mutex> lock(*mutex_);
  for (const auto& [point, keyframe] : behind) map_->RemoveObservation(point, keyframe);
  stats.removed = static_cast<int>(behind.size());
  if (!stats.bundle.usable) return stats;
  for (const auto& pose : problem.poses) {
    if (!pose.fixed) map_->FindKeyFrame(pose.keyframe)->camera_from_map = pose.camera_from_map;
  }
  for (const auto& point : problem.points) {
    if (MapPoint* p = map_->FindPoint(point.id)) p->position = point.position;
  }
  for (const auto& o : problem.observations) {
    const double limit = 2.0 * options_.max_reprojection_px * o.level_scale;
    if (ReprojectionErrorPx(camera_, problem, o) > limit) {
      map_->RemoveObservation(problem.points[o.point].id, problem.poses[o.pose].keyframe);
      ++stats.removed;
    }
  }
  return stats;
}

void LocalMapper::MapChanged() {
  const int n = static_cast<int>(map_->keyframes().size());
  const int step = std::max(1, options_.idle_ba_window / 2);
  idle_slices_left_ = n < 3 ? 0 : (n + step - 1) / step;
}

IdleBundleStats LocalMapper::IdleBundle(int iterations, const std::function<bool()>& should_stop) {
  const int n = static_cast<int>(map_->keyframes().size());
  if (idle_slices_left_ <= 0 || iterations <= 0 || n < 3) return {};
  // Slices overlap by half a window, so every keyframe is optimised with both neighbours.
  const int window = std::min(n, options_.idle_ba_window);
  const int first = std::min(idle_cursor_, n - window);
  IdleBundleStats stats = AdjustWindow(first, first + window, iterations, should_stop);
  idle_cursor_ = first + window >= n ? 0 : first + std::max(1, window / 2);
  --idle_slices_left_;
  return stats;
}

int LocalMapper::Cull(int64_t current_keyframe) {
  std::lock_guard<std::mutex> lock(*mutex_);
  std::vector<int64_t> bad;
  for (const auto& [id, p] : map_->points()) {
    const bool unreliable =
        p.visible >= 10 && static_cast<double>(p.found) / p.visible < options_.min_found_ratio;
    const bool unconfirmed = current_keyframe - p.first_keyframe >= 3 && p.observations.size() <= 2;
    if (unreliable || unconfirmed) bad.push_back(id);
  }
  for (int64_t id : bad) map_->RemovePoint(id);
  return static_cast<int>(bad.size());
}

BundleSummary LocalMapper::GlobalBundle(double baseline) {
  return SolveGlobal(std::max(options_.ba_iterations, 20), baseline, false);
}

BundleSummary LocalMapper::FinalBundle(int iterations) {
  if (iterations <= 0 || map_->keyframes().size() < 3) return {};
  // Points made late in the run are observed only by the keyframes near them; finding them in
  // every keyframe first links the whole run, so the adjustment can take out the scale drift.
  BundleSummary summary;
  int iterations_done = 0;
  for (int round = 0; round < 2; ++round) {
    std::vector<KeyFrame*> all;
    for (const auto& k : map_->keyframes()) all.push_back(k.get());
    for (KeyFrame* k : all) {
      std::vector<KeyFrame*> others;
      for (KeyFrame* o : all) {
        if (o != k) others.push_back(o);
      }
      FuseNeighbourPoints(k, others);
    }
    summary = SolveGlobal(iterations, 0, true);
    iterations_done += summary.iterations;
  }
  summary.iterations = iterations_done;  // Of both rounds.
  return summary;
}

namespace {

double PathLength(const std::vector<BundleProblem::Pose>& poses) {
  double length = 0;
  for (size_t k = 1; k < poses.size(); ++k) {
    length += (poses[k].camera_from_map.inverse().translation() -
               poses[k - 1].camera_from_map.inverse().translation())
                  .norm();
  }
  return length;
}

}  // namespace

BundleSummary LocalMapper::SolveGlobal(int iterations, double baseline, bool keep_path_length) {
  BundleProblem problem;
  std::unordered_map<int64_t, int> point_index;
  for (const auto& k : map_->keyframes())
    problem.poses.push_back({k->id, k->camera_from_map, k->id == 0});
  for (const auto& [id, p] : map_->points()) {
    point_index[id] = static_cast<int>(problem.points.size());
    problem.points.push_back({id, p.position});
    for (const auto& [kf, index] : p.observations) {
      const KeyFrame& k = *map_->keyframes()[kf];
      problem.observations.push_back({static_cast<int>(kf), point_index[id],
                                      k.features.pixels[index],
                                      Scale(scale_factor_, k.features.keypoints[index])});
    }
  }
  const double length_before = PathLength(problem.poses);
  BundleSummary summary = SolveBundle(camera_, &problem, iterations, options_.ba_huber_px);
  if (!summary.usable || problem.poses.size() < 2) return summary;
  double s = 1.0;
  if (keep_path_length) {
    const double length_after = PathLength(problem.poses);
    if (length_after > 0) s = length_before / length_after;
  } else {
    const double length = (problem.poses[1].camera_from_map.inverse().translation() -
                           problem.poses[0].camera_from_map.inverse().translation())
                              .norm();
    if (length > 0) s = baseline / length;
  }
  std::lock_guard<std::mutex> lock(*mutex_);
  for (const auto& pose : problem.poses) {
    Eigen::Isometry3d c = pose.camera_from_map;
    c.translation() *= s;
    map_->FindKeyFrame(pose.keyframe)->camera_from_map = c;
  }
  for (const auto& point : problem.points) map_->FindPoint(point.id)->position = point.position * s;
  for (const auto& o : problem.observations) {
    if (ReprojectionErrorPx(camera_, problem, o) >
        2.0 * options_.max_reprojection_px * o.level_scale) {
      map_->RemoveObservation(problem.points[o.point].id, problem.poses[o.pose].keyframe);
    }
  }
  return summary;
}

}  // namespace sightline
