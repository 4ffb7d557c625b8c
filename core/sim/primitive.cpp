#include "core/sim/primitive.h"

#include <cmath>

namespace sightline::sim {

std::vector<Eigen::Vector2d> PlanarPatch::Outline() const {
  switch (shape) {
    case PatchShape::kRectangle:
      return {{0, 0}, {size.x(), 0}, {size.x(), size.y()}, {0, size.y()}};
    case PatchShape::kDisc: {
      // An octagon whose edges touch the circle.
      const double r = size.x() / std::cos(M_PI / 8);
      std::vector<Eigen::Vector2d> octagon;
      for (int k = 0; k < 8; ++k) {
        const double a = (k + 0.5) * M_PI / 4;
        octagon.emplace_back(r * std::cos(a), r * std::sin(a));
      }
      return octagon;
    }
    case PatchShape::kPolygon:
      return polygon;
  }
  return {};
}

Eigen::AlignedBox3d BoundsOf(const Shape& shape) {
  Eigen::AlignedBox3d box;
  if (const auto* p = std::get_if<PlanarPatch>(&shape)) {
    for (const Eigen::Vector2d& st : p->Outline()) box.extend(p->At(st.x(), st.y()));
  } else if (const auto* c = std::get_if<Cylinder>(&shape)) {
    for (const Eigen::Vector3d& end : {c->base, Eigen::Vector3d(c->base + c->height * c->axis)}) {
      for (int k = 0; k < 3; ++k) {
        // Extent of a circle of normal `axis` along coordinate k: r * sqrt(1 - axis_k^2).
        Eigen::Vector3d e = Eigen::Vector3d::Zero();
        e[k] = c->radius * std::sqrt(std::max(0.0, 1.0 - c->axis[k] * c->axis[k]));
        box.extend(end + e);
        box.extend(end - e);
      }
    }
  } else if (const auto* s = std::get_if<Sphere>(&shape)) {
    box.extend(s->center - Eigen::Vector3d::Constant(s->radius));
    box.extend(s->center + Eigen::Vector3d::Constant(s->radius));
  }
  return box;
}

Shape Transformed(const Shape& shape, const Eigen::Isometry3d& transform) {
  if (const auto* p = std::get_if<PlanarPatch>(&shape)) {
    PlanarPatch q = *p;
    q.origin = transform * p->origin;
    q.axis_s = transform.linear() * p->axis_s;
    q.axis_t = transform.linear() * p->axis_t;
    return q;
  }
  if (const auto* c = std::get_if<Cylinder>(&shape)) {
    Cylinder q = *c;
    q.base = transform * c->base;
    q.axis = transform.linear() * c->axis;
    return q;
  }
  const Sphere& s = std::get<Sphere>(shape);
  return Sphere{transform * s.center, s.radius};
}

}  // namespace sightline::sim
