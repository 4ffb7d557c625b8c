#include "core/sim/panel_scene.h"

#include <cmath>

#include "core/sim/builder_util.h"
#include "core/sim/random.h"
#include "core/sim/texture_images.h"

namespace sightline::sim {
namespace {

constexpr double kPlateThickness = 0.012;
constexpr double kWallHalfWidth = 2.5, kWallHeight = 2.7;

}  // namespace

bool PanelOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& message) {
    if (error) *error = "sim.panel." + message;
    return false;
  };
  if (rows < 1 || rows > 12) return fail("rows must lie in [1, 12]");
  if (columns < 1 || columns > 6) return fail("columns must lie in [1, 6]");
  if (!(button_size_m >= 0.01 && button_size_m <= 0.1)) {
    return fail("button_size_m must lie in [0.01, 0.1] m");
  }
  if (!(pitch_m >= button_size_m + 0.005 && pitch_m <= 0.3)) {
    return fail("pitch_m must lie in [button_size_m + 0.005, 0.3] m");
  }
  if (!(button_depth_m >= 0.001 && button_depth_m <= 0.05)) {
    return fail("button_depth_m must lie in [0.001, 0.05] m");
  }
  if (!(center_height_m >= 0.5 && center_height_m <= 2.0)) {
    return fail("center_height_m must lie in [0.5, 2] m");
  }
  if (!(wall_distance_m >= 0.8 && wall_distance_m <= 5)) {
    return fail("wall_distance_m must lie in [0.8, 5] m");
  }
  if (target_button < 0 || target_button >= rows * columns) {
    return fail("target_button must lie in [0, rows * columns - 1]");
  }
  return true;
}

OptionTable<PanelOptions> PanelOptions::Describe() {
  using O = PanelOptions;
  return OptionTable<O>("panel")
      .Int("rows", &O::rows, "", 1, 12, 1, "Button rows.")
      .Int("columns", &O::columns, "", 1, 6, 1, "Button columns.")
      .Bool("round_buttons", &O::round_buttons, "Round buttons (else square ones).")
      .Double("button_size_m", &O::button_size_m, "m", 0.01, 0.1, 0.002,
              "Button diameter (round) or side (square).")
      .Double("pitch_m", &O::pitch_m, "m", 0.015, 0.3, 0.005,
              "Distance between neighbouring button centres.")
      .Double("button_depth_m", &O::button_depth_m, "m", 0.001, 0.05, 0.001,
              "How far a button stands out of the plate.")
      .Double("center_height_m", &O::center_height_m, "m", 0.5, 2, 0.05,
              "Height of the button grid's centre above the floor.")
      .Double("wall_distance_m", &O::wall_distance_m, "m", 0.8, 5, 0.05,
              "Map x of the wall; the arm's base is at the origin.")
      .Int("target_button", &O::target_button, "", 0, 71, 1,
           "Id of the button the arm approaches (0 = bottom left).");
}

StatusOr<Scene> BuildPanel(const PanelOptions& o, uint64_t seed) {
  std::string error;
  if (!o.IsValid(&error)) return InvalidArgument(error);
  std::mt19937 rng = MakeEngine(DeriveSeed(seed, 0x9A4E1));
  Scene scene("panel");
  scene.background = {0.15f, 0.15f, 0.15f};
  const double wall_x = o.wall_distance_m;
  const Eigen::Vector3d toward(-1, 0, 0), right(0, -1, 0), up(0, 0, 1);

  // Wall and floor.
  const int wall_object = scene.AddObject(ObjectKind::kWall, "wall 0", 0);
  const int marble = scene.AddMaterial({TextureKind::kSpeckle,
                                        JitterColor(rng, {0.8f, 0.76f, 0.7f}, 0.04),
                                        {0.6f, 0.56f, 0.5f},
                                        0.08f,
                                        NextSeed(rng),
                                        0.35f});
  // The wall has an opening for the elevator door (map y in [dy0, dy1], up to dh).
  const double dy0 = 0.35, dy1 = 1.45, dh = 2.1, recess = 0.05;
  AddFacingRectangle(&scene, wall_object, marble, {wall_x, -kWallHalfWidth, 0},
                     {0, dy0 + kWallHalfWidth, 0}, {0, 0, kWallHeight}, toward);
  AddFacingRectangle(&scene, wall_object, marble, {wall_x, dy1, 0}, {0, kWallHalfWidth - dy1, 0},
                     {0, 0, kWallHeight}, toward);
  AddFacingRectangle(&scene, wall_object, marble, {wall_x, dy0, dh}, {0, dy1 - dy0, 0},
                     {0, 0, kWallHeight - dh}, toward);
  scene.walls.push_back({0, {wall_x, -kWallHalfWidth}, {wall_x, kWallHalfWidth}});
  const int floor_object = scene.AddObject(ObjectKind::kFloor, "floor", 0);
  const int tiles = scene.AddMaterial(
      {TextureKind::kTiles, {0.5f, 0.5f, 0.52f}, {0.25f, 0.25f, 0.25f}, 0.4f, NextSeed(rng)});
  scene.AddRectangle(floor_object, tiles, {-1.5, -kWallHalfWidth, 0}, {1, 0, 0}, {0, 1, 0},
                     {wall_x + 1.5, 2 * kWallHalfWidth});

  // Elevator door left of the panel (map +y), recessed 5 cm.
  const int door_object = scene.AddObject(ObjectKind::kDoor, "elevator door", 0);
  const int steel = scene.AddMaterial(
      {TextureKind::kBrushed, {0.7f, 0.72f, 0.75f}, {0.4f, 0.4f, 0.4f}, 0.01f, NextSeed(rng)});
  AddFacingRectangle(&scene, door_object, steel, {wall_x + recess, dy0, 0}, {0, dy1 - dy0, 0},
                     {0, 0, dh}, toward);
  AddFacingRectangle(&scene, door_object, steel, {wall_x, dy0, 0}, {recess, 0, 0}, {0, 0, dh},
                     {0, 1, 0});
  AddFacingRectangle(&scene, door_object, steel, {wall_x, dy1, 0}, {recess, 0, 0}, {0, 0, dh},
                     {0, -1, 0});
  AddFacingRectangle(&scene, door_object, steel, {wall_x, dy0, dh}, {recess, 0, 0},
                     {0, dy1 - dy0, 0}, -up);
  const int gap = scene.AddMaterial({TextureKind::kPlain, {0.08f, 0.08f, 0.08f}});
  AddFacingRectangle(&scene, door_object, gap,
                     {wall_x + recess - 0.001, 0.5 * (dy0 + dy1) - 0.004, 0}, {0, 0.008, 0},
                     {0, 0, dh}, toward);

  // The plate.
  const double grid_w = o.columns * o.pitch_m, grid_h = o.rows * o.pitch_m;
  const double plate_w = grid_w + 0.05, plate_h = grid_h + 0.14;
  const double grid_z = o.center_height_m;
  const double plate_z0 = grid_z - 0.5 * grid_h - 0.03;
  const int plate_object = scene.AddObject(ObjectKind::kPlate, "panel plate", 0);
  const int plate_material = scene.AddMaterial(
      {TextureKind::kBrushed, {0.62f, 0.63f, 0.66f}, {0.4f, 0.4f, 0.4f}, 0.006f, NextSeed(rng)});
  scene.AddBox(plate_object, plate_material, {wall_x - 0.5 * kPlateThickness, 0, plate_z0},
               {kPlateThickness, plate_w, plate_h});
  const double face_x = wall_x - kPlateThickness;
  // Floor display above the buttons.
  Material display{TextureKind::kImage};
  display.image = scene.AddImage(MakeDisplayImage(
      std::to_string(static_cast<int>(Uniform(rng, 0, o.rows * o.columns - 1))), 160, 64));
  const double disp_w = std::min(0.1, plate_w - 0.02), disp_h = 0.04;
  display.image_size_m = {static_cast<float>(disp_w), static_cast<float>(disp_h)};
  scene.AddRectangle(plate_object, scene.AddMaterial(display),
                     {face_x - 0.0005, 0.5 * disp_w, grid_z + 0.5 * grid_h + 0.02}, right, up,
                     {disp_w, disp_h});

  // Buttons, bottom left first as seen from the front (left = map +y).
  const int rim = scene.AddMaterial(
      {TextureKind::kBrushed, {0.5f, 0.5f, 0.52f}, {0.3f, 0.3f, 0.3f}, 0.004f, NextSeed(rng)});
  const double half = 0.5 * o.button_size_m, depth = o.button_depth_m;
  for (int r = 0; r < o.rows; ++r) {
    for (int c = 0; c < o.columns; ++c) {
      const int id = r * o.columns + c;
      const std::string label = std::to_string(id - 1);
      const double y = ((o.columns - 1) * 0.5 - c) * o.pitch_m;
      const double z = grid_z + (r - (o.rows - 1) * 0.5) * o.pitch_m;
      const int object = scene.AddObject(ObjectKind::kButton, "button " + label, id);
      Material face{TextureKind::kImage};
      face.image = scene.AddImage(MakeButtonLabelImage(label, o.round_buttons, 128));
      face.image_size_m = {static_cast<float>(2 * half), static_cast<float>(2 * half)};
      Eigen::Vector3d center;
      if (o.round_buttons) {
        face.image_offset_m = {static_cast<float>(-half), static_cast<float>(-half)};
        center = {face_x - depth, y, z};
        scene.Add({Cylinder{{face_x, y, z}, toward, half, depth}, rim, object});
        scene.AddDisc(object, scene.AddMaterial(face), center, toward, right, half);
      } else {
        scene.AddBox(object, rim, {face_x - 0.5 * depth, y, z - half}, {depth, 2 * half, 2 * half});
        center = {face_x - depth - 0.0002, y, z};
        scene.AddRectangle(object, scene.AddMaterial(face), center + half * (-right - up), right,
                           up, {2 * half, 2 * half});
      }
      scene.buttons.push_back({id, label, center, toward, half, object});
    }
  }
  scene.hints.world_from_arm_base =
      Eigen::Translation3d(0, 0, 0.75) * Eigen::Isometry3d::Identity();
  scene.hints.target_button = o.target_button;
  return scene;
}

}  // namespace sightline::sim
