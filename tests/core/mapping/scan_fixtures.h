// Synthetic 2D scans for the line extractor tests: rays from the origin over a field of view,
// hitting infinite wall lines, with Gaussian noise, cell quantisation and outliers.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/mapping/pose2d.h"

namespace sightline::testing {

// A wall line through `point` with direction angle `angle_rad` (base frame).
struct ScanWall {
  Eigen::Vector2d point;
  double angle_rad = 0;
};

struct ScanFixtureOptions {
  double fov_deg = 60;
  double resolution_deg = 0.2;
  double noise_m = 0.01;       // Gaussian, perpendicular to the wall.
  double cell_m = 0.02;        // Points snap to cell centres (0 = no snapping).
  double outlier_ratio = 0.0;  // Rays replaced by a random range.
  double max_range_m = 8.0;
  unsigned seed = 3;
};

// Points ordered by bearing (right to left).
inline std::vector<Eigen::Vector2d> ScanOfWalls(const std::vector<ScanWall>& walls,
                                                const ScanFixtureOptions& o) {
  std::mt19937 rng(o.seed);
  std::normal_distribution<double> noise(0.0, o.noise_m);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector2d> points;
  const int rays = static_cast<int>(std::lround(o.fov_deg / o.resolution_deg));
  for (int k = 0; k <= rays; ++k) {
    const double bearing = DegToRad(-0.5 * o.fov_deg + k * o.resolution_deg);
    const Eigen::Vector2d ray(std::cos(bearing), std::sin(bearing));
    double best = std::numeric_limits<double>::infinity();
    const ScanWall* hit = nullptr;
    for (const ScanWall& wall : walls) {
      const Eigen::Vector2d n(-std::sin(wall.angle_rad), std::cos(wall.angle_rad));
      const double denom = n.dot(ray);
      if (std::abs(denom) < 1e-9) continue;
      const double t = n.dot(wall.point) / denom;
      if (t > 0.05 && t < best) {
        best = t;
        hit = &wall;
      }
    }
    if (hit == nullptr || best > o.max_range_m) continue;
    Eigen::Vector2d p = best * ray;
    const Eigen::Vector2d n(-std::sin(hit->angle_rad), std::cos(hit->angle_rad));
    p += noise(rng) * n;
    if (unit(rng) < o.outlier_ratio) p = (0.5 + unit(rng) * (best - 0.5)) * ray;
    if (o.cell_m > 0) {
      p = ((p / o.cell_m).array().floor() + 0.5).matrix() * o.cell_m;
    }
    points.push_back(p);
  }
  return points;
}

}  // namespace sightline::testing
