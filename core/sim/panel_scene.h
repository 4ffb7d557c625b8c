// The `panel` world: a textured wall with an elevator-style button panel and an elevator door,
// for the monocular button localisation with an arm-mounted camera (seed 004).
#pragma once

#include <cstdint>
#include <string>

#include "core/common/status.h"
#include "core/options/option_table.h"
#include "core/sim/scene.h"

namespace sightline::sim {

// The button panel: a metal plate on the wall with rows x columns numbered buttons and a floor
// display above them.
struct PanelOptions {
  int rows = 6;                   // Button rows.
  int columns = 2;                // Button columns.
  bool round_buttons = true;      // Round (true) or square buttons.
  double button_size_m = 0.036;   // Diameter (round) or side (square), metres.
  double pitch_m = 0.06;          // Distance between neighbouring button centres, metres.
  double button_depth_m = 0.005;  // How far a button stands out of the plate, metres.
  double center_height_m = 1.1;   // Height of the button grid's centre above the floor, m.
  double wall_distance_m = 1.25;  // Map x of the wall (the arm's base is near the origin), m.
  int target_button = 5;          // The button the arm approaches (id, see buttons.csv).

  // Checks ranges and that the buttons fit their pitch; names the bad field.
  bool IsValid(std::string* error) const;
  static OptionTable<PanelOptions> Describe();
};

// Builds the panel scene. Map frame: origin on the floor, x towards the wall (the wall faces
// -x), y left, z up. Buttons are numbered row by row from the bottom left as seen from the
// front (id 0 = bottom left), labelled "-1", "0", "1", ...; ButtonSpec::center is the centre of
// the button's front face. The arm's base stands at (0, 0, 0.75) with the map's orientation.
// InvalidArgument for options that fail IsValid().
StatusOr<Scene> BuildPanel(const PanelOptions& options, uint64_t seed);

}  // namespace sightline::sim
