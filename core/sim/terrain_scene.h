// The `terrain` world: floor, ramp, step, rough patch, boxes and a wall, with the slope and
// roughness of every region known exactly, for the RGB-D mobility map (seed 001).
#pragma once

#include <cstdint>
#include <string>

#include "core/common/status.h"
#include "core/options/option_table.h"
#include "core/sim/scene.h"

namespace sightline::sim {

// The terrain's layout: ahead of the robot (map +x) a ramp on the left rises to a platform, a
// step stands in the middle, a rough patch lies on the right, boxes and a wall behind.
struct TerrainOptions {
  double ramp_slope_deg = 20.0;  // Ramp inclination, degrees.
  double ramp_rise_m = 0.25;     // Height the ramp climbs to (the platform's height), metres.
  double ramp_width_m = 0.8;     // Metres.
  double step_height_m = 0.12;   // Height of the step block, metres.
  double roughness = 1.15;       // Target roughness of the rough patch (3D / projected area).
  double rough_cell_m = 0.05;    // Facet size of the rough patch, metres.
  int boxes = 2;                 // Boxes in front of the wall.
  double wall_distance_m = 4.0;  // Map x of the wall, metres.

  // Checks ranges and that everything fits before the wall; names the bad field.
  bool IsValid(std::string* error) const;
  static OptionTable<TerrainOptions> Describe();
};

// Builds the terrain. Map frame: origin on the floor, x ahead (towards the wall), y left, z up;
// the default route runs along y = 0 from x = -0.2 towards the objects. Regions: floor, ramp
// (slope = ramp_slope_deg), platform, step, rough (roughness computed exactly from its facets,
// matching `roughness` to 1e-6), boxes (tops) and the wall (slope 90). InvalidArgument for
// options that fail IsValid().
StatusOr<Scene> BuildTerrain(const TerrainOptions& options, uint64_t seed);

}  // namespace sightline::sim
