// Accuracy of indoor mapping against ground truth: heading error, wall-angle error of extracted
// lines, which true walls a pose can see, and agreement of the stitched map with the true walls.
// Used by the `mapping` pipeline's metrics.json and by the tests.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/mapping/occupancy_grid_map.h"
#include "core/mapping/pose2d.h"

namespace sightline {

// A true wall face on the floor plan (world frame), e.g. from the simulator's walls.csv.
struct TrueWall {
  int id = 0;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d end = Eigen::Vector2d::Zero();

  double LengthM() const { return (end - start).norm(); }
  double AngleRad() const;  // Direction in [-pi/2, pi/2).
};

// Reads walls.csv ("# wall,x1,y1,x2,y2,..." with a '#' header line). Errors name file and line.
StatusOr<std::vector<TrueWall>> ReadWallsCsv(const std::string& path);

// Heading errors relative to the first frame: e_k = wrap((est_k - est_0) - (true_k - true_0)).
struct HeadingErrors {
  std::vector<double> error_deg;  // |e_k| per frame [deg].
  double mean_deg = 0;
  double max_deg = 0;
  double final_deg = 0;
};
HeadingErrors ComputeHeadingErrors(const std::vector<double>& estimate_rad,
                                   const std::vector<double>& truth_rad);

// The true wall a world-frame segment lies on: the wall with the smallest angle difference
// among those within max_angle_deg whose line passes within max_distance_m of the segment's
// midpoint and whose extent (plus the margin) contains it.
struct WallMatch {
  int wall_index = -1;
  double angle_error_deg = 0;  // Undirected angle difference [deg].
  double distance_m = 0;       // Midpoint to the wall's line [m].
};
std::optional<WallMatch> MatchSegmentToWalls(const Eigen::Vector2d& start_in_world,
                                             const Eigen::Vector2d& end_in_world,
                                             const std::vector<TrueWall>& walls,
                                             double max_angle_deg = 10.0,
                                             double max_distance_m = 0.3);

// How much of each true wall a 2D range sensor at `world_from_base` sees: rays at
// `resolution_rad` over bearings [fov_min, fov_max] up to max_range_m, occluded by every wall
// and by `occluders` (other obstacles: boxes, bins) when given.
struct WallVisibility {
  int wall_index = -1;
  int rays = 0;                 // Rays whose first hit is this wall.
  double visible_length_m = 0;  // Extent of the hits along the wall [m].
};
std::vector<WallVisibility> VisibleWalls(const Pose2d& world_from_base, double fov_min_rad,
                                         double fov_max_rad, double resolution_rad,
                                         double max_range_m, const std::vector<TrueWall>& walls,
                                         const std::vector<TrueWall>& occluders = {});

// The rigid 2D transform truth_from_estimate minimising sum |truth_i - T(estimate_i)|^2
// (Kabsch / Umeyama in 2D). Identity when fewer than 2 points.
Pose2d AlignSe2(const std::vector<Eigen::Vector2d>& estimate,
                const std::vector<Eigen::Vector2d>& truth);

// Agreement of a map's occupied cells with the true walls, with a tolerance of a few cells
// (as boundary F-scores do): precision = occupied cells within tolerance of a wall / occupied
// cells; recall = wall cells the map observed that lie within tolerance of an occupied cell /
// wall cells the map observed; iou = 1 / (1 / precision + 1 / recall - 1), the intersection
// over union these imply.
struct MapAgreement {
  double precision = 0;
  double recall = 0;
  double iou = 0;
  int occupied_cells = 0;
  int wall_cells = 0;  // Observed wall cells.
};
// `truth_from_estimate` maps the map's world frame into the walls' frame.
MapAgreement CompareMapWithWalls(const OccupancyGridMap& map, const std::vector<TrueWall>& walls,
                                 const Pose2d& truth_from_estimate, int tolerance_cells = 1);

}  // namespace sightline
