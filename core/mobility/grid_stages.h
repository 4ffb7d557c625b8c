// The per-point stages on the organized pixel grid (mode "grid"): downsampling by a pixel
// stride, range cut, statistical outlier removal over grid neighbours and the grid neighbours
// the region growing walks (normals: grid_normals.h).
#pragma once

#include <vector>

#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/mobility/mobility_types.h"

namespace sightline {

// Every stride-th pixel of an organized cloud (NaN points left out). FailedPrecondition for an
// unorganized cloud.
StatusOr<WorkingCloud> GridDownsample(const PointCloud& cloud, int stride);

// Drops points farther than max_range_m from the sensor (and non-finite ones). Any mode.
void RangeCut(double max_range_m, WorkingCloud* cloud);

// Seed eq. 1 over the 8 grid neighbours: d_i = mean distance to the neighbours divided by the
// depth (grid spacing grows with depth), kept when d_i <= mu + alpha sigma; isolated points go.
void GridRemoveOutliers(double alpha, WorkingCloud* cloud);

// The 4-connected grid neighbours of point i whose depths differ by at most max_depth_jump
// times the nearer depth (symmetric: j is i's neighbour when i is j's).
void GridNeighbors(const WorkingCloud& cloud, int i, double max_depth_jump, std::vector<int>* out);

}  // namespace sightline
