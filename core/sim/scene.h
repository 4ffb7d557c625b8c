// A simulated world: primitives with materials, the objects they belong to, and the ground truth
// a pipeline is scored against (wall lines, terrain regions, buttons, walking people).
//
// Frames and units (see core/sim/README.md): the map frame has z up, the floor at z = 0 and
// x along the first corridor (or towards the terrain / the panel); metres and radians.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/sim/material.h"
#include "core/sim/planar_path.h"
#include "core/sim/primitive.h"

namespace sightline::sim {

// What a group of primitives is.
enum class ObjectKind {
  kFloor,
  kCeiling,
  kWall,
  kDoor,
  kBox,
  kBin,
  kPoster,
  kPerson,
  kRamp,
  kStep,
  kRough,
  kPlate,
  kButton,
  kOther,
};

// "floor", "ceiling", "wall", "door", ...
const char* ObjectKindName(ObjectKind kind);

// One object of the scene; its primitives name it by index.
struct SceneObject {
  ObjectKind kind = ObjectKind::kOther;
  int label = -1;    // Id in its annotation list (wall, region, button or person id), or -1.
  std::string name;  // For scene.yaml and messages, e.g. "door 3".
};

// A wall face as a line segment on the floor plan (map frame x, y).
struct WallLine {
  int id = 0;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d end = Eigen::Vector2d::Zero();

  // (a, b, c) with a x + b y + c = 0 on the wall, a^2 + b^2 = 1 and (a, b) pointing into the
  // free side (the side the wall faces).
  Eigen::Vector3d Line() const;
};

// A terrain region with the properties the mobility map estimates.
struct TerrainRegion {
  int id = 0;
  std::string kind;      // "floor", "ramp", "platform", "step", "rough", "box", "wall".
  double slope_deg = 0;  // Angle between the surface normal and the map's z axis.
  double roughness = 1;  // Sum of 3D triangle areas / sum of their projected areas (>= 1).
  double height_m = 0;   // Highest point above the floor.
  std::vector<Eigen::Vector2d> polygon;  // Footprint on the floor plan (map x, y), CCW.
};

// A push button: the centre of its front face.
struct ButtonSpec {
  int id = 0;
  std::string label;                                  // The printed text, e.g. "3".
  Eigen::Vector3d center = Eigen::Vector3d::Zero();   // Map frame.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // Unit, out of the panel.
  double radius_m = 0.02;  // Round buttons: radius; square ones: half the side.
  int object = -1;         // Scene object index of the button.
};

// A person walking along a path; rendered as legs, torso, arms and head.
struct WalkingPerson {
  int id = 0;
  int object = -1;  // Scene object index.
  PlanarPath path;
  double speed_mps = 1.0;
  double start_m = 0;    // Arc length at time 0.
  double lateral_m = 0;  // Offset to the left of the path.
  double height_m = 1.7;
  int clothes_material = 0;
  int trousers_material = 0;
  int skin_material = 0;
};

// How the builder suggests moving through the scene (used by the default trajectories).
struct MotionHints {
  std::vector<Eigen::Vector2d> route;  // Floor-plan route for robots and handheld cameras.
  bool route_loops = false;            // The route closes back to its first point.
  // Arm scenes: the arm's base in the map frame and the button the camera approaches.
  Eigen::Isometry3d world_from_arm_base = Eigen::Isometry3d::Identity();
  int target_button = -1;
};

// The simulated world. Build it declaratively with the Add* helpers, e.g. a test's own room:
//
//   Scene scene("room");
//   int grey = scene.AddMaterial({TextureKind::kPlain});
//   int wall = scene.AddObject(ObjectKind::kWall, "wall 0");
//   scene.AddRectangle(wall, grey, {3, -2, 0}, {0, 1, 0}, {0, 0, 1}, {4, 2.5});  // x = 3
class Scene {
 public:
  explicit Scene(std::string name = "custom") : name_(std::move(name)) {}

  const std::string& name() const { return name_; }

  // --- Building ---
  int AddMaterial(const Material& material);
  int AddImage(TextureImage image);
  int AddObject(ObjectKind kind, std::string name, int label = -1);
  // Adds a primitive; returns its index.
  int Add(Primitive primitive);

  // A rectangle from `corner` spanning `size` along the unit axes; it faces axis_s x axis_t.
  int AddRectangle(int object, int material, const Eigen::Vector3d& corner,
                   const Eigen::Vector3d& axis_s, const Eigen::Vector3d& axis_t,
                   const Eigen::Vector2d& size, bool two_sided = false);
  // A convex polygon given by its corners in 3D (coplanar, counter-clockwise seen from the
  // front); texture coordinates start at the first corner with s along the first edge.
  int AddPolygon(int object, int material, const std::vector<Eigen::Vector3d>& corners,
                 bool two_sided = false);
  // A disc of `radius` at `center` facing `normal`; texture s runs along `axis_s` (projected
  // onto the disc), with (0, 0) at the centre.
  int AddDisc(int object, int material, const Eigen::Vector3d& center,
              const Eigen::Vector3d& normal, const Eigen::Vector3d& axis_s, double radius);
  // A closed box: centre of its bottom face, size (length along the yawed x, width, height) and
  // yaw about z. Six outward-facing rectangles.
  void AddBox(int object, int material, const Eigen::Vector3d& bottom_center,
              const Eigen::Vector3d& size, double yaw_rad = 0);
  // A closed vertical cylinder standing on `bottom_center` (side and top cap).
  void AddUprightCylinder(int object, int material, const Eigen::Vector3d& bottom_center,
                          double radius, double height);

  // --- Contents ---
  const std::vector<Material>& materials() const { return materials_; }
  const std::vector<TextureImage>& images() const { return images_; }
  const std::vector<SceneObject>& objects() const { return objects_; }
  // The static primitives.
  const std::vector<Primitive>& primitives() const { return primitives_; }
  // Primitives that move, at time t (the walking people), appended after the static ones.
  std::vector<Primitive> DynamicPrimitives(double t_s) const;

  // Sky / void colour where no surface is hit (linear RGB).
  Eigen::Vector3f background = {0.55f, 0.62f, 0.70f};
  // Direction towards the main light in the map frame (unit); plus ambient light.
  Eigen::Vector3d light_direction = Eigen::Vector3d(0.35, 0.25, 0.9).normalized();
  float ambient = 0.55f;  // Fraction of light that does not depend on orientation.

  // Suggested motion through the scene.
  MotionHints hints;

  // --- Ground truth ---
  std::vector<WallLine> walls;
  std::vector<TerrainRegion> regions;
  std::vector<ButtonSpec> buttons;
  std::vector<WalkingPerson> people;

 private:
  std::string name_;
  std::vector<Material> materials_;
  std::vector<TextureImage> images_;
  std::vector<SceneObject> objects_;
  std::vector<Primitive> primitives_;
};

// The primitives of a walking person at time t (legs swing with the stride).
std::vector<Primitive> PersonPrimitives(const WalkingPerson& person, double t_s);

// The pose of a walking person's body at time t: position on the floor and heading.
PathPose PersonPose(const WalkingPerson& person, double t_s);

}  // namespace sightline::sim
