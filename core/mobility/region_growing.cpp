#include "core/mobility/region_growing.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sightline {

std::vector<cv::Vec3b> EncodeNormals(const std::vector<Eigen::Vector3f>& normals) {
  std::vector<cv::Vec3b> colors(normals.size(), cv::Vec3b(0, 0, 0));
  for (size_t i = 0; i < normals.size(); ++i) {
    const Eigen::Vector3f& n = normals[i];
    if (!n.allFinite()) continue;
    for (int c = 0; c < 3; ++c) {
      // In [0, 255] for a unit normal (up to rounding): rounding is adding a half and
      // truncating.
      const double value = 255.0 * (n[c] + 1.0) / 2.0;
      colors[i][c] = static_cast<uchar>(static_cast<int>(value + 0.5));
    }
  }
  return colors;
}

std::vector<int> GrowRegions(const std::vector<cv::Vec3b>& rgbn,
                             const std::vector<uint8_t>& eligible, double color_threshold,
                             int min_points, const NeighborFunction& neighbors, int* regions) {
  const size_t n = rgbn.size();
  std::vector<int> label(n, -1);
  const int threshold2 = static_cast<int>(std::floor(color_threshold * color_threshold));
  std::vector<int> queue, found, members;
  int next = 0;
  for (size_t seed = 0; seed < n; ++seed) {
    if (!eligible[seed] || label[seed] != -1) continue;
    members.clear();
    queue.assign(1, static_cast<int>(seed));
    label[seed] = next;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int p = queue[head];
      members.push_back(p);
      neighbors(p, &found);
      for (int q : found) {
        if (!eligible[q] || label[q] != -1) continue;
        int d2 = 0;
        for (int c = 0; c < 3; ++c) {
          const int diff = static_cast<int>(rgbn[p][c]) - rgbn[q][c];
          d2 += diff * diff;
        }
        if (d2 > threshold2) continue;
        label[q] = next;
        queue.push_back(q);
      }
    }
    if (static_cast<int>(members.size()) < min_points) {
      for (int p : members) label[p] = -2;  // Visited, too small.
      continue;
    }
    ++next;
  }
  for (int& l : label) {
    if (l < 0) l = -1;
  }
  *regions = next;
  return label;
}

namespace {

// The root of i's tree, halving the path on the way.
int Root(std::vector<int>* parent, int i) {
  int* p = parent->data();
  while (p[i] != i) {
    p[i] = p[p[i]];
    i = p[i];
  }
  return i;
}

// Joins the trees of a and b under the smaller root, so that a root is its region's first point.
void Join(std::vector<int>* parent, int a, int b) {
  a = Root(parent, a);
  b = Root(parent, b);
  if (a < b) {
    (*parent)[b] = a;
  } else if (b < a) {
    (*parent)[a] = b;
  }
}

}  // namespace

std::vector<int> GrowGridRegions(const WorkingCloud& cloud, const std::vector<cv::Vec3b>& rgbn,
                                 const std::vector<uint8_t>& eligible, double color_threshold,
                                 double max_depth_jump, int min_points, int* regions) {
  const int n = static_cast<int>(cloud.size());
  const int w = cloud.grid_w;
  const int threshold2 = static_cast<int>(std::floor(color_threshold * color_threshold));
  const float jump = static_cast<float>(max_depth_jump);
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto linked = [&](int i, int j) {
    if (!eligible[j]) return false;
    const float zi = cloud.points[i].z(), zj = cloud.points[j].z();
    if (std::abs(zj - zi) > jump * std::min(zi, zj)) return false;
    int d2 = 0;
    for (int c = 0; c < 3; ++c) {
      const int diff = static_cast<int>(rgbn[i][c]) - rgbn[j][c];
      d2 += diff * diff;
    }
    return d2 <= threshold2;
  };
  for (int i = 0; i < n; ++i) {
    if (!eligible[i]) continue;
    const int cell = cloud.point_cell[i];
    const int gx = cell % w;
    if (gx > 0) {
      const int left = cloud.cell_point[cell - 1];
      if (left >= 0 && linked(i, left)) Join(&parent, i, left);
    }
    if (cell >= w) {
      const int up = cloud.cell_point[cell - w];
      if (up >= 0 && linked(i, up)) Join(&parent, i, up);
    }
  }
  // Every parent precedes its child, so one pass in index order points each at its root. Then
  // region sizes at the roots, and numbers in the order of the regions' first points.
  std::vector<int> size(n, 0);
  for (int i = 0; i < n; ++i) {
    parent[i] = parent[parent[i]];
    if (eligible[i]) ++size[parent[i]];
  }
  std::vector<int> label(n, -1);
  int next = 0;
  for (int i = 0; i < n; ++i) {
    if (!eligible[i]) continue;
    const int root = parent[i];
    if (root == i) {
      if (size[i] >= min_points) label[i] = next++;
    } else {
      label[i] = label[root];  // The root comes first.
    }
  }
  *regions = next;
  return label;
}

}  // namespace sightline
