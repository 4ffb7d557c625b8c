#include "core/sim/builder_util.h"

#include <algorithm>

#include "core/sim/random.h"

namespace sightline::sim {

int AddFacingRectangle(Scene* scene, int object, int material, const Eigen::Vector3d& corner,
                       const Eigen::Vector3d& edge_a, const Eigen::Vector3d& edge_b,
                       const Eigen::Vector3d& facing) {
  if (edge_a.cross(edge_b).dot(facing) >= 0) {
    return scene->AddRectangle(object, material, corner, edge_a, edge_b,
                               {edge_a.norm(), edge_b.norm()});
  }
  return scene->AddRectangle(object, material, corner, edge_b, edge_a,
                             {edge_b.norm(), edge_a.norm()});
}

Eigen::Vector3f JitterColor(std::mt19937& engine, const Eigen::Vector3f& base, double spread) {
  Eigen::Vector3f c;
  for (int k = 0; k < 3; ++k) {
    c[k] = static_cast<float>(std::clamp(base[k] + Uniform(engine, -spread, spread), 0.0, 1.0));
  }
  return c;
}

uint32_t NextSeed(std::mt19937& engine) { return static_cast<uint32_t>(engine()); }

bool IntervalSet::IsFree(double a, double b) const {
  for (const Eigen::Vector2d& t : taken_) {
    if (a < t.y() && b > t.x()) return false;
  }
  return true;
}

}  // namespace sightline::sim
