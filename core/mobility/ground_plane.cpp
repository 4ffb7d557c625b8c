#include "core/mobility/ground_plane.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace sightline {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

// The inlier distance at a point: grows with depth squared like the sensor's noise.
float GroundThreshold(const MobilityOptions& o, const Eigen::Vector3f& p) {
  return static_cast<float>(o.ground_distance_m + o.ground_distance_per_m2 * p.z() * p.z());
}

struct Candidate {
  GroundPlane plane;
  std::vector<int> members;  // Indices into the cloud.
};

// A point that may support the ground, gathered once with its inlier distance so that the
// passes over the pool stream through one array.
struct PoolPoint {
  Eigen::Vector3f point;
  float threshold;  // GroundThreshold of the point.
  Eigen::Vector3f normal;
  int index;  // Into the cloud.
};

// Whether p lies on the plane n . x + d = 0 (distance and own normal within tolerance).
inline bool OnPlane(const PoolPoint& p, const Eigen::Vector3d& n, double d,
                    const Eigen::Vector3f& nf, float cos_member) {
  const double distance = std::abs(n.dot(p.point.cast<double>()) + d);
  const float facing = p.normal.dot(nf);
  return static_cast<int>(distance < p.threshold) & static_cast<int>(facing >= cos_member);
}

// One RANSAC search among the pool; returns false when no hypothesis had an up-facing normal.
bool BestUpPlane(const std::vector<PoolPoint>& pool, const Eigen::Vector3d& up,
                 const MobilityOptions& options, int iterations, std::mt19937* rng,
                 Eigen::Vector3d* normal, double* d) {
  if (pool.size() < 3) return false;
  std::uniform_int_distribution<size_t> pick(0, pool.size() - 1);
  // Hypotheses are scored on an even subsample of the pool, gathered once with its thresholds.
  const size_t step = std::max<size_t>(1, pool.size() / options.ransac_sample_points);
  // As arrays (x, y, z, inlier distance), so that scoring a hypothesis vectorizes.
  std::vector<float> sx, sy, sz, sw;
  for (size_t k = 0; k < pool.size(); k += step) {
    const PoolPoint& p = pool[k];
    sx.push_back(p.point.x()), sy.push_back(p.point.y()), sz.push_back(p.point.z());
    sw.push_back(p.threshold);
  }
  const size_t samples = sx.size();
  const double cos_tolerance = std::cos(options.up_tolerance_deg * kDegToRad);
  int best = -1;
  for (int it = 0; it < iterations; ++it) {
    const Eigen::Vector3f& a = pool[pick(*rng)].point;
    const Eigen::Vector3f& b = pool[pick(*rng)].point;
    const Eigen::Vector3f& c = pool[pick(*rng)].point;
    Eigen::Vector3f n = (b - a).cross(c - a);
    const float norm = n.norm();
    if (norm < 1e-9f) continue;  // Collinear or repeated.
    n /= norm;
    if (n.cast<double>().dot(up) < 0) n = -n;
    if (n.cast<double>().dot(up) < cos_tolerance) continue;
    const float offset = -n.dot(a);
    int count = 0;
    const float nx = n.x(), ny = n.y(), nz = n.z();
    for (size_t k = 0; k < samples; ++k) {
      count += std::abs(nx * sx[k] + ny * sy[k] + nz * sz[k] + offset) < sw[k];
    }
    if (count > best) {
      best = count;
      *normal = n.cast<double>();
      *d = offset;
    }
  }
  return best > 0;
}

// Least-squares plane of the pool's points on the plane n . x + d = 0, without a branch per
// point (outliers add with weight 0). False when too few or degenerate.
bool RefitPlane(const std::vector<PoolPoint>& pool, const Eigen::Vector3d& up, float cos_member,
                Eigen::Vector3d* n, double* d) {
  const Eigen::Vector3f nf = n->cast<float>();
  const Eigen::Vector3d reference = pool.front().point.cast<double>();
  double count = 0, sx = 0, sy = 0, sz = 0, sxx = 0, sxy = 0, sxz = 0, syy = 0, syz = 0, szz = 0;
  for (const PoolPoint& p : pool) {
    const double w = OnPlane(p, *n, *d, nf, cos_member) ? 1.0 : 0.0;
    const double x = p.point.x() - reference.x(), y = p.point.y() - reference.y(),
                 z = p.point.z() - reference.z();
    const double wx = w * x, wy = w * y, wz = w * z;
    count += w, sx += wx, sy += wy, sz += wz;
    sxx += wx * x, sxy += wx * y, sxz += wx * z, syy += wy * y, syz += wy * z, szz += wz * z;
  }
  PlaneSums sums;
  sums.count = static_cast<int>(count);
  sums.reference = reference;
  sums.sx = sx, sums.sy = sy, sums.sz = sz;
  sums.sxx = sxx, sums.sxy = sxy, sums.sxz = sxz, sums.syy = syy, sums.syz = syz, sums.szz = szz;
  Eigen::Vector3d centroid;
  if (!sums.Fit(n, &centroid)) return false;
  if (n->dot(up) < 0) *n = -*n;
  *d = -n->dot(centroid);
  return true;
}

// Median of direction . x over the members.
double MedianLevel(const WorkingCloud& cloud, const std::vector<int>& members,
                   const Eigen::Vector3d& direction) {
  std::vector<double> levels;
  levels.reserve(members.size());
  for (int i : members) levels.push_back(direction.dot(cloud.points[i].cast<double>()));
  std::nth_element(levels.begin(), levels.begin() + levels.size() / 2, levels.end());
  return levels[levels.size() / 2];
}

}  // namespace

int RansacIterations(double success, double inlier_ratio, int sample_size) {
  const double all_inliers = std::pow(inlier_ratio, sample_size);
  if (all_inliers >= 1) return 1;
  const double k = std::log(1 - success) / std::log(1 - all_inliers);
  return static_cast<int>(std::clamp(std::ceil(k), 1.0, 1e6));
}

Eigen::Vector3d ExpectedUpFromMount(double pitch_deg, double roll_deg) {
  // Up in a level camera is -y; pitching the camera down turns up towards -z in its frame.
  const Eigen::Vector3d level(0, -1, 0);
  const Eigen::AngleAxisd pitch(pitch_deg * kDegToRad, Eigen::Vector3d::UnitX());
  const Eigen::AngleAxisd roll(roll_deg * kDegToRad, Eigen::Vector3d::UnitZ());
  return (roll * pitch * level).normalized();
}

bool PlaneSums::Fit(Eigen::Vector3d* normal, Eigen::Vector3d* centroid) const {
  if (count < 3) return false;
  const double n = static_cast<double>(count);
  const Eigen::Vector3d mean(sx / n, sy / n, sz / n);
  // Scatter about the mean (not divided by the count).
  Eigen::Matrix3d scatter;
  scatter << sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz;
  scatter -= n * mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  if (solver.info() != Eigen::Success || solver.eigenvalues()(1) <= 1e-12) return false;
  *normal = solver.eigenvectors().col(0).normalized();
  *centroid = reference + mean;
  return normal->allFinite();
}

bool FitPlaneLeastSquares(const std::vector<Eigen::Vector3f>& points, Eigen::Vector3d* normal,
                          Eigen::Vector3d* centroid) {
  PlaneSums sums;
  for (const Eigen::Vector3f& p : points) sums.Add(p);
  return sums.Fit(normal, centroid);
}

StatusOr<GroundPlane> FindGround(const WorkingCloud& cloud, const Eigen::Vector3d& up,
                                 const MobilityOptions& options, std::vector<uint8_t>* is_ground,
                                 int* iterations_out) {
  is_ground->assign(cloud.size(), 0);
  const int iterations = RansacIterations(options.ransac_success, options.ransac_inlier_ratio);
  if (iterations_out != nullptr) *iterations_out = iterations;
  if (cloud.size() < 3) return NotFound("no ground: fewer than 3 points");
  // Only points whose own normal faces up within the tolerance may support a plane.
  const double cos_pool = std::cos(options.up_tolerance_deg * kDegToRad);
  const float cos_member = static_cast<float>(std::cos(options.ground_normal_deg * kDegToRad));
  std::vector<PoolPoint> pool;
  pool.reserve(cloud.size());
  for (size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3f& n = cloud.normals[i];
    if (n.allFinite() && n.cast<double>().dot(up) >= cos_pool) {
      const Eigen::Vector3f& p = cloud.points[i];
      pool.push_back({p, GroundThreshold(options, p), n, static_cast<int>(i)});
    }
  }
  std::mt19937 rng(7);
  const int min_points =
      std::max(3, static_cast<int>(options.min_ground_ratio * static_cast<double>(cloud.size())));
  std::vector<Candidate> candidates;
  std::vector<PoolPoint> rest;
  for (int c = 0; c < options.ground_candidates && static_cast<int>(pool.size()) >= min_points;
       ++c) {
    Eigen::Vector3d n;
    double d = 0;
    if (!BestUpPlane(pool, up, options, iterations, &rng, &n, &d)) break;
    // Least-squares refit on the inliers, then the final members (distance and own normal).
    for (int refit = 0; refit < 2; ++refit) {
      if (!RefitPlane(pool, up, cos_member, &n, &d)) break;
    }
    Candidate candidate;
    candidate.plane.normal = n;
    candidate.plane.d = d;
    const Eigen::Vector3f nf = n.cast<float>();
    // Members and the rest written without a branch per point; the last candidate needs no rest.
    const bool last = c + 1 == options.ground_candidates;
    candidate.members.resize(pool.size());
    rest.resize(last ? 0 : pool.size());
    size_t members = 0, others = 0;
    for (const PoolPoint& p : pool) {
      const bool on_plane = OnPlane(p, n, d, nf, cos_member);
      candidate.members[members] = p.index;
      if (!last) rest[others] = p;
      members += on_plane;
      others += !on_plane;
    }
    candidate.members.resize(members);
    rest.resize(last ? 0 : others);
    pool.swap(rest);
    if (static_cast<int>(candidate.members.size()) < min_points) break;
    candidates.push_back(std::move(candidate));
  }
  // The lowest qualifying plane: the one whose points lie lowest along the largest candidate's
  // normal (a ramp's plane may pass below the floor under the camera, its points do not).
  const Candidate* largest = nullptr;
  for (const Candidate& c : candidates) {
    if (largest == nullptr || c.members.size() > largest->members.size()) largest = &c;
  }
  std::vector<const Candidate*> qualified;
  for (const Candidate& c : candidates) {
    if (c.plane.d <= 0) continue;  // The camera is below it (a ceiling, a table seen from under).
    if (std::acos(std::clamp(c.plane.normal.dot(up), -1.0, 1.0)) >
        options.up_tolerance_deg * kDegToRad) {
      continue;
    }
    qualified.push_back(&c);
  }
  const Candidate* ground = qualified.size() == 1 ? qualified[0] : nullptr;
  double ground_level = 0;
  for (size_t k = 0; qualified.size() > 1 && k < qualified.size(); ++k) {
    const double level = MedianLevel(cloud, qualified[k]->members, largest->plane.normal);
    if (ground == nullptr || level < ground_level) ground = qualified[k], ground_level = level;
  }
  if (ground == nullptr) {
    char text[256];
    std::snprintf(text, sizeof(text),
                  "no ground plane: no plane within %.0f deg of the expected up direction "
                  "(%.2f, %.2f, %.2f) holds %d of the %zu points (%.0f %%); %zu up-facing "
                  "candidate(s) found",
                  options.up_tolerance_deg, up.x(), up.y(), up.z(), min_points, cloud.size(),
                  100 * options.min_ground_ratio, candidates.size());
    return NotFound(text);
  }
  GroundPlane plane = ground->plane;
  plane.found = true;
  plane.inliers = static_cast<int>(ground->members.size());
  plane.candidates = static_cast<int>(candidates.size());
  for (int i : ground->members) (*is_ground)[i] = 1;
  return plane;
}

}  // namespace sightline
