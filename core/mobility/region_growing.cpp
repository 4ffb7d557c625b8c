#include "core/mobility/region_growing.h"

#include <cmath>

namespace sightline {

std::vector<cv::Vec3b> EncodeNormals(const std::vector<Eigen::Vector3f>& normals) {
  std::vector<cv::Vec3b> colors(normals.size(), cv::Vec3b(0, 0, 0));
  for (size_t i = 0; i < normals.size(); ++i) {
    const Eigen::Vector3f& n = normals[i];
    if (!n.allFinite()) continue;
    for (int c = 0; c < 3; ++c) {
      colors[i][c] = cv::saturate_cast<uchar>(std::lround(255.0 * (n[c] + 1.0) / 2.0));
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

}  // namespace sightline
