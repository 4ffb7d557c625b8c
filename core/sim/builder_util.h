// Small helpers shared by the scene builders (internal to core/sim).
#pragma once

#include <Eigen/Core>
#include <random>
#include <vector>

#include "core/sim/scene.h"

namespace sightline::sim {

// Adds the rectangle corner + a * edge_a + b * edge_b (a, b in [0, 1]) facing `facing` (the
// edges are swapped when needed). Returns the primitive index.
int AddFacingRectangle(Scene* scene, int object, int material, const Eigen::Vector3d& corner,
                       const Eigen::Vector3d& edge_a, const Eigen::Vector3d& edge_b,
                       const Eigen::Vector3d& facing);

// A random colour near `base` (each channel +- spread), clamped to [0, 1].
Eigen::Vector3f JitterColor(std::mt19937& engine, const Eigen::Vector3f& base, double spread);

// A per-surface texture seed.
uint32_t NextSeed(std::mt19937& engine);

// Free intervals along a line (a wall): reserve [a, b] and ask whether an interval is free.
class IntervalSet {
 public:
  bool IsFree(double a, double b) const;
  void Reserve(double a, double b) { taken_.push_back({a, b}); }

 private:
  std::vector<Eigen::Vector2d> taken_;
};

}  // namespace sightline::sim
