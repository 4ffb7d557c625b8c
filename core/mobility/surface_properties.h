// Per-segment surface properties (seed eqs. 7-10): plane fit by RANSAC and least squares,
// slope against the ground normal, roughness as the ratio of 3D to projected triangle area over
// one triangulation in plane coordinates, area and the height raised above the ground.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/mobility/mobility_options.h"
#include "core/mobility/mobility_types.h"

namespace sightline {

// A fitted plane: unit normal and a point on it.
struct SegmentPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  int inliers = 0;
};

// RANSAC (iterations, inlier distance) then least squares on the inliers; PCA of all points
// when iterations is 0. InvalidArgument for fewer than 3 points or collinear points.
StatusOr<SegmentPlane> FitSegmentPlane(const std::vector<Eigen::Vector3f>& points, int iterations,
                                       double distance_m, unsigned seed = 1);

// What the roughness triangulation gave.
struct RoughnessResult {
  double roughness = 1;  // Sum of 3D areas / sum of projected areas (>= 1).
  double projected_area_m2 = 0;
  double surface_area_m2 = 0;
  int cells = 0;  // Occupied plane cells.
  int triangles = 0;
};

// Projects the points onto the plane, averages them in square cells of cell_m (the mean (u, v)
// and height of each cell), triangulates the cell means once in plane coordinates
// ("grid": two triangles per square of four occupied cells; "delaunay": cv::Subdiv2D, dropping
// triangles with an edge longer than max_edge_cells cells) and returns the area ratio.
// InvalidArgument when no triangle can be formed.
StatusOr<RoughnessResult> ComputeRoughness(const std::vector<Eigen::Vector3f>& points,
                                           const SegmentPlane& plane, double cell_m,
                                           const std::string& triangulation, double max_edge_cells);

// The number of plane cells of cell_m the points occupy (ComputeRoughness's cells, without
// the triangulation).
int CountPlaneCells(const std::vector<Eigen::Vector3f>& points, const SegmentPlane& plane,
                    double cell_m);

// All properties of one segment (scores are left 0). `ground` is the found ground (for the
// ground segment itself the slope is 0 by definition). InvalidArgument, naming the segment,
// when the segment has too few points or no plane.
StatusOr<SegmentProperties> MeasureSegment(int id, bool is_ground,
                                           const std::vector<Eigen::Vector3f>& points,
                                           const GroundPlane& ground,
                                           const MobilityOptions& options);

}  // namespace sightline
