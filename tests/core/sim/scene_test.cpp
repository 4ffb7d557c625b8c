#include "core/sim/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/sim/corridor_scene.h"
#include "core/sim/floor_plan.h"
#include "core/sim/panel_scene.h"
#include "core/sim/terrain_scene.h"

namespace sightline::sim {
namespace {

// Every wall's line is normalised, passes through its end points and faces free space.
void ExpectWallsFaceFreeSpace(const std::vector<WallLine>& walls,
                              const std::vector<FreeRect>& rects) {
  for (const WallLine& w : walls) {
    const Eigen::Vector3d l = w.Line();
    EXPECT_NEAR(l.x() * l.x() + l.y() * l.y(), 1.0, 1e-12);
    EXPECT_NEAR(l.x() * w.start.x() + l.y() * w.start.y() + l.z(), 0, 1e-12);
    EXPECT_NEAR(l.x() * w.end.x() + l.y() * w.end.y() + l.z(), 0, 1e-12);
    const Eigen::Vector2d mid = 0.5 * (w.start + w.end);
    const Eigen::Vector2d inside = mid + 0.05 * Eigen::Vector2d(l.x(), l.y());
    const Eigen::Vector2d outside = mid - 0.05 * Eigen::Vector2d(l.x(), l.y());
    EXPECT_TRUE(InsideFreeSpace(rects, inside.x(), inside.y())) << "wall " << w.id;
    EXPECT_FALSE(InsideFreeSpace(rects, outside.x(), outside.y())) << "wall " << w.id;
  }
}

TEST(FloorPlan, LShapedUnionHasSixMaximalWalls) {
  const std::vector<FreeRect> rects = {{0, 0, 6, 2}, {4, 0, 6, 5}};
  const std::vector<WallLine> walls = BoundaryWalls(rects);
  EXPECT_EQ(walls.size(), 6u);
  ExpectWallsFaceFreeSpace(walls, rects);
  double perimeter = 0;
  for (const WallLine& w : walls) perimeter += (w.end - w.start).norm();
  EXPECT_NEAR(perimeter, 2 * (6 + 5), 1e-12);
}

TEST(Scene, TestsCanBuildTheirOwnScene) {
  Scene scene("room");
  const int grey = scene.AddMaterial({TextureKind::kPlain});
  const int wall = scene.AddObject(ObjectKind::kWall, "wall 0", 0);
  scene.AddRectangle(wall, grey, {3, 2, 0}, {0, -1, 0}, {0, 0, 1}, {4, 2.5});
  const int box = scene.AddObject(ObjectKind::kBox, "box 0", 0);
  scene.AddBox(box, grey, {1, 0, 0}, {0.5, 0.5, 0.5});
  ASSERT_EQ(scene.primitives().size(), 7u);
  const auto& patch = std::get<PlanarPatch>(scene.primitives()[0].shape);
  EXPECT_NEAR((patch.normal() - Eigen::Vector3d(-1, 0, 0)).norm(), 0, 1e-12);
  // Box faces point outwards.
  for (size_t i = 1; i < 7; ++i) {
    const auto& face = std::get<PlanarPatch>(scene.primitives()[i].shape);
    const Eigen::Vector3d center = face.At(0.5 * face.size.x(), 0.5 * face.size.y());
    EXPECT_GT((center - Eigen::Vector3d(1, 0, 0.25)).dot(face.normal()), 0.2) << "face " << i;
  }
}

TEST(CorridorScene, HasJunctionsDoorsPeopleAndNormalisedWalls) {
  auto scene = BuildCorridor(CorridorOptions(), 7);
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  // A loop with two dead-end branches: 4 outer + 4 inner walls, plus 3 per branch, minus the
  // outer walls the branches split (each split adds one).
  EXPECT_GE(scene->walls.size(), 14u);
  std::set<ObjectKind> kinds;
  for (const SceneObject& o : scene->objects()) kinds.insert(o.kind);
  for (ObjectKind k :
       {ObjectKind::kFloor, ObjectKind::kCeiling, ObjectKind::kWall, ObjectKind::kDoor,
        ObjectKind::kBox, ObjectKind::kBin, ObjectKind::kPoster, ObjectKind::kPerson}) {
    EXPECT_TRUE(kinds.count(k)) << ObjectKindName(k);
  }
  EXPECT_EQ(scene->people.size(), 2u);
  EXPECT_TRUE(scene->hints.route_loops);
  for (const WallLine& w : scene->walls) {
    // Manhattan: every wall runs along x or y.
    const Eigen::Vector2d d = (w.end - w.start).normalized();
    EXPECT_NEAR(std::abs(d.x() * d.y()), 0, 1e-12);
  }
}

TEST(CorridorScene, PeopleWalk) {
  auto scene = BuildCorridor(CorridorOptions(), 7);
  ASSERT_TRUE(scene.ok());
  ASSERT_FALSE(scene->people.empty());
  const WalkingPerson& leader = scene->people[0];
  const PathPose start = PersonPose(leader, 0), later = PersonPose(leader, 2.0);
  EXPECT_NEAR((later.position - start.position).norm(), 2.0 * leader.speed_mps, 1e-9);
  const auto body = scene->DynamicPrimitives(1.0);
  EXPECT_FALSE(body.empty());
  for (const Primitive& p : body) EXPECT_EQ(scene->objects()[p.object].kind, ObjectKind::kPerson);
}

TEST(CorridorScene, SameSeedSameSceneOtherSeedOtherScene) {
  auto a = BuildCorridor(CorridorOptions(), 3), b = BuildCorridor(CorridorOptions(), 3);
  auto c = BuildCorridor(CorridorOptions(), 4);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  ASSERT_EQ(a->primitives().size(), b->primitives().size());
  for (size_t i = 0; i < a->materials().size(); ++i) {
    EXPECT_EQ(a->materials()[i].seed, b->materials()[i].seed);
  }
  EXPECT_NE(a->materials()[0].seed, c->materials()[0].seed);
}

TEST(TerrainScene, RegionsCarryTheConfiguredSlopeHeightAndRoughness) {
  TerrainOptions options;
  options.ramp_slope_deg = 30;
  options.step_height_m = 0.15;
  options.roughness = 1.2;
  auto scene = BuildTerrain(options, 1);
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  auto find = [&](const std::string& kind) {
    return *std::find_if(scene->regions.begin(), scene->regions.end(),
                         [&](const TerrainRegion& r) { return r.kind == kind; });
  };
  EXPECT_DOUBLE_EQ(find("ramp").slope_deg, 30);
  EXPECT_DOUBLE_EQ(find("ramp").height_m, options.ramp_rise_m);
  EXPECT_DOUBLE_EQ(find("step").height_m, 0.15);
  EXPECT_NEAR(find("rough").roughness, 1.2, 1e-6);
  EXPECT_DOUBLE_EQ(find("wall").slope_deg, 90);
  // The ramp's top really is inclined by the slope.
  for (const Primitive& p : scene->primitives()) {
    if (scene->objects()[p.object].kind != ObjectKind::kRamp) continue;
    const auto& patch = std::get<PlanarPatch>(p.shape);
    const double tilt = std::acos(patch.normal().z()) * 180 / M_PI;
    if (tilt > 1 && tilt < 89) EXPECT_NEAR(tilt, 30, 1e-9);
  }
}

TEST(PanelScene, TwelveNumberedButtonsOnOnePlane) {
  auto scene = BuildPanel(PanelOptions(), 1);
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  ASSERT_EQ(scene->buttons.size(), 12u);
  EXPECT_EQ(scene->buttons.front().label, "-1");
  EXPECT_EQ(scene->buttons.back().label, "10");
  for (const ButtonSpec& b : scene->buttons) {
    EXPECT_NEAR(b.center.x(), scene->buttons[0].center.x(), 1e-12);
    EXPECT_NEAR((b.normal - Eigen::Vector3d(-1, 0, 0)).norm(), 0, 1e-12);
    EXPECT_EQ(scene->objects()[b.object].kind, ObjectKind::kButton);
  }
  // Bottom left first, as seen from the front (left = map +y).
  EXPECT_GT(scene->buttons[0].center.y(), scene->buttons[1].center.y());
  EXPECT_LT(scene->buttons[0].center.z(), scene->buttons[2].center.z());
}

TEST(SceneBuilders, InvalidOptionsNameTheKey) {
  CorridorOptions corridor;
  corridor.corridor_width_m = 0.2;
  auto c = BuildCorridor(corridor, 1);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.status().message().find("sim.corridor.corridor_width_m"), std::string::npos);
  TerrainOptions terrain;
  terrain.ramp_slope_deg = 5;
  terrain.ramp_rise_m = 1.0;  // 11 m long: does not fit before the wall.
  auto t = BuildTerrain(terrain, 1);
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.status().message().find("sim.terrain.wall_distance_m"), std::string::npos);
  PanelOptions panel;
  panel.target_button = 12;
  auto p = BuildPanel(panel, 1);
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.status().message().find("sim.panel.target_button"), std::string::npos);
}

}  // namespace
}  // namespace sightline::sim
