#include "core/sim/corridor_scene.h"

#include <algorithm>
#include <cmath>

#include "core/sim/builder_util.h"
#include "core/sim/floor_plan.h"
#include "core/sim/random.h"
#include "core/sim/texture_images.h"

namespace sightline::sim {
namespace {

constexpr double kDoorWidth = 0.9;
constexpr double kEndMargin = 0.8;  // Doors, boxes and posters keep this far from wall ends.

// One wall face in its own frame: s from `end` towards `start`, up, and the facing normal.
struct WallFrame {
  Eigen::Vector3d origin, along, normal;
  double length;
  Eigen::Vector3d At(double s, double z, double out = 0) const {
    return origin + s * along + z * Eigen::Vector3d::UnitZ() + out * normal;
  }
};

WallFrame FrameOf(const WallLine& wall) {
  WallFrame f;
  f.origin = Eigen::Vector3d(wall.end.x(), wall.end.y(), 0);
  const Eigen::Vector2d e = (wall.start - wall.end).normalized();
  f.along = Eigen::Vector3d(e.x(), e.y(), 0);
  f.normal = f.along.cross(Eigen::Vector3d::UnitZ());
  f.length = (wall.start - wall.end).norm();
  return f;
}

// Everything placed along one wall.
struct WallPlan {
  WallFrame frame;
  std::vector<Eigen::Vector2d> doors;  // [a, b] along s.
  IntervalSet high;                    // Doors, signs and posters.
  IntervalSet low;                     // Doors, boxes and bins.
};

class CorridorBuilder {
 public:
  CorridorBuilder(const CorridorOptions& o, uint64_t seed)
      : o_(o), rng_(MakeEngine(DeriveSeed(seed, 0xC0441D04))), scene_("corridor") {}

  StatusOr<Scene> Build() {
    const double hw = 0.5 * o_.corridor_width_m, lx = o_.loop_length_m, ly = o_.loop_width_m;
    std::vector<FreeRect> rects = {{-hw, -hw, lx + hw, hw},
                                   {lx - hw, -hw, lx + hw, ly + hw},
                                   {-hw, ly - hw, lx + hw, ly + hw},
                                   {-hw, -hw, hw, ly + hw}};
    if (o_.branch_length_m > 0) {
      const double bx = std::round(0.45 * lx * 10) / 10, by = std::round(0.5 * ly * 10) / 10;
      rects.push_back({bx - hw, -hw - o_.branch_length_m, bx + hw, -hw});          // T off x.
      rects.push_back({lx + hw, by - hw, lx + hw + o_.branch_length_m, by + hw});  // T off y.
    }
    AddFloorAndCeiling(rects);
    scene_.walls = BoundaryWalls(rects);
    for (const WallLine& wall : scene_.walls) plans_.push_back(PlanWall(wall));
    for (int i = 0; i < o_.posters; ++i) AddPoster(i);
    for (int i = 0; i < o_.boxes; ++i) AddBoxAlongWall(i);
    for (int i = 0; i < o_.bins; ++i) AddBin(i);
    AddPeople();
    scene_.hints.route = {{1, 0}, {lx, 0}, {lx, ly}, {0, ly}, {0, 0}};
    scene_.hints.route_loops = true;
    scene_.background = {0.1f, 0.1f, 0.1f};
    return std::move(scene_);
  }

 private:
  void AddFloorAndCeiling(const std::vector<FreeRect>& rects) {
    double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
    for (const FreeRect& r : rects) {
      x0 = std::min(x0, r.x0), y0 = std::min(y0, r.y0);
      x1 = std::max(x1, r.x1), y1 = std::max(y1, r.y1);
    }
    // Beyond the walls too, so the floor runs under the recessed doors.
    const double margin = o_.door_recess_m + 0.1;
    x0 -= margin, y0 -= margin, x1 += margin, y1 += margin;
    Material floor{
        TextureKind::kTiles, {0.62f, 0.6f, 0.56f}, {0.3f, 0.29f, 0.27f}, 0.5f, NextSeed(rng_)};
    const int floor_object = scene_.AddObject(ObjectKind::kFloor, "floor", 0);
    scene_.AddRectangle(floor_object, scene_.AddMaterial(floor), {x0, y0, 0}, {1, 0, 0}, {0, 1, 0},
                        {x1 - x0, y1 - y0});
    scene_.regions.push_back({0, "floor", 0, 1, 0, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}});
    Material ceiling{
        TextureKind::kTiles, {0.85f, 0.85f, 0.82f}, {0.55f, 0.55f, 0.55f}, 0.6f, NextSeed(rng_)};
    const int ceiling_object = scene_.AddObject(ObjectKind::kCeiling, "ceiling");
    const double h = o_.height_m;
    scene_.AddRectangle(ceiling_object, scene_.AddMaterial(ceiling), {x0, y0, h}, {0, 1, 0},
                        {1, 0, 0}, {y1 - y0, x1 - x0});
    // Light panels along every corridor's centreline, every 2.4 m.
    const int light = scene_.AddMaterial({TextureKind::kPlain, {1.6f, 1.6f, 1.5f}});
    for (const FreeRect& r : rects) {
      const bool along_x = r.x1 - r.x0 >= r.y1 - r.y0;
      const double length = along_x ? r.x1 - r.x0 : r.y1 - r.y0;
      for (double s = 1.2; s + 0.6 < length; s += 2.4) {
        const Eigen::Vector3d c = along_x
                                      ? Eigen::Vector3d(r.x0 + s, 0.5 * (r.y0 + r.y1), h - 0.005)
                                      : Eigen::Vector3d(0.5 * (r.x0 + r.x1), r.y0 + s, h - 0.005);
        const Eigen::Vector3d a = along_x ? Eigen::Vector3d(1.2, 0, 0) : Eigen::Vector3d(0, 1.2, 0);
        const Eigen::Vector3d b = along_x ? Eigen::Vector3d(0, 0.6, 0) : Eigen::Vector3d(0.6, 0, 0);
        AddFacingRectangle(&scene_, ceiling_object, light, c - 0.5 * a - 0.5 * b, a, b,
                           -Eigen::Vector3d::UnitZ());
      }
    }
  }

  WallPlan PlanWall(const WallLine& wall) {
    WallPlan plan;
    plan.frame = FrameOf(wall);
    const WallFrame& f = plan.frame;
    const double h = o_.height_m, door_h = std::min(2.1, h - 0.25);
    Material paint{TextureKind::kSpeckle,
                   JitterColor(rng_, {0.84f, 0.81f, 0.74f}, 0.06),
                   JitterColor(rng_, {0.6f, 0.57f, 0.52f}, 0.08),
                   0.16f,
                   NextSeed(rng_),
                   0.3f};
    const int material = scene_.AddMaterial(paint);
    const int object =
        scene_.AddObject(ObjectKind::kWall, "wall " + std::to_string(wall.id), wall.id);
    // Doors at jittered, roughly even spacing; some slots stay empty.
    const double usable = f.length - 2 * kEndMargin;
    const int slots = usable > kDoorWidth ? static_cast<int>(usable / o_.door_spacing_m) : 0;
    for (int k = 0; k < slots; ++k) {
      const double center =
          kEndMargin + (k + 0.5) * usable / slots + Uniform(rng_, -0.2, 0.2) * o_.door_spacing_m;
      if (Uniform(rng_, 0, 1) < 0.2) continue;
      const double a = center - 0.5 * kDoorWidth, b = center + 0.5 * kDoorWidth;
      if (a < kEndMargin || b > f.length - kEndMargin || !plan.high.IsFree(a - 0.2, b + 0.5)) {
        continue;
      }
      plan.doors.push_back({a, b});
      plan.high.Reserve(a - 0.15, b + 0.45);
      plan.low.Reserve(a - 0.3, b + 0.3);
    }
    std::sort(plan.doors.begin(), plan.doors.end(),
              [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) { return p.x() < q.x(); });
    // Wall pieces between doors, and lintels above them.
    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
    double s = 0;
    for (const Eigen::Vector2d& door : plan.doors) {
      scene_.AddRectangle(object, material, f.At(s, 0), f.along, up, {door.x() - s, h});
      scene_.AddRectangle(object, material, f.At(door.x(), door_h), f.along, up,
                          {door.y() - door.x(), h - door_h});
      AddDoor(f, door, door_h);
      s = door.y();
    }
    scene_.AddRectangle(object, material, f.At(s, 0), f.along, up, {f.length - s, h});
    return plan;
  }

  void AddDoor(const WallFrame& f, const Eigen::Vector2d& door, double door_h) {
    const int id = door_count_++;
    const int object = scene_.AddObject(ObjectKind::kDoor, "door " + std::to_string(id), id);
    const double r = o_.door_recess_m, width = door.y() - door.x();
    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
    const int wood = scene_.AddMaterial({TextureKind::kSpeckle,
                                         JitterColor(rng_, {0.55f, 0.38f, 0.22f}, 0.08),
                                         {0.32f, 0.2f, 0.1f},
                                         0.09f,
                                         NextSeed(rng_)});
    const int frame = scene_.AddMaterial(
        {TextureKind::kSpeckle, {0.45f, 0.45f, 0.48f}, {0.3f, 0.3f, 0.32f}, 0.05f, NextSeed(rng_)});
    scene_.AddRectangle(object, wood, f.At(door.x(), 0, -r), f.along, up, {width, door_h});
    AddFacingRectangle(&scene_, object, frame, f.At(door.x(), 0, -r), r * f.normal, door_h * up,
                       f.along);
    AddFacingRectangle(&scene_, object, frame, f.At(door.y(), 0, -r), r * f.normal, door_h * up,
                       -f.along);
    AddFacingRectangle(&scene_, object, frame, f.At(door.x(), door_h, -r), width * f.along,
                       r * f.normal, -up);
    const double yaw = std::atan2(f.along.y(), f.along.x());
    scene_.AddBox(object, frame, f.At(door.y() - 0.15, 0.98, -r + 0.025), {0.15, 0.05, 0.035}, yaw);
    // A room sign beside the door.
    const std::string label = std::to_string(101 + id);
    const int image = scene_.AddImage(MakeButtonLabelImage(label, false, 96));
    Material sign{TextureKind::kImage};
    sign.image = image;
    sign.image_size_m = {0.16f, 0.16f};
    scene_.AddRectangle(object, scene_.AddMaterial(sign), f.At(door.y() + 0.2, 1.45, 0.004),
                        f.along, up, {0.16, 0.16});
  }

  // A random wall position with [s - half, s + half] free in `set`, or -1.
  int PickSpot(double half, bool high, double* s_out) {
    for (int attempt = 0; attempt < 60; ++attempt) {
      const int w = static_cast<int>(Uniform(rng_, 0, static_cast<double>(plans_.size())));
      WallPlan& plan = plans_[w];
      const double lo = kEndMargin + half, hi = plan.frame.length - kEndMargin - half;
      if (hi <= lo) continue;
      const double s = Uniform(rng_, lo, hi);
      IntervalSet& set = high ? plan.high : plan.low;
      if (!set.IsFree(s - half - 0.1, s + half + 0.1)) continue;
      set.Reserve(s - half, s + half);
      *s_out = s;
      return w;
    }
    return -1;
  }

  void AddPoster(int i) {
    const bool portrait = Uniform(rng_, 0, 1) < 0.6;
    const double w = portrait ? 0.6 : 0.84, h = portrait ? 0.84 : 0.6;
    double s = 0;
    const int wall = PickSpot(0.5 * w, true, &s);
    if (wall < 0) return;
    const WallFrame& f = plans_[wall].frame;
    const int object = scene_.AddObject(ObjectKind::kPoster, "poster " + std::to_string(i), i);
    Material m{TextureKind::kImage};
    m.image = scene_.AddImage(
        MakePosterImage(NextSeed(rng_), static_cast<int>(w / 0.002), static_cast<int>(h / 0.002)));
    m.image_size_m = {static_cast<float>(w), static_cast<float>(h)};
    // Seen from the corridor, +along points right: s along it and t up show it upright.
    scene_.AddRectangle(object, scene_.AddMaterial(m), f.At(s - 0.5 * w, 1.5 - 0.5 * h, 0.004),
                        f.along, Eigen::Vector3d::UnitZ(), {w, h});
  }

  void AddBoxAlongWall(int i) {
    const double length = Uniform(rng_, 0.35, 0.7), depth = Uniform(rng_, 0.3, 0.55);
    const double height = Uniform(rng_, 0.3, 0.7);
    double s = 0;
    const int wall = PickSpot(0.5 * length, false, &s);
    if (wall < 0) return;
    const WallFrame& f = plans_[wall].frame;
    const int object = scene_.AddObject(ObjectKind::kBox, "box " + std::to_string(i), i);
    const int cardboard = scene_.AddMaterial({TextureKind::kSpeckle,
                                              JitterColor(rng_, {0.66f, 0.5f, 0.32f}, 0.07),
                                              {0.35f, 0.26f, 0.16f},
                                              0.07f,
                                              NextSeed(rng_)});
    const double yaw = std::atan2(f.along.y(), f.along.x());
    scene_.AddBox(object, cardboard, f.At(s, 0, 0.5 * depth + 0.03), {length, depth, height}, yaw);
    if (Uniform(rng_, 0, 1) < 0.35) {  // A smaller box on top.
      scene_.AddBox(object, cardboard, f.At(s, height, 0.5 * depth + 0.03),
                    {0.7 * length, 0.7 * depth, 0.6 * height}, yaw + Uniform(rng_, -0.3, 0.3));
    }
  }

  void AddBin(int i) {
    double s = 0;
    const int wall = PickSpot(0.22, false, &s);
    if (wall < 0) return;
    const WallFrame& f = plans_[wall].frame;
    const int object = scene_.AddObject(ObjectKind::kBin, "bin " + std::to_string(i), i);
    const int plastic = scene_.AddMaterial({TextureKind::kSpeckle,
                                            JitterColor(rng_, {0.2f, 0.35f, 0.6f}, 0.1),
                                            {0.1f, 0.15f, 0.3f},
                                            0.06f,
                                            NextSeed(rng_)});
    scene_.AddUprightCylinder(object, plastic, f.At(s, 0, 0.22), 0.18, 0.55);
  }

  void AddPeople() {
    const int count = std::clamp(o_.people, 0, 2);
    const double lx = o_.loop_length_m;
    for (int i = 0; i < count; ++i) {
      WalkingPerson p;
      p.id = i;
      p.object = scene_.AddObject(ObjectKind::kPerson, "person " + std::to_string(i), i);
      p.clothes_material =
          scene_.AddMaterial({TextureKind::kSpeckle, JitterColor(rng_, {0.5f, 0.3f, 0.3f}, 0.3),
                              JitterColor(rng_, {0.2f, 0.2f, 0.3f}, 0.15), 0.05f, NextSeed(rng_)});
      p.trousers_material = scene_.AddMaterial({TextureKind::kSpeckle,
                                                JitterColor(rng_, {0.2f, 0.22f, 0.3f}, 0.1),
                                                {0.1f, 0.1f, 0.12f},
                                                0.04f,
                                                NextSeed(rng_)});
      p.skin_material = scene_.AddMaterial({TextureKind::kSpeckle,
                                            JitterColor(rng_, {0.8f, 0.62f, 0.5f}, 0.1),
                                            {0.3f, 0.2f, 0.15f},
                                            0.03f,
                                            NextSeed(rng_)});
      p.height_m = Uniform(rng_, 1.62, 1.86);
      if (i == 0) {  // The leader walks the robot's route ahead of it.
        const double ly = o_.loop_width_m;
        auto path = PlanarPath::Through({{1, 0}, {lx, 0}, {lx, ly}, {0, ly}, {0, 0}}, 0.9,
                                        PlanarPath::End::kLoop);
        if (!path.ok()) continue;
        p.path = std::move(*path);
        p.start_m = 4.0;
        p.speed_mps = o_.people_speed_mps;
        p.lateral_m = 0.35;
      } else {  // A passer-by walking the first corridor to and fro, on the robot's right.
        auto path = PlanarPath::Through({{lx - 1.5, 0}, {2.5, 0}}, 0, PlanarPath::End::kPingPong);
        if (!path.ok()) continue;
        p.path = std::move(*path);
        p.speed_mps = 1.1;
        p.lateral_m = 0.6;
      }
      scene_.people.push_back(p);
    }
  }

  const CorridorOptions& o_;
  std::mt19937 rng_;
  Scene scene_;
  std::vector<WallPlan> plans_;
  int door_count_ = 0;
};

}  // namespace

bool CorridorOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& message) {
    if (error) *error = "sim.corridor." + message;
    return false;
  };
  if (!(corridor_width_m >= 1.0 && corridor_width_m <= 5.0)) {
    return fail("corridor_width_m must lie in [1, 5] m");
  }
  if (!(loop_length_m >= 2 * corridor_width_m + 2 && loop_length_m <= 500)) {
    return fail("loop_length_m must lie in [2 * corridor_width_m + 2, 500] m");
  }
  if (!(loop_width_m >= 2 * corridor_width_m + 2 && loop_width_m <= 500)) {
    return fail("loop_width_m must lie in [2 * corridor_width_m + 2, 500] m");
  }
  if (!(height_m >= 2.0 && height_m <= 10)) return fail("height_m must lie in [2, 10] m");
  if (!(branch_length_m >= 0 && branch_length_m <= 100)) {
    return fail("branch_length_m must lie in [0, 100] m");
  }
  if (!(door_spacing_m >= 1.5 && door_spacing_m <= 100)) {
    return fail("door_spacing_m must lie in [1.5, 100] m");
  }
  if (!(door_recess_m >= 0.01 && door_recess_m <= 0.5)) {
    return fail("door_recess_m must lie in [0.01, 0.5] m");
  }
  if (boxes < 0 || boxes > 100) return fail("boxes must lie in [0, 100]");
  if (bins < 0 || bins > 100) return fail("bins must lie in [0, 100]");
  if (posters < 0 || posters > 100) return fail("posters must lie in [0, 100]");
  if (people < 0 || people > 2) return fail("people must be 0, 1 or 2");
  if (!(people_speed_mps >= 0 && people_speed_mps <= 3)) {
    return fail("people_speed_mps must lie in [0, 3] m/s");
  }
  return true;
}

OptionTable<CorridorOptions> CorridorOptions::Describe() {
  using O = CorridorOptions;
  return OptionTable<O>("corridor")
      .Double("loop_length_m", &O::loop_length_m, "m", 6, 500, 0.5,
              "Centreline length of the loop's first corridor (map x).")
      .Double("loop_width_m", &O::loop_width_m, "m", 6, 500, 0.5,
              "Centreline length of the loop's second corridor (map y).")
      .Double("corridor_width_m", &O::corridor_width_m, "m", 1, 5, 0.1, "Wall to wall.")
      .Double("height_m", &O::height_m, "m", 2, 10, 0.1, "Floor to ceiling.")
      .Double("branch_length_m", &O::branch_length_m, "m", 0, 100, 0.5,
              "Length of the two dead-end side corridors (T junctions); 0 = none.")
      .Double("door_spacing_m", &O::door_spacing_m, "m", 1.5, 100, 0.5,
              "Mean distance between doors along a wall.")
      .Double("door_recess_m", &O::door_recess_m, "m", 0.01, 0.5, 0.01,
              "Depth of the doors behind the wall face (lintels and jambs show in depth).")
      .Int("boxes", &O::boxes, "", 0, 100, 1, "Cardboard boxes along the walls.")
      .Int("bins", &O::bins, "", 0, 100, 1, "Waste bins along the walls.")
      .Int("posters", &O::posters, "", 0, 100, 1, "Posters on the walls.")
      .Int("people", &O::people, "", 0, 2, 1,
           "Walking people: 1 = a leader walking the route ahead of the robot, 2 = also a "
           "passer-by in the first corridor.")
      .Double("people_speed_mps", &O::people_speed_mps, "m/s", 0, 3, 0.1,
              "Walking speed of the leader.");
}

StatusOr<Scene> BuildCorridor(const CorridorOptions& options, uint64_t seed) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  return CorridorBuilder(options, seed).Build();
}

}  // namespace sightline::sim
