// RGB-N colour coding and region growing on the normal colours (seed eq. 5 and Algorithm 1).
#pragma once

#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "core/mobility/mobility_types.h"

namespace sightline {

// The fixed colour map c = 255 (n + 1) / 2 per component (R from x, G from y, B from z), so a
// colour threshold means the same in every frame (the seed's per-frame min-max is not used).
// Points without a normal get (0, 0, 0).
std::vector<cv::Vec3b> EncodeNormals(const std::vector<Eigen::Vector3f>& normals);

// Appends the neighbours of point i to the (cleared) vector.
using NeighborFunction = std::function<void(int i, std::vector<int>* neighbors)>;

// Flood fill over `neighbors` among the points with eligible[i] != 0: a neighbour joins the
// region when its RGB-N colour lies within color_threshold (Euclidean, colour units) of the
// point it is reached from. Seeds are taken in index order (deterministic). Regions smaller
// than min_points are dropped. Returns the region of each point (0, 1, ...; -1 = none) and the
// region count in *regions.
std::vector<int> GrowRegions(const std::vector<cv::Vec3b>& rgbn,
                             const std::vector<uint8_t>& eligible, double color_threshold,
                             int min_points, const NeighborFunction& neighbors, int* regions);

// The same regions on the organized grid by label propagation instead of a flood fill: one
// pass joins each point to its left and upper grid neighbours (union-find), a second numbers
// the regions by their first point. Grid neighbours are linked when both are eligible, their
// colours lie within color_threshold and their depths differ by at most max_depth_jump times
// the nearer depth (the link of GridNeighbors). Gives GrowRegions' labels with GridNeighbors.
std::vector<int> GrowGridRegions(const WorkingCloud& cloud, const std::vector<cv::Vec3b>& rgbn,
                                 const std::vector<uint8_t>& eligible, double color_threshold,
                                 double max_depth_jump, int min_points, int* regions);

}  // namespace sightline
