#include "core/sim/floor_plan.h"

#include <algorithm>

namespace sightline::sim {

bool InsideFreeSpace(const std::vector<FreeRect>& rects, double x, double y) {
  for (const FreeRect& r : rects) {
    if (x > r.x0 && x < r.x1 && y > r.y0 && y < r.y1) return true;
  }
  return false;
}

std::vector<WallLine> BoundaryWalls(const std::vector<FreeRect>& rects) {
  // A compressed grid on the rectangles' coordinates: every cell is wholly free or wholly not.
  std::vector<double> xs, ys;
  for (const FreeRect& r : rects) {
    xs.insert(xs.end(), {r.x0, r.x1});
    ys.insert(ys.end(), {r.y0, r.y1});
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  const int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1;
  auto free = [&](int i, int j) {
    if (i < 0 || j < 0 || i >= nx || j >= ny) return false;
    return InsideFreeSpace(rects, 0.5 * (xs[i] + xs[i + 1]), 0.5 * (ys[j] + ys[j + 1]));
  };
  std::vector<WallLine> walls;
  // Appends the edge, merging it with the previous one when it continues it.
  auto add = [&](const Eigen::Vector2d& start, const Eigen::Vector2d& end) {
    if (!walls.empty()) {
      WallLine& last = walls.back();
      const Eigen::Vector2d d0 = (last.end - last.start).normalized();
      const Eigen::Vector2d d1 = (end - start).normalized();
      if ((last.end - start).norm() < 1e-12 && d0.dot(d1) > 0.999999) {
        last.end = end;
        return;
      }
      if ((last.start - end).norm() < 1e-12 && d0.dot(d1) > 0.999999) {
        last.start = start;
        return;
      }
    }
    walls.push_back({static_cast<int>(walls.size()), start, end});
  };
  // Vertical grid lines x = xs[i]: cells (i-1, j) and (i, j) on either side.
  for (int i = 0; i <= nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      const bool left = free(i - 1, j), right = free(i, j);
      if (left == right) continue;
      const Eigen::Vector2d a(xs[i], ys[j]), b(xs[i], ys[j + 1]);
      // The free side must be left of start -> end.
      if (right)
        add(b, a);
      else
        add(a, b);
    }
  }
  // Horizontal grid lines y = ys[j]: cells (i, j-1) below and (i, j) above.
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const bool below = free(i, j - 1), above = free(i, j);
      if (below == above) continue;
      const Eigen::Vector2d a(xs[i], ys[j]), b(xs[i + 1], ys[j]);
      if (above)
        add(a, b);
      else
        add(b, a);
    }
  }
  for (size_t k = 0; k < walls.size(); ++k) walls[k].id = static_cast<int>(k);
  return walls;
}

}  // namespace sightline::sim
