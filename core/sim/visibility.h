// The visibility pass of the simulator's renderer: which surface each pixel's ray hits first.
// Internal to core/sim (used by renderer.cpp and its tests).
//
// Method: every primitive is moved into the camera frame, clipped to the near plane and its
// screen outline is scan-converted; inside that outline each pixel centre's ray is intersected
// with the primitive exactly (planes: inverse depth is affine in the pixel coordinates;
// cylinders and spheres: a quadratic), so depths are exact ray casts while only pixels the
// primitive can cover are visited (no per-pixel search over all primitives).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "core/common/camera.h"
#include "core/sim/scene.h"

namespace sightline::sim {

// A primitive prepared for one view, in the camera frame (z forward, x right, y down).
struct ViewItem {
  enum Kind : uint8_t { kPlane, kDisc, kCylinder, kSphere };
  Kind kind = kPlane;
  int primitive = 0;  // Index in static-then-dynamic order.
  int object = 0;
  int material = 0;
  // Planes and discs: n.p = d with n the front normal; s = axis_s.p - s0, t = axis_t.p - t0.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double d = 0;
  Eigen::Vector3d axis_s = Eigen::Vector3d::Zero(), axis_t = Eigen::Vector3d::Zero();
  double s0 = 0, t0 = 0;
  double radius = 0;  // Discs, cylinders, spheres.
  // Cylinders: base, axis, height, and two unit vectors spanning the cross-section.
  Eigen::Vector3d base = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::Zero();
  Eigen::Vector3d ref_u = Eigen::Vector3d::Zero(), ref_v = Eigen::Vector3d::Zero();
  double height = 0;
  // Spheres: centre.
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  // Screen bounds: planes and discs list their outline corners, curved shapes the 8 corners of
  // their bounding box, as a range of PreparedView::points.
  int points_begin = 0, points_count = 0;
};

// The primitives of one view, reused from frame to frame to avoid allocations.
struct PreparedView {
  std::vector<ViewItem> items;
  std::vector<Eigen::Vector3d> points;  // Camera frame.
};

// Per-pixel ray directions (x/z and y/z of the ray through each pixel centre).
struct RayTable {
  std::vector<float> x;               // Per column: (u - cx) / fx.
  std::vector<float> y;               // Per row: (v - cy) / fy.
  std::vector<float> inverse_length;  // Per pixel (row-major): 1 / |(x, y, 1)|.
};

// Fills `table` for `camera` (pixel centres at integer coordinates, as PinholeCamera).
void MakeRayTable(const PinholeCamera& camera, RayTable* table);

// Prepares the primitives for the view (culling those behind the camera or facing away).
void PrepareView(const Scene& scene, const std::vector<Primitive>& dynamic,
                 const Eigen::Isometry3d& camera_from_world, PreparedView* view);

// Writes, per pixel, the inverse depth (1/z, 0 = nothing) and the index into view.items of the
// nearest surface hit at z >= near_m (-1 = nothing). Both buffers hold width * height values.
void RasterizeVisibility(const PreparedView& view, const PinholeCamera& camera,
                         const RayTable& rays, double near_m, std::vector<float>* inverse_depth,
                         std::vector<int32_t>* item_index);

}  // namespace sightline::sim
