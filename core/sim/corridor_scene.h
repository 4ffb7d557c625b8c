// The `corridor` world: an indoor office corridor loop for the Kinect mapping pipeline (seed 000)
// and stereo odometry (seed 003).
#pragma once

#include <cstdint>
#include <string>

#include "core/common/status.h"
#include "core/options/option_table.h"
#include "core/sim/scene.h"

namespace sightline::sim {

// The corridor's layout. The corridor is a rectangular loop (four L junctions at right angles)
// with two dead-end side branches (T junctions); walls carry recessed doors with lintels,
// posters and room signs; boxes and bins stand along the walls; people walk.
struct CorridorOptions {
  double loop_length_m = 16.0;    // Centreline length of the first corridor (map x), metres.
  double loop_width_m = 10.0;     // Centreline length of the second corridor (map y), metres.
  double corridor_width_m = 2.0;  // Wall to wall, metres.
  double height_m = 2.6;          // Floor to ceiling, metres.
  double branch_length_m = 3.0;   // Length of each dead-end side corridor, metres.
  double door_spacing_m = 3.0;    // Mean distance between doors along a wall, metres.
  double door_recess_m = 0.1;     // Depth of a door behind the wall face, metres.
  int boxes = 4;                  // Cardboard boxes along the walls.
  int bins = 2;                   // Waste bins along the walls.
  int posters = 8;                // Posters on the walls.
  int people = 2;                 // Walking people (0, 1 or 2): a leader ahead, a passer-by.
  double people_speed_mps = 0.5;  // Speed of the person walking ahead, m/s.

  // Checks ranges and that the branches and doors fit; names the bad field.
  bool IsValid(std::string* error) const;
  static OptionTable<CorridorOptions> Describe();
};

// Builds the corridor. Map frame: origin on the floor where the centrelines of the first and the
// last corridor of the loop cross, x along the first corridor, y into the loop, z up. The robot
// route is the loop's centreline, driven counter-clockwise (left turns) from (1, 0). Ground
// truth: every wall face (walls), the people, and the floor as one region. InvalidArgument
// for options that fail IsValid().
StatusOr<Scene> BuildCorridor(const CorridorOptions& options, uint64_t seed);

}  // namespace sightline::sim
