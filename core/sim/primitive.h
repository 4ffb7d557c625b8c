// Geometric primitives of simulated scenes, in the scene's map frame (metres, z up).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <variant>
#include <vector>

namespace sightline::sim {

// The outline of a planar patch in its local (s, t) coordinates.
enum class PatchShape {
  kRectangle,  // [0, size.x] x [0, size.y].
  kDisc,       // Radius size.x around (0, 0).
  kPolygon,    // Convex polygon `polygon` (any winding).
};

// A flat surface piece: walls, floors, box faces, ramps, buttons, posters. Points are
// origin + s * axis_s + t * axis_t; the front side faces normal() = axis_s x axis_t.
struct PlanarPatch {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_s = Eigen::Vector3d::UnitX();  // Unit.
  Eigen::Vector3d axis_t = Eigen::Vector3d::UnitY();  // Unit, orthogonal to axis_s.
  PatchShape shape = PatchShape::kRectangle;
  Eigen::Vector2d size = Eigen::Vector2d::Ones();  // Rectangle extents; size.x = disc radius.
  std::vector<Eigen::Vector2d> polygon;            // kPolygon vertices.
  bool two_sided = false;  // False: invisible from behind (closed solids, walls seen from inside).

  // The front-side unit normal.
  Eigen::Vector3d normal() const { return axis_s.cross(axis_t); }
  // The outline's corners (rectangle, polygon) or a circumscribed octagon (disc), in (s, t).
  std::vector<Eigen::Vector2d> Outline() const;
  // The point at local (s, t).
  Eigen::Vector3d At(double s, double t) const { return origin + s * axis_s + t * axis_t; }
};

// The side surface of a finite cylinder (people's bodies, bins); caps are separate discs.
// Texture coordinates: s = arc length around the axis from ref, t = height along the axis.
struct Cylinder {
  Eigen::Vector3d base = Eigen::Vector3d::Zero();   // Centre of the bottom circle.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // Unit.
  double radius = 0.2;
  double height = 1.0;
};

// A sphere (heads). Texture coordinates: longitude and latitude arc lengths.
struct Sphere {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.1;
};

// Any primitive shape.
using Shape = std::variant<PlanarPatch, Cylinder, Sphere>;

// A shape with its material (index into Scene::materials()) and the scene object it belongs to
// (index into Scene::objects(): a wall, a box, a person, a button).
struct Primitive {
  Shape shape;
  int material = 0;
  int object = 0;
};

// Axis-aligned bounds of a shape in its frame.
Eigen::AlignedBox3d BoundsOf(const Shape& shape);

// A copy of `shape` moved by `transform` (a rigid motion).
Shape Transformed(const Shape& shape, const Eigen::Isometry3d& transform);

}  // namespace sightline::sim
