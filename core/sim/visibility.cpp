#include "core/sim/visibility.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace sightline::sim {
namespace {

// Pixel-centre tolerance of the scan conversion: shared edges are covered by both neighbours
// (harmless, the depth test decides), so there are no cracks.
constexpr double kEdgeTolerancePx = 1e-4;

// A small fixed-capacity polygon (outlines have at most 8 corners; clipping adds one per edge).
struct Polygon {
  std::array<Eigen::Vector3d, 24> v;
  int n = 0;
  void Push(const Eigen::Vector3d& p) {
    if (n < static_cast<int>(v.size())) v[n++] = p;
  }
};

// Sutherland-Hodgman clip of a convex polygon to z >= near.
Polygon ClipNear(const Eigen::Vector3d* points, int count, double near) {
  Polygon out;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d& a = points[i];
    const Eigen::Vector3d& b = points[(i + 1) % count];
    const bool a_in = a.z() >= near, b_in = b.z() >= near;
    if (a_in) out.Push(a);
    if (a_in != b_in) out.Push(a + (near - a.z()) / (b.z() - a.z()) * (b - a));
  }
  return out;
}

// Pixel rectangle [u0, u1] x [v0, v1]; empty when u0 > u1 or v0 > v1.
struct PixelRect {
  int u0 = 0, u1 = -1, v0 = 0, v1 = -1;
};

// The pixels covered by the projection of the part of a box (8 corners) with z >= near.
PixelRect ProjectedBoxRect(const Eigen::Vector3d* corners, const PinholeCamera& cam, double near) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  bool any = false;
  auto add = [&](const Eigen::Vector3d& p) {
    const double x = cam.fx * p.x() / p.z() + cam.cx, y = cam.fy * p.y() / p.z() + cam.cy;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    any = true;
  };
  for (int i = 0; i < 8; ++i) {
    if (corners[i].z() >= near) add(corners[i]);
    for (int bit : {1, 2, 4}) {  // The 12 edges join corners differing in one index bit.
      const int j = i | bit;
      if (j == i) continue;
      const Eigen::Vector3d& a = corners[i];
      const Eigen::Vector3d& b = corners[j];
      if ((a.z() >= near) != (b.z() >= near)) {
        add(a + (near - a.z()) / (b.z() - a.z()) * (b - a));
      }
    }
  }
  PixelRect r;
  if (!any) return r;
  // Clamped before the casts: projections of points near the near plane can be huge.
  r.u0 = static_cast<int>(std::clamp(std::floor(x0), 0.0, static_cast<double>(cam.width)));
  r.u1 = static_cast<int>(std::clamp(std::ceil(x1), -1.0, cam.width - 1.0));
  r.v0 = static_cast<int>(std::clamp(std::floor(y0), 0.0, static_cast<double>(cam.height)));
  r.v1 = static_cast<int>(std::clamp(std::ceil(y1), -1.0, cam.height - 1.0));
  return r;
}

void RasterPlane(const ViewItem& item, int index, const PreparedView& view,
                 const PinholeCamera& cam, const RayTable& rays, double near, float* inv,
                 int32_t* ids) {
  const Polygon clipped = ClipNear(&view.points[item.points_begin], item.points_count, near);
  if (clipped.n < 3) return;
  std::array<Eigen::Vector2d, 24> q;
  double area = 0, y_min = 1e300, y_max = -1e300, x_min = 1e300, x_max = -1e300;
  for (int i = 0; i < clipped.n; ++i) {
    const Eigen::Vector3d& p = clipped.v[i];
    q[i] = {cam.fx * p.x() / p.z() + cam.cx, cam.fy * p.y() / p.z() + cam.cy};
    y_min = std::min(y_min, q[i].y()), y_max = std::max(y_max, q[i].y());
    x_min = std::min(x_min, q[i].x()), x_max = std::max(x_max, q[i].x());
  }
  if (x_max < -1 || x_min > cam.width || y_max < -1 || y_min > cam.height) return;
  for (int i = 0; i < clipped.n; ++i) {
    const Eigen::Vector2d& a = q[i];
    const Eigen::Vector2d& b = q[(i + 1) % clipped.n];
    area += a.x() * b.y() - a.y() * b.x();
  }
  if (std::abs(area) < 1e-12) return;  // Seen edge-on.
  const double sign = area > 0 ? 1.0 : -1.0;
  // Edge half-planes a u + b v + c >= 0 (inside).
  std::array<Eigen::Vector3d, 24> edges;
  for (int i = 0; i < clipped.n; ++i) {
    const Eigen::Vector2d& p = q[i];
    const Eigen::Vector2d e = q[(i + 1) % clipped.n] - p;
    const double norm = e.norm();
    if (norm < 1e-12) {
      edges[i] = {0, 0, 1};  // Degenerate edge: no constraint.
      continue;
    }
    // Normalised so the tolerance is in pixels.
    edges[i] = sign / norm * Eigen::Vector3d(-e.y(), e.x(), e.y() * p.x() - e.x() * p.y());
  }
  // Inverse depth 1/z = (n . ray) / d, affine in (u, v).
  const Eigen::Vector3d& n = item.normal;
  const double a_inv = n.x() / (cam.fx * item.d);
  const double b_inv = n.y() / (cam.fy * item.d);
  const double c_inv = (n.z() - n.x() * cam.cx / cam.fx - n.y() * cam.cy / cam.fy) / item.d;
  const int v0 = static_cast<int>(
      std::ceil(std::clamp(y_min, 0.0, static_cast<double>(cam.height)) - kEdgeTolerancePx));
  const int v1 =
      static_cast<int>(std::floor(std::clamp(y_max, -1.0, cam.height - 1.0) + kEdgeTolerancePx));
  const bool disc = item.kind == ViewItem::kDisc;
  const double r2 = item.radius * item.radius;
  for (int v = v0; v <= v1; ++v) {
    double lo = 0, hi = cam.width - 1;
    for (int i = 0; i < clipped.n; ++i) {
      const Eigen::Vector3d& e = edges[i];
      const double rest = e.y() * v + e.z();
      if (e.x() > 1e-12) {
        lo = std::max(lo, -rest / e.x());
      } else if (e.x() < -1e-12) {
        hi = std::min(hi, -rest / e.x());
      } else if (rest < -kEdgeTolerancePx) {
        hi = -1;
      }
    }
    // lo and hi may be huge for edges nearly parallel to the rows: clamp before the casts.
    lo = std::min(lo, static_cast<double>(cam.width));
    hi = std::max(hi, -1.0);
    const int u0 = std::max(0, static_cast<int>(std::ceil(lo - kEdgeTolerancePx)));
    const int u1 = std::min(cam.width - 1, static_cast<int>(std::floor(hi + kEdgeTolerancePx)));
    if (u0 > u1) continue;
    float* inv_row = inv + static_cast<size_t>(v) * cam.width;
    int32_t* id_row = ids + static_cast<size_t>(v) * cam.width;
    const double row = b_inv * v + c_inv;
    if (!disc) {
      for (int u = u0; u <= u1; ++u) {
        const float w = static_cast<float>(a_inv * u + row);
        if (w > inv_row[u]) {
          inv_row[u] = w;
          id_row[u] = index;
        }
      }
      continue;
    }
    const double ry = rays.y[v];
    for (int u = u0; u <= u1; ++u) {
      const double w = a_inv * u + row;
      if (!(static_cast<float>(w) > inv_row[u]) || !(w > 0)) continue;
      const Eigen::Vector3d p = Eigen::Vector3d(rays.x[u], ry, 1.0) / w;
      const double s = item.axis_s.dot(p) - item.s0, t = item.axis_t.dot(p) - item.t0;
      if (s * s + t * t > r2) continue;
      inv_row[u] = static_cast<float>(w);
      id_row[u] = index;
    }
  }
}

// Nearest ray parameter (= depth z, rays have unit z) of a hit with z >= near, or -1.
inline double HitCylinder(const ViewItem& c, double x, double y, double near) {
  const Eigen::Vector3d dir(x, y, 1.0);
  const double da = dir.dot(c.axis);
  const Eigen::Vector3d b_perp = c.base - c.base.dot(c.axis) * c.axis;
  const double qa = dir.squaredNorm() - da * da;
  if (qa < 1e-12) return -1;
  const double qb = -2 * dir.dot(b_perp);
  const double qc = b_perp.squaredNorm() - c.radius * c.radius;
  const double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return -1;
  const double root = std::sqrt(disc);
  const double ba = c.base.dot(c.axis);
  for (double z : {(-qb - root) / (2 * qa), (-qb + root) / (2 * qa)}) {
    if (z < near) continue;
    const double h = z * da - ba;
    if (h >= 0 && h <= c.height) return z;
  }
  return -1;
}

inline double HitSphere(const ViewItem& s, double x, double y, double near) {
  const Eigen::Vector3d dir(x, y, 1.0);
  const double qa = dir.squaredNorm();
  const double qb = -2 * dir.dot(s.center);
  const double qc = s.center.squaredNorm() - s.radius * s.radius;
  const double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return -1;
  const double root = std::sqrt(disc);
  for (double z : {(-qb - root) / (2 * qa), (-qb + root) / (2 * qa)}) {
    if (z >= near) return z;
  }
  return -1;
}

void RasterCurved(const ViewItem& item, int index, const PreparedView& view,
                  const PinholeCamera& cam, const RayTable& rays, double near, float* inv,
                  int32_t* ids) {
  const PixelRect r = ProjectedBoxRect(&view.points[item.points_begin], cam, near);
  for (int v = r.v0; v <= r.v1; ++v) {
    float* inv_row = inv + static_cast<size_t>(v) * cam.width;
    int32_t* id_row = ids + static_cast<size_t>(v) * cam.width;
    for (int u = r.u0; u <= r.u1; ++u) {
      const double z = item.kind == ViewItem::kCylinder
                           ? HitCylinder(item, rays.x[u], rays.y[v], near)
                           : HitSphere(item, rays.x[u], rays.y[v], near);
      if (z < 0) continue;
      const float w = static_cast<float>(1.0 / z);
      if (w > inv_row[u]) {
        inv_row[u] = w;
        id_row[u] = index;
      }
    }
  }
}

// Any unit vector perpendicular to `axis`, chosen from the axis alone (stable across views).
Eigen::Vector3d Perpendicular(const Eigen::Vector3d& axis) {
  const Eigen::Vector3d other =
      std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return axis.cross(other).normalized();
}

}  // namespace

void MakeRayTable(const PinholeCamera& camera, RayTable* table) {
  table->x.resize(camera.width);
  table->y.resize(camera.height);
  for (int u = 0; u < camera.width; ++u) {
    table->x[u] = static_cast<float>((u - camera.cx) / camera.fx);
  }
  for (int v = 0; v < camera.height; ++v) {
    table->y[v] = static_cast<float>((v - camera.cy) / camera.fy);
  }
  table->inverse_length.resize(static_cast<size_t>(camera.width) * camera.height);
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      const double x = table->x[u], y = table->y[v];
      table->inverse_length[static_cast<size_t>(v) * camera.width + u] =
          static_cast<float>(1.0 / std::sqrt(1.0 + x * x + y * y));
    }
  }
}

void PrepareView(const Scene& scene, const std::vector<Primitive>& dynamic,
                 const Eigen::Isometry3d& camera_from_world, PreparedView* view) {
  view->items.clear();
  view->points.clear();
  const Eigen::Matrix3d rotation = camera_from_world.linear();
  const size_t static_count = scene.primitives().size();
  const size_t total = static_count + dynamic.size();
  for (size_t i = 0; i < total; ++i) {
    const Primitive& prim = i < static_count ? scene.primitives()[i] : dynamic[i - static_count];
    ViewItem item;
    item.primitive = static_cast<int>(i);
    item.object = prim.object;
    item.material = prim.material;
    item.points_begin = static_cast<int>(view->points.size());
    if (const auto* patch = std::get_if<PlanarPatch>(&prim.shape)) {
      const Eigen::Vector3d origin = camera_from_world * patch->origin;
      item.axis_s = rotation * patch->axis_s;
      item.axis_t = rotation * patch->axis_t;
      item.normal = item.axis_s.cross(item.axis_t);
      item.d = item.normal.dot(origin);
      // The camera (at the origin) sees the front side when d < 0.
      if (std::abs(item.d) < 1e-9 || (!patch->two_sided && item.d >= 0)) continue;
      item.s0 = item.axis_s.dot(origin);
      item.t0 = item.axis_t.dot(origin);
      item.kind = patch->shape == PatchShape::kDisc ? ViewItem::kDisc : ViewItem::kPlane;
      item.radius = patch->size.x();
      for (const Eigen::Vector2d& st : patch->Outline()) {
        view->points.push_back(origin + st.x() * item.axis_s + st.y() * item.axis_t);
      }
    } else {
      const Eigen::AlignedBox3d box = BoundsOf(prim.shape);
      bool in_front = false;
      for (int k = 0; k < 8; ++k) {
        const Eigen::Vector3d corner(k & 1 ? box.max().x() : box.min().x(),
                                     k & 2 ? box.max().y() : box.min().y(),
                                     k & 4 ? box.max().z() : box.min().z());
        view->points.push_back(camera_from_world * corner);
        in_front = in_front || view->points.back().z() > 0;
      }
      if (!in_front) {
        view->points.resize(item.points_begin);
        continue;
      }
      if (const auto* cyl = std::get_if<Cylinder>(&prim.shape)) {
        item.kind = ViewItem::kCylinder;
        item.base = camera_from_world * cyl->base;
        item.axis = rotation * cyl->axis;
        item.ref_u = rotation * Perpendicular(cyl->axis);
        item.ref_v = item.axis.cross(item.ref_u);
        item.radius = cyl->radius;
        item.height = cyl->height;
      } else {
        const Sphere& sphere = std::get<Sphere>(prim.shape);
        item.kind = ViewItem::kSphere;
        item.center = camera_from_world * sphere.center;
        item.radius = sphere.radius;
        item.ref_u = rotation * Eigen::Vector3d::UnitX();
        item.ref_v = rotation * Eigen::Vector3d::UnitY();
        item.axis = rotation * Eigen::Vector3d::UnitZ();
      }
    }
    item.points_count = static_cast<int>(view->points.size()) - item.points_begin;
    if (item.points_count == 0) continue;
    view->items.push_back(item);
  }
}

void RasterizeVisibility(const PreparedView& view, const PinholeCamera& camera,
                         const RayTable& rays, double near_m, std::vector<float>* inverse_depth,
                         std::vector<int32_t>* item_index) {
  const size_t pixels = static_cast<size_t>(camera.width) * camera.height;
  inverse_depth->assign(pixels, 0.0f);
  item_index->assign(pixels, -1);
  for (size_t i = 0; i < view.items.size(); ++i) {
    const ViewItem& item = view.items[i];
    const int index = static_cast<int>(i);
    if (item.kind == ViewItem::kPlane || item.kind == ViewItem::kDisc) {
      RasterPlane(item, index, view, camera, rays, near_m, inverse_depth->data(),
                  item_index->data());
    } else {
      RasterCurved(item, index, view, camera, rays, near_m, inverse_depth->data(),
                   item_index->data());
    }
  }
}

}  // namespace sightline::sim
