// Ground truth of simulated terrain (regions.csv: region, kind, slope, roughness, height,
// footprint polygon) and the matching of measured segments to true regions for accuracy.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/mobility/mobility_types.h"

namespace sightline {

// One true region of the terrain (map frame: z up, floor at z = 0).
struct TrueRegion {
  int id = 0;
  std::string kind;  // floor, ramp, platform, step, rough, box, wall.
  double slope_deg = 0;
  double roughness = 1;
  double height_m = 0;
  std::vector<Eigen::Vector2d> polygon;  // Footprint (map x, y).
};

// Reads regions.csv; errors name the file and line.
StatusOr<std::vector<TrueRegion>> ReadTerrainRegions(const std::string& path);

// A segment matched to the true region holding most of its points.
struct SegmentMatch {
  int segment = 0;      // Index into MobilityResult::segments.
  int region = -1;      // Index into the regions, -1 = none.
  double fraction = 0;  // Of the segment's points inside the region.
};

// Matches each segment to the region whose footprint holds most of its points (a point
// belongs to a region when inside its footprint and, for all but the floor and walls, above
// 1 cm). Needs world_from_camera (the camera's true pose in the map frame).
std::vector<SegmentMatch> MatchSegmentsToRegions(const MobilityResult& result,
                                                 const Eigen::Isometry3d& world_from_camera,
                                                 const std::vector<TrueRegion>& regions);

// Whether a point (map x, y) lies inside a polygon (even-odd rule).
bool InsidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

}  // namespace sightline
