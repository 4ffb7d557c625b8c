// Floor plans made of axis-aligned free rectangles (corridors, junctions): the wall faces that
// bound their union, as segments facing the free space.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/sim/scene.h"

namespace sightline::sim {

// An axis-aligned rectangle of free floor, map frame x, y in metres.
struct FreeRect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // x0 < x1, y0 < y1.
};

// The maximal straight wall segments of the boundary of the union of `rects`, each facing the
// free side (WallLine convention: the free side is left of start -> end). Ids are 0, 1, ... in
// a deterministic order. Exact: the rectangles' own coordinates are used, nothing is gridded.
std::vector<WallLine> BoundaryWalls(const std::vector<FreeRect>& rects);

// True when (x, y) lies inside one of `rects`.
bool InsideFreeSpace(const std::vector<FreeRect>& rects, double x, double y);

}  // namespace sightline::sim
