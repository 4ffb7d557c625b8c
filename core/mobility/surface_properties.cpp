#include "core/mobility/surface_properties.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <random>
#include <unordered_map>

#include "core/mobility/ground_plane.h"

namespace sightline {
namespace {

// A cell's running mean in plane coordinates (u, v) and height h.
struct CellMean {
  double u = 0, v = 0, h = 0;
  int count = 0;
  Eigen::Vector3d Mean() const { return Eigen::Vector3d(u / count, v / count, h / count); }
};

int64_t CellKey(int64_t a, int64_t b) { return (a << 32) ^ (b & 0xffffffff); }

// Adds one triangle (plane coordinates, third component = height) to the sums.
void AddTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                 RoughnessResult* r) {
  const Eigen::Vector3d ab = b - a, ac = c - a;
  r->surface_area_m2 += 0.5 * ab.cross(ac).norm();
  r->projected_area_m2 += 0.5 * std::abs(ab.x() * ac.y() - ab.y() * ac.x());
  ++r->triangles;
}

// Two triangles per square of four occupied cells; `find(a, b)` gives a cell or nullptr.
template <typename Find>
void TriangulateGrid(const Find& find, const std::vector<std::pair<int, int>>& keys,
                     RoughnessResult* r) {
  for (const auto& [a, b] : keys) {
    const CellMean* c00 = find(a, b);
    const CellMean* c10 = find(a + 1, b);
    const CellMean* c01 = find(a, b + 1);
    const CellMean* c11 = find(a + 1, b + 1);
    if (c10 && c11) AddTriangle(c00->Mean(), c10->Mean(), c11->Mean(), r);
    if (c01 && c11) AddTriangle(c00->Mean(), c11->Mean(), c01->Mean(), r);
    // Squares missing their far corner still get the one triangle they hold.
    if (!c11 && c10 && c01) AddTriangle(c00->Mean(), c10->Mean(), c01->Mean(), r);
  }
}

// std::floor to int for |x| < 2^31 without the library call (no SSE4.1 rounding here).
inline int FloorToInt(double x) {
  const int t = static_cast<int>(x);  // Truncates towards zero.
  return t - (x < t);
}

// A point in the plane's coordinates: cell indices, (u, v) and height h.
struct PlanePoint {
  int a, b;
  double u, v, h;
};

// Plane coordinates of the points (basis e1 = n.unitOrthogonal(), e2 = n x e1, origin the
// centroid) and the cells' index bounds.
std::vector<PlanePoint> ToPlane(const std::vector<Eigen::Vector3f>& points,
                                const SegmentPlane& plane, double cell_m, int bounds[4]) {
  const Eigen::Vector3d& n = plane.normal;
  const Eigen::Vector3d e1 = n.unitOrthogonal();
  const Eigen::Vector3d e2 = n.cross(e1);
  const double inv = 1.0 / cell_m;
  std::vector<PlanePoint> out(points.size());
  bounds[0] = bounds[1] = std::numeric_limits<int>::max();
  bounds[2] = bounds[3] = std::numeric_limits<int>::min();
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d q = points[i].cast<double>() - plane.centroid;
    PlanePoint& pp = out[i];
    pp.u = q.dot(e1), pp.v = q.dot(e2), pp.h = q.dot(n);
    pp.a = FloorToInt(pp.u * inv);
    pp.b = FloorToInt(pp.v * inv);
    bounds[0] = std::min(bounds[0], pp.a), bounds[1] = std::min(bounds[1], pp.b);
    bounds[2] = std::max(bounds[2], pp.a), bounds[3] = std::max(bounds[3], pp.b);
  }
  return out;
}

// A dense cell array pays when the bounding box is not much larger than the point count.
bool DenseFits(const int bounds[4], size_t points) {
  const int64_t cells = (static_cast<int64_t>(bounds[2]) - bounds[0] + 1) *
                        (static_cast<int64_t>(bounds[3]) - bounds[1] + 1);
  return cells <= std::max<int64_t>(4096, 4 * static_cast<int64_t>(points));
}

void TriangulateDelaunay(const std::vector<Eigen::Vector3d>& means, double cell_m,
                         double max_edge_cells, RoughnessResult* r) {
  double u0 = 1e30, v0 = 1e30, u1 = -1e30, v1 = -1e30;
  for (const Eigen::Vector3d& m : means) {
    u0 = std::min(u0, m.x());
    v0 = std::min(v0, m.y());
    u1 = std::max(u1, m.x());
    v1 = std::max(v1, m.y());
  }
  // Subdiv2D works in float pixels: scale to cell units with a margin.
  const double scale = 1.0 / cell_m;
  cv::Subdiv2D subdiv(cv::Rect(-2, -2, static_cast<int>((u1 - u0) * scale) + 5,
                               static_cast<int>((v1 - v0) * scale) + 5));
  std::vector<int> vertex_of;  // Subdiv2D vertex id -> mean index.
  for (size_t i = 0; i < means.size(); ++i) {
    const int id = subdiv.insert(cv::Point2f(static_cast<float>((means[i].x() - u0) * scale),
                                             static_cast<float>((means[i].y() - v0) * scale)));
    if (id >= static_cast<int>(vertex_of.size())) vertex_of.resize(id + 1, -1);
    vertex_of[id] = static_cast<int>(i);
  }
  std::vector<cv::Vec6f> triangles;
  subdiv.getTriangleList(triangles);
  const double max_edge = max_edge_cells * cell_m;
  for (const cv::Vec6f& t : triangles) {
    Eigen::Vector3d corner[3];
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k) {
      int edge = 0, vertex = 0;
      const int located = subdiv.locate(cv::Point2f(t[2 * k], t[2 * k + 1]), edge, vertex);
      ok = located == cv::Subdiv2D::PTLOC_VERTEX && vertex < static_cast<int>(vertex_of.size()) &&
           vertex_of[vertex] >= 0;
      if (ok) corner[k] = means[vertex_of[vertex]];
    }
    if (!ok) continue;  // A triangle touching the bounding box's outer vertices.
    if ((corner[0] - corner[1]).head<2>().norm() > max_edge ||
        (corner[1] - corner[2]).head<2>().norm() > max_edge ||
        (corner[2] - corner[0]).head<2>().norm() > max_edge) {
      continue;
    }
    AddTriangle(corner[0], corner[1], corner[2], r);
  }
}

}  // namespace

StatusOr<SegmentPlane> FitSegmentPlane(const std::vector<Eigen::Vector3f>& points, int iterations,
                                       double distance_m, unsigned seed) {
  if (points.size() < 3) {
    return InvalidArgument("a plane needs at least 3 points, the segment has " +
                           std::to_string(points.size()));
  }
  SegmentPlane plane;
  PlaneSums inliers;
  if (iterations > 0) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<size_t> pick(0, points.size() - 1);
    const size_t step = std::max<size_t>(1, points.size() / 500);  // Score on <= ~500 points.
    int best = -1;
    Eigen::Vector3f best_n = Eigen::Vector3f::UnitZ();
    float best_d = 0;
    for (int it = 0; it < iterations; ++it) {
      const Eigen::Vector3f& a = points[pick(rng)];
      Eigen::Vector3f n = (points[pick(rng)] - a).cross(points[pick(rng)] - a);
      if (n.norm() < 1e-9f) continue;
      n.normalize();
      const float d = -n.dot(a);
      int count = 0;
      for (size_t k = 0; k < points.size(); k += step) {
        count += std::abs(n.dot(points[k]) + d) < distance_m;
      }
      if (count > best) best = count, best_n = n, best_d = d;
    }
    if (best > 0) {
      for (const Eigen::Vector3f& p : points) {
        if (std::abs(best_n.dot(p) + best_d) < distance_m) inliers.Add(p);
      }
    }
  }
  if (inliers.count < 3) {  // No RANSAC, or too few inliers: all points.
    inliers = PlaneSums();
    for (const Eigen::Vector3f& p : points) inliers.Add(p);
  }
  if (!inliers.Fit(&plane.normal, &plane.centroid)) {
    return InvalidArgument("the segment's " + std::to_string(points.size()) +
                           " points are collinear: no plane");
  }
  plane.inliers = inliers.count;
  return plane;
}

StatusOr<RoughnessResult> ComputeRoughness(const std::vector<Eigen::Vector3f>& points,
                                           const SegmentPlane& plane, double cell_m,
                                           const std::string& triangulation,
                                           double max_edge_cells) {
  int bounds[4];
  const std::vector<PlanePoint> projected = ToPlane(points, plane, cell_m, bounds);
  // Cell means, in a dense array over the bounding box when it is small enough (no hashing),
  // else in a hash map; keys keep the order of first occupation either way.
  std::vector<std::pair<int, int>> keys;
  std::vector<CellMean> dense;
  std::unordered_map<int64_t, CellMean> sparse;
  const bool use_dense = !points.empty() && DenseFits(bounds, points.size());
  const int width = use_dense ? bounds[2] - bounds[0] + 1 : 0;
  const int height = use_dense ? bounds[3] - bounds[1] + 1 : 0;
  if (use_dense) {
    dense.resize(static_cast<size_t>(width) * height);
  } else {
    sparse.reserve(points.size());
  }
  auto cell_at = [&](int a, int b) -> CellMean& {
    if (use_dense) return dense[static_cast<size_t>(b - bounds[1]) * width + (a - bounds[0])];
    return sparse[CellKey(a, b)];
  };
  for (const PlanePoint& pp : projected) {
    CellMean& cell = cell_at(pp.a, pp.b);
    if (cell.count == 0) keys.emplace_back(pp.a, pp.b);
    cell.u += pp.u, cell.v += pp.v, cell.h += pp.h, ++cell.count;
  }
  auto find = [&](int a, int b) -> const CellMean* {
    if (use_dense) {
      if (a < bounds[0] || b < bounds[1] || a > bounds[2] || b > bounds[3]) return nullptr;
      const CellMean& c = dense[static_cast<size_t>(b - bounds[1]) * width + (a - bounds[0])];
      return c.count > 0 ? &c : nullptr;
    }
    const auto it = sparse.find(CellKey(a, b));
    return it == sparse.end() ? nullptr : &it->second;
  };
  RoughnessResult r;
  r.cells = static_cast<int>(keys.size());
  if (triangulation == "delaunay") {
    std::vector<Eigen::Vector3d> means;
    means.reserve(keys.size());
    for (const auto& [a, b] : keys) means.push_back(find(a, b)->Mean());
    if (means.size() >= 3) TriangulateDelaunay(means, cell_m, max_edge_cells, &r);
  } else {
    TriangulateGrid(find, keys, &r);
  }
  if (r.triangles == 0 || r.projected_area_m2 <= 0) {
    return InvalidArgument("no triangle for the roughness: the segment covers " +
                           std::to_string(r.cells) + " cell(s) of " + std::to_string(cell_m) +
                           " m");
  }
  r.roughness = std::max(1.0, r.surface_area_m2 / r.projected_area_m2);
  return r;
}

int CountPlaneCells(const std::vector<Eigen::Vector3f>& points, const SegmentPlane& plane,
                    double cell_m) {
  int bounds[4];
  const std::vector<PlanePoint> projected = ToPlane(points, plane, cell_m, bounds);
  if (projected.empty()) return 0;
  int cells = 0;
  if (DenseFits(bounds, points.size())) {
    const int width = bounds[2] - bounds[0] + 1;
    std::vector<uint8_t> occupied(static_cast<size_t>(width) * (bounds[3] - bounds[1] + 1), 0);
    for (const PlanePoint& pp : projected) {
      uint8_t& o = occupied[static_cast<size_t>(pp.b - bounds[1]) * width + (pp.a - bounds[0])];
      cells += o == 0;
      o = 1;
    }
  } else {
    std::unordered_map<int64_t, uint8_t> occupied;
    occupied.reserve(points.size());
    for (const PlanePoint& pp : projected) occupied[CellKey(pp.a, pp.b)] = 1;
    cells = static_cast<int>(occupied.size());
  }
  return cells;
}

StatusOr<SegmentProperties> MeasureSegment(int id, bool is_ground,
                                           const std::vector<Eigen::Vector3f>& points,
                                           const GroundPlane& ground,
                                           const MobilityOptions& options) {
  const std::string name = is_ground ? "the ground" : "segment " + std::to_string(id);
  StatusOr<SegmentPlane> plane =
      FitSegmentPlane(points, options.plane_ransac_iterations, options.plane_distance_m, 1 + id);
  if (!plane.ok()) return plane.status().WithContext(name);
  SegmentProperties s;
  s.id = id;
  s.is_ground = is_ground;
  s.points = static_cast<int>(points.size());
  s.normal = plane->normal;
  s.centroid = plane->centroid;
  if (!is_ground) {
    s.slope_deg =
        std::acos(std::clamp(std::abs(plane->normal.dot(ground.normal)), 0.0, 1.0)) * 180.0 / M_PI;
  }
  // Roughness from the near points (depth noise grows with z^2), area from all of them.
  const float max2 =
      static_cast<float>(options.roughness_max_range_m * options.roughness_max_range_m);
  size_t near_count = 0;
  for (const Eigen::Vector3f& p : points) near_count += p.squaredNorm() <= max2;
  std::vector<Eigen::Vector3f> near_points;  // Only when some are far.
  if (near_count != points.size()) {
    near_points.reserve(near_count);
    for (const Eigen::Vector3f& p : points) {
      if (p.squaredNorm() <= max2) near_points.push_back(p);
    }
  }
  const std::vector<Eigen::Vector3f>& near = near_count == points.size() ? points : near_points;
  StatusOr<RoughnessResult> rough(InvalidArgument("no near points"));
  if (near.size() >= 3) {
    rough = ComputeRoughness(near, *plane, options.roughness_cell_m, options.triangulation,
                             options.max_edge_cells);
  }
  if (!rough.ok()) {
    rough = ComputeRoughness(points, *plane, options.roughness_cell_m, options.triangulation,
                             options.max_edge_cells);
  }
  if (!rough.ok()) return rough.status().WithContext(name);
  s.roughness = rough->roughness;
  s.area_m2 = rough->cells * options.roughness_cell_m * options.roughness_cell_m;
  if (near.size() != points.size()) {
    // Area over every point: count the occupied cells of all of them.
    s.area_m2 = CountPlaneCells(points, *plane, options.roughness_cell_m) *
                options.roughness_cell_m * options.roughness_cell_m;
  }
  // Raised height: a low quantile of the heights above the ground.
  if (ground.found && !is_ground) {
    std::vector<float> heights(points.size());
    for (size_t i = 0; i < points.size(); ++i)
      heights[i] = static_cast<float>(ground.HeightOf(points[i]));
    const size_t k = std::min(heights.size() - 1,
                              static_cast<size_t>(options.height_percentile * heights.size()));
    std::nth_element(heights.begin(), heights.begin() + k, heights.end());
    s.height_m = heights[k];
    const double tan_slope = std::tan(s.slope_deg * M_PI / 180.0);
    s.foot_m = tan_slope > 1e-6 ? std::max(0.0, s.height_m) / tan_slope
                                : std::numeric_limits<double>::infinity();
  }
  return s;
}

}  // namespace sightline
