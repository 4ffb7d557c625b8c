// Normals on the organized pixel grid (mode "grid"): PCA of the points in a square window of
// cells, from box sums of the point moments slid along the grid, with the smallest eigenvalue
// by Newton steps several windows at a time.
#pragma once

#include "core/mobility/mobility_types.h"

namespace sightline {

// Normals by PCA of the points in a (2 window + 1)^2 cell window, from box sums of the moments
// slid along the grid (constant time per point), oriented towards the viewpoint (seed eq. 4).
// Points whose surface variation (smallest eigenvalue / sum) exceeds max_curvature get none.
void GridNormals(int window, double max_curvature, WorkingCloud* cloud);

}  // namespace sightline
