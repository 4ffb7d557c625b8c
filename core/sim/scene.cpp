#include "core/sim/scene.h"

#include <cmath>

namespace sightline::sim {

const char* ObjectKindName(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::kFloor:
      return "floor";
    case ObjectKind::kCeiling:
      return "ceiling";
    case ObjectKind::kWall:
      return "wall";
    case ObjectKind::kDoor:
      return "door";
    case ObjectKind::kBox:
      return "box";
    case ObjectKind::kBin:
      return "bin";
    case ObjectKind::kPoster:
      return "poster";
    case ObjectKind::kPerson:
      return "person";
    case ObjectKind::kRamp:
      return "ramp";
    case ObjectKind::kStep:
      return "step";
    case ObjectKind::kRough:
      return "rough";
    case ObjectKind::kPlate:
      return "plate";
    case ObjectKind::kButton:
      return "button";
    case ObjectKind::kOther:
      return "other";
  }
  return "other";
}

Eigen::Vector3d WallLine::Line() const {
  const Eigen::Vector2d d = (end - start).normalized();
  // The wall faces left of its direction (start -> end), see the builders.
  const Eigen::Vector2d n(-d.y(), d.x());
  return {n.x(), n.y(), -n.dot(start)};
}

int Scene::AddMaterial(const Material& material) {
  materials_.push_back(material);
  return static_cast<int>(materials_.size()) - 1;
}

int Scene::AddImage(TextureImage image) {
  images_.push_back(std::move(image));
  return static_cast<int>(images_.size()) - 1;
}

int Scene::AddObject(ObjectKind kind, std::string name, int label) {
  objects_.push_back({kind, label, std::move(name)});
  return static_cast<int>(objects_.size()) - 1;
}

int Scene::Add(Primitive primitive) {
  primitives_.push_back(std::move(primitive));
  return static_cast<int>(primitives_.size()) - 1;
}

int Scene::AddRectangle(int object, int material, const Eigen::Vector3d& corner,
                        const Eigen::Vector3d& axis_s, const Eigen::Vector3d& axis_t,
                        const Eigen::Vector2d& size, bool two_sided) {
  PlanarPatch patch;
  patch.origin = corner;
  patch.axis_s = axis_s.normalized();
  patch.axis_t = axis_t.normalized();
  patch.shape = PatchShape::kRectangle;
  patch.size = size;
  patch.two_sided = two_sided;
  return Add({patch, material, object});
}

int Scene::AddPolygon(int object, int material, const std::vector<Eigen::Vector3d>& corners,
                      bool two_sided) {
  PlanarPatch patch;
  patch.origin = corners.at(0);
  patch.axis_s = (corners.at(1) - corners[0]).normalized();
  const Eigen::Vector3d normal = (corners[1] - corners[0]).cross(corners.at(2) - corners[0]);
  patch.axis_t = normal.normalized().cross(patch.axis_s);
  patch.shape = PatchShape::kPolygon;
  for (const Eigen::Vector3d& c : corners) {
    patch.polygon.emplace_back((c - patch.origin).dot(patch.axis_s),
                               (c - patch.origin).dot(patch.axis_t));
  }
  patch.two_sided = two_sided;
  return Add({patch, material, object});
}

int Scene::AddDisc(int object, int material, const Eigen::Vector3d& center,
                   const Eigen::Vector3d& normal, const Eigen::Vector3d& axis_s, double radius) {
  PlanarPatch patch;
  const Eigen::Vector3d n = normal.normalized();
  patch.origin = center;
  patch.axis_s = (axis_s - axis_s.dot(n) * n).normalized();
  patch.axis_t = n.cross(patch.axis_s);
  patch.shape = PatchShape::kDisc;
  patch.size = {radius, radius};
  return Add({patch, material, object});
}

void Scene::AddBox(int object, int material, const Eigen::Vector3d& c, const Eigen::Vector3d& size,
                   double yaw) {
  const Eigen::Vector3d ex(std::cos(yaw), std::sin(yaw), 0), ey(-std::sin(yaw), std::cos(yaw), 0);
  const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();
  const double l = size.x(), w = size.y(), h = size.z();
  const Eigen::Vector3d lo = c - 0.5 * l * ex - 0.5 * w * ey;             // Bottom corner (-x, -y).
  AddRectangle(object, material, lo + h * ez, ex, ey, {l, w});            // Top, +z.
  AddRectangle(object, material, lo, ey, ex, {w, l});                     // Bottom, -z.
  AddRectangle(object, material, lo + l * ex, ey, ez, {w, h});            // +x.
  AddRectangle(object, material, lo + w * ey, -ey, ez, {w, h});           // -x.
  AddRectangle(object, material, lo + l * ex + w * ey, -ex, ez, {l, h});  // +y.
  AddRectangle(object, material, lo, ex, ez, {l, h});                     // -y.
}

void Scene::AddUprightCylinder(int object, int material, const Eigen::Vector3d& bottom_center,
                               double radius, double height) {
  Add({Cylinder{bottom_center, Eigen::Vector3d::UnitZ(), radius, height}, material, object});
  AddDisc(object, material, bottom_center + height * Eigen::Vector3d::UnitZ(),
          Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), radius);
}

std::vector<Primitive> Scene::DynamicPrimitives(double t_s) const {
  std::vector<Primitive> dynamic;
  for (const WalkingPerson& person : people) {
    std::vector<Primitive> body = PersonPrimitives(person, t_s);
    dynamic.insert(dynamic.end(), body.begin(), body.end());
  }
  return dynamic;
}

PathPose PersonPose(const WalkingPerson& person, double t_s) {
  PathPose pose = person.path.At(person.start_m + person.speed_mps * t_s);
  const Eigen::Vector2d left(-std::sin(pose.heading_rad), std::cos(pose.heading_rad));
  pose.position += person.lateral_m * left;
  return pose;
}

std::vector<Primitive> PersonPrimitives(const WalkingPerson& person, double t_s) {
  const PathPose pose = PersonPose(person, t_s);
  const double k = person.height_m / 1.7;  // Proportions of a 1.7 m person.
  const Eigen::Vector3d f(std::cos(pose.heading_rad), std::sin(pose.heading_rad), 0);
  const Eigen::Vector3d l(-f.y(), f.x(), 0), up = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d p(pose.position.x(), pose.position.y(), 0);
  const double phase = 2 * M_PI * (person.speed_mps * t_s) / (1.3 * k);
  const double swing = 0.22 * k * std::sin(phase);
  std::vector<Primitive> out;
  auto limb = [&](const Eigen::Vector3d& from, const Eigen::Vector3d& to, double radius,
                  int material) {
    const Eigen::Vector3d axis = to - from;
    out.push_back(
        {Cylinder{from, axis.normalized(), radius, axis.norm()}, material, person.object});
  };
  auto disc = [&](const Eigen::Vector3d& center, const Eigen::Vector3d& normal, double radius,
                  int material) {
    PlanarPatch patch;
    patch.origin = center;
    patch.axis_s = f;
    patch.axis_t = normal.cross(f);
    patch.shape = PatchShape::kDisc;
    patch.size = {radius, radius};
    out.push_back({patch, material, person.object});
  };
  const double hip = 0.82 * k, shoulder = 1.40 * k, torso_top = 1.44 * k;
  for (int side : {-1, 1}) {
    const Eigen::Vector3d hip_point = p + side * 0.09 * k * l + hip * up;
    const Eigen::Vector3d foot = p + side * 0.09 * k * l + side * swing * f;
    limb(foot, hip_point, 0.07 * k, person.trousers_material);
    const Eigen::Vector3d shoulder_point = p + side * 0.23 * k * l + shoulder * up;
    const Eigen::Vector3d hand =
        shoulder_point - 0.62 * k * up - side * 0.8 * swing * f + side * 0.03 * k * l;
    limb(hand, shoulder_point, 0.045 * k, person.clothes_material);
  }
  const double torso_radius = 0.17 * k;
  out.push_back({Cylinder{p + hip * up, up, torso_radius, torso_top - hip}, person.clothes_material,
                 person.object});
  disc(p + torso_top * up, up, torso_radius, person.clothes_material);
  disc(p + hip * up, -up, torso_radius, person.trousers_material);
  out.push_back({Sphere{p + (torso_top + 0.035 * k + 0.1 * k) * up, 0.1 * k}, person.skin_material,
                 person.object});
  return out;
}

}  // namespace sightline::sim
