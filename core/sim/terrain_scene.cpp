#include "core/sim/terrain_scene.h"

#include <algorithm>
#include <cmath>

#include "core/sim/builder_util.h"
#include "core/sim/random.h"

namespace sightline::sim {
namespace {

constexpr double kRampX = 1.3, kRampY0 = 0.35;  // Foot of the ramp, its right edge.
constexpr double kPlatformLength = 0.5;
constexpr double kRoughX0 = 1.2, kRoughY0 = -1.35, kRoughLength = 1.0, kRoughWidth = 0.8;
constexpr double kStepX0 = 1.7, kStepX1 = 2.4, kStepY0 = -0.35, kStepY1 = 0.25;

double RampLength(const TerrainOptions& o) {
  return o.ramp_rise_m / std::tan(o.ramp_slope_deg * M_PI / 180);
}

std::vector<Eigen::Vector2d> Rect2(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A heightfield over a grid of cells (nx x ny) with zero height on the border.
struct Heightfield {
  int nx = 0, ny = 0;
  double cell = 0;
  std::vector<double> unit;  // Heights for amplitude 1, (nx + 1) * (ny + 1), row-major in y.
  double H(int i, int j, double amplitude) const { return amplitude * unit[j * (nx + 1) + i]; }
  Eigen::Vector3d P(double x0, double y0, int i, int j, double amplitude) const {
    return {x0 + i * cell, y0 + j * cell, H(i, j, amplitude)};
  }
  // Sum of 3D facet areas / sum of projected areas.
  double Roughness(double amplitude) const {
    double area = 0;
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const Eigen::Vector3d a = P(0, 0, i, j, amplitude), b = P(0, 0, i + 1, j, amplitude);
        const Eigen::Vector3d c = P(0, 0, i + 1, j + 1, amplitude),
                              d = P(0, 0, i, j + 1, amplitude);
        area += 0.5 * (b - a).cross(c - a).norm() + 0.5 * (c - a).cross(d - a).norm();
      }
    }
    return area / (nx * ny * cell * cell);
  }
};

}  // namespace

bool TerrainOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& message) {
    if (error) *error = "sim.terrain." + message;
    return false;
  };
  if (!(ramp_slope_deg >= 1 && ramp_slope_deg <= 60)) {
    return fail("ramp_slope_deg must lie in [1, 60] deg");
  }
  if (!(ramp_rise_m >= 0.02 && ramp_rise_m <= 1.0))
    return fail("ramp_rise_m must lie in [0.02, 1] m");
  if (!(ramp_width_m >= 0.2 && ramp_width_m <= 2.0))
    return fail("ramp_width_m must lie in [0.2, 2] m");
  if (!(step_height_m >= 0.01 && step_height_m <= 1.0)) {
    return fail("step_height_m must lie in [0.01, 1] m");
  }
  if (!(roughness >= 1.0 && roughness <= 2.0)) return fail("roughness must lie in [1, 2]");
  if (!(rough_cell_m >= 0.01 && rough_cell_m <= 0.2)) {
    return fail("rough_cell_m must lie in [0.01, 0.2] m");
  }
  if (boxes < 0 || boxes > 10) return fail("boxes must lie in [0, 10]");
  const double needed = std::max(3.8, kRampX + RampLength(*this) + kPlatformLength + 0.8);
  if (!(wall_distance_m >= needed && wall_distance_m <= 50)) {
    return fail("wall_distance_m must lie in [" + std::to_string(needed) +
                ", 50] m (the ramp and platform must fit before the wall)");
  }
  return true;
}

OptionTable<TerrainOptions> TerrainOptions::Describe() {
  using O = TerrainOptions;
  return OptionTable<O>("terrain")
      .Double("ramp_slope_deg", &O::ramp_slope_deg, "deg", 1, 60, 1, "Ramp inclination.")
      .Double("ramp_rise_m", &O::ramp_rise_m, "m", 0.02, 1, 0.01,
              "Height the ramp climbs to (the platform's height).")
      .Double("ramp_width_m", &O::ramp_width_m, "m", 0.2, 2, 0.05, "Width of ramp and platform.")
      .Double("step_height_m", &O::step_height_m, "m", 0.01, 1, 0.01, "Height of the step block.")
      .Double("roughness", &O::roughness, "", 1, 2, 0.01,
              "Roughness of the rough patch: 3D facet area / projected area (1 = flat).")
      .Double("rough_cell_m", &O::rough_cell_m, "m", 0.01, 0.2, 0.01,
              "Facet size of the rough patch.")
      .Int("boxes", &O::boxes, "", 0, 10, 1, "Boxes in front of the wall.")
      .Double("wall_distance_m", &O::wall_distance_m, "m", 3.8, 50, 0.1,
              "Map x of the wall behind the objects.");
}

StatusOr<Scene> BuildTerrain(const TerrainOptions& o, uint64_t seed) {
  std::string error;
  if (!o.IsValid(&error)) return InvalidArgument(error);
  std::mt19937 rng = MakeEngine(DeriveSeed(seed, 0x7E44A1));
  Scene scene("terrain");
  scene.background = {0.6f, 0.66f, 0.72f};
  int region = 0;
  auto material = [&](const Eigen::Vector3f& color, const Eigen::Vector3f& accent, float scale,
                      float density = 0.6f) {
    return scene.AddMaterial({TextureKind::kSpeckle, JitterColor(rng, color, 0.04), accent, scale,
                              NextSeed(rng), density});
  };

  // Rough patch: random facet heights scaled until the roughness matches.
  Heightfield field;
  field.cell = o.rough_cell_m;
  field.nx = std::max(2, static_cast<int>(std::round(kRoughLength / o.rough_cell_m)));
  field.ny = std::max(2, static_cast<int>(std::round(kRoughWidth / o.rough_cell_m)));
  field.cell = kRoughLength / field.nx;
  std::mt19937 height_rng = MakeEngine(DeriveSeed(seed, 0x40C6));
  for (int j = 0; j <= field.ny; ++j) {
    for (int i = 0; i <= field.nx; ++i) {
      const bool border = i == 0 || j == 0 || i == field.nx || j == field.ny;
      field.unit.push_back(border ? 0.0 : Normal(height_rng));
    }
  }
  double lo = 0, hi = 0.01;
  while (field.Roughness(hi) < o.roughness && hi < 10) hi *= 2;
  for (int k = 0; k < 100 && o.roughness > 1; ++k) {
    const double mid = 0.5 * (lo + hi);
    (field.Roughness(mid) < o.roughness ? lo : hi) = mid;
  }
  const double amplitude = o.roughness > 1 ? 0.5 * (lo + hi) : 0.0;
  // Floor with a hole for the rough patch.
  const double fx0 = -3, fx1 = o.wall_distance_m, fy0 = -3, fy1 = 3;
  const double rx1 = kRoughX0 + field.nx * field.cell, ry1 = kRoughY0 + field.ny * field.cell;
  const int floor_object = scene.AddObject(ObjectKind::kFloor, "floor", region);
  const int concrete = material({0.6f, 0.6f, 0.58f}, {0.45f, 0.45f, 0.43f}, 0.12f, 0.35f);
  for (const auto& r :
       {Eigen::Vector4d(fx0, fy0, fx1, kRoughY0), Eigen::Vector4d(fx0, ry1, fx1, fy1),
        Eigen::Vector4d(fx0, kRoughY0, kRoughX0, ry1), Eigen::Vector4d(rx1, kRoughY0, fx1, ry1)}) {
    scene.AddRectangle(floor_object, concrete, {r[0], r[1], 0}, {1, 0, 0}, {0, 1, 0},
                       {r[2] - r[0], r[3] - r[1]});
  }
  scene.regions.push_back({region++, "floor", 0, 1, 0, Rect2(fx0, fy0, fx1, fy1)});

  // Ramp and platform.
  const double ramp_length = RampLength(o), rise = o.ramp_rise_m;
  const double y0 = kRampY0, y1 = kRampY0 + o.ramp_width_m, xe = kRampX + ramp_length;
  const int ramp_object = scene.AddObject(ObjectKind::kRamp, "ramp", region);
  const int ramp_material = material({0.35f, 0.45f, 0.6f}, {0.15f, 0.2f, 0.3f}, 0.08f);
  scene.AddPolygon(ramp_object, ramp_material,
                   {{kRampX, y0, 0}, {xe, y0, rise}, {xe, y1, rise}, {kRampX, y1, 0}});
  scene.AddPolygon(ramp_object, ramp_material, {{kRampX, y0, 0}, {xe, y0, 0}, {xe, y0, rise}});
  scene.AddPolygon(ramp_object, ramp_material, {{kRampX, y1, 0}, {xe, y1, rise}, {xe, y1, 0}});
  scene.regions.push_back({region++, "ramp", o.ramp_slope_deg, 1, rise, Rect2(kRampX, y0, xe, y1)});
  const int platform_object = scene.AddObject(ObjectKind::kRamp, "platform", region);
  scene.AddBox(platform_object, ramp_material, {xe + 0.5 * kPlatformLength, 0.5 * (y0 + y1), 0},
               {kPlatformLength, o.ramp_width_m, rise});
  scene.regions.push_back(
      {region++, "platform", 0, 1, rise, Rect2(xe, y0, xe + kPlatformLength, y1)});

  // Step.
  const int step_object = scene.AddObject(ObjectKind::kStep, "step", region);
  scene.AddBox(step_object, material({0.65f, 0.35f, 0.3f}, {0.35f, 0.15f, 0.12f}, 0.07f),
               {0.5 * (kStepX0 + kStepX1), 0.5 * (kStepY0 + kStepY1), 0},
               {kStepX1 - kStepX0, kStepY1 - kStepY0, o.step_height_m});
  scene.regions.push_back(
      {region++, "step", 0, 1, o.step_height_m, Rect2(kStepX0, kStepY0, kStepX1, kStepY1)});

  const int rough_object = scene.AddObject(ObjectKind::kRough, "rough patch", region);
  const int gravel = material({0.55f, 0.48f, 0.38f}, {0.3f, 0.25f, 0.2f}, 0.03f);
  double max_height = 0;
  for (int j = 0; j < field.ny; ++j) {
    for (int i = 0; i < field.nx; ++i) {
      const Eigen::Vector3d a = field.P(kRoughX0, kRoughY0, i, j, amplitude);
      const Eigen::Vector3d b = field.P(kRoughX0, kRoughY0, i + 1, j, amplitude);
      const Eigen::Vector3d c = field.P(kRoughX0, kRoughY0, i + 1, j + 1, amplitude);
      const Eigen::Vector3d d = field.P(kRoughX0, kRoughY0, i, j + 1, amplitude);
      scene.AddPolygon(rough_object, gravel, {a, b, c});
      scene.AddPolygon(rough_object, gravel, {a, c, d});
      max_height = std::max({max_height, a.z(), b.z(), c.z(), d.z()});
    }
  }
  scene.regions.push_back({region++, "rough", 0, field.Roughness(amplitude), max_height,
                           Rect2(kRoughX0, kRoughY0, rx1, ry1)});

  // Boxes in front of the wall, then the wall.
  const double wall_x = o.wall_distance_m;
  for (int i = 0; i < o.boxes; ++i) {
    const double size = Uniform(rng, 0.3, 0.5), height = Uniform(rng, 0.25, 0.6);
    const double x = wall_x - 0.9 + Uniform(rng, -0.2, 0.2);
    const double y = -1.6 + 3.2 * (i + 0.5) / o.boxes + Uniform(rng, -0.2, 0.2);
    const double yaw = Uniform(rng, -0.5, 0.5);
    const int box_object = scene.AddObject(ObjectKind::kBox, "box " + std::to_string(i), region);
    scene.AddBox(box_object, material({0.66f, 0.5f, 0.32f}, {0.35f, 0.26f, 0.16f}, 0.07f),
                 {x, y, 0}, {size, size, height}, yaw);
    // The footprint of a yawed square box.
    std::vector<Eigen::Vector2d> footprint;
    for (const auto& c : Rect2(-0.5 * size, -0.5 * size, 0.5 * size, 0.5 * size)) {
      footprint.emplace_back(x + std::cos(yaw) * c.x() - std::sin(yaw) * c.y(),
                             y + std::sin(yaw) * c.x() + std::cos(yaw) * c.y());
    }
    scene.regions.push_back({region++, "box", 0, 1, height, footprint});
  }
  const int wall_object = scene.AddObject(ObjectKind::kWall, "wall 0", 0);
  const int wall_material = material({0.8f, 0.78f, 0.72f}, {0.55f, 0.52f, 0.48f}, 0.15f, 0.35f);
  AddFacingRectangle(&scene, wall_object, wall_material, {wall_x, fy0, 0}, {0, fy1 - fy0, 0},
                     {0, 0, 2.0}, -Eigen::Vector3d::UnitX());
  scene.walls.push_back({0, {wall_x, fy0}, {wall_x, fy1}});  // Faces -x: left of +y.
  scene.regions.push_back({region++, "wall", 90, 1, 2.0, Rect2(wall_x, fy0, wall_x + 0.01, fy1)});

  scene.hints.route = {{-0.2, 0}, {1.0, 0}};
  scene.hints.route_loops = false;
  return scene;
}

}  // namespace sightline::sim
