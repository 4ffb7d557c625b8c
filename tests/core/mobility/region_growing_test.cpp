// Region growing on the grid: label propagation (GrowGridRegions) gives exactly the flood fill's
// regions (GrowRegions over GridNeighbors), numbering and the minimum size included.
#include "core/mobility/region_growing.h"

#include <gtest/gtest.h>

#include <random>

#include "core/mobility/grid_stages.h"

namespace sightline {
namespace {

// A w x h grid with holes, depth steps and patches of a few normal colours with small noise,
// so that regions touch, merge through chains and fall below the minimum size.
struct GridScene {
  WorkingCloud cloud;
  std::vector<cv::Vec3b> rgbn;
  std::vector<uint8_t> eligible;
};

GridScene MakeScene(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  std::uniform_int_distribution<int> noise(-3, 3);
  const cv::Vec3b colours[3] = {cv::Vec3b(128, 30, 128), cv::Vec3b(128, 128, 10),
                                cv::Vec3b(60, 128, 40)};
  GridScene s;
  s.cloud.grid_w = w;
  s.cloud.grid_h = h;
  s.cloud.cell_point.assign(static_cast<size_t>(w) * h, -1);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (unit(rng) < 0.05f) continue;  // A hole.
      const int cell = y * w + x;
      const float z = 1.0f + 0.5f * static_cast<float>((x / 7 + y / 5) % 3) + 0.01f * unit(rng);
      s.cloud.cell_point[cell] = static_cast<int>(s.cloud.points.size());
      s.cloud.point_cell.push_back(cell);
      s.cloud.pixel.push_back(cell);
      s.cloud.points.emplace_back(0.01f * x, 0.01f * y, z);
      cv::Vec3b c = colours[(x / 9 + 2 * (y / 6)) % 3];
      for (int k = 0; k < 3; ++k) c[k] = cv::saturate_cast<uchar>(c[k] + noise(rng));
      s.rgbn.push_back(c);
      s.eligible.push_back(unit(rng) < 0.9f);
    }
  }
  return s;
}

TEST(GrowGridRegions, GivesTheFloodFillRegions) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const GridScene s = MakeScene(64, 48, seed);
    for (int min_points : {1, 5, 30}) {
      int flood_regions = 0, grid_regions = 0;
      const std::vector<int> flood = GrowRegions(
          s.rgbn, s.eligible, 10.0, min_points,
          [&](int i, std::vector<int>* out) { GridNeighbors(s.cloud, i, 0.05, out); },
          &flood_regions);
      const std::vector<int> grid =
          GrowGridRegions(s.cloud, s.rgbn, s.eligible, 10.0, 0.05, min_points, &grid_regions);
      EXPECT_EQ(grid_regions, flood_regions) << "seed " << seed << ", min " << min_points;
      EXPECT_EQ(grid, flood) << "seed " << seed << ", min " << min_points;
      EXPECT_GE(grid_regions, 3) << "the scene must hold several regions";
    }
  }
}

TEST(GrowGridRegions, DepthStepsAndColourEdgesSeparate) {
  // Two 10x10 patches side by side: same colour, 1.0 m and 1.2 m away (a 20 % step).
  WorkingCloud cloud;
  cloud.grid_w = 20;
  cloud.grid_h = 10;
  cloud.cell_point.assign(200, -1);
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 20; ++x) {
      cloud.cell_point[y * 20 + x] = static_cast<int>(cloud.points.size());
      cloud.point_cell.push_back(y * 20 + x);
      cloud.points.emplace_back(0.01f * x, 0.01f * y, x < 10 ? 1.0f : 1.2f);
    }
  }
  std::vector<cv::Vec3b> rgbn(200, cv::Vec3b(128, 20, 128));
  std::vector<uint8_t> eligible(200, 1);
  int regions = 0;
  std::vector<int> label = GrowGridRegions(cloud, rgbn, eligible, 14, 0.05, 10, &regions);
  EXPECT_EQ(regions, 2);
  EXPECT_NE(label[0], label[19]);
  // Same depth, colours 20 apart: also two regions; with a threshold above 20, one.
  for (auto& p : cloud.points) p.z() = 1.0f;
  for (int i = 0; i < 200; ++i) {
    if (cloud.point_cell[i] % 20 >= 10) rgbn[i] = cv::Vec3b(148, 20, 128);
  }
  label = GrowGridRegions(cloud, rgbn, eligible, 14, 0.05, 10, &regions);
  EXPECT_EQ(regions, 2);
  label = GrowGridRegions(cloud, rgbn, eligible, 21, 0.05, 10, &regions);
  EXPECT_EQ(regions, 1);
  // Too small: nothing.
  label = GrowGridRegions(cloud, rgbn, eligible, 21, 0.05, 201, &regions);
  EXPECT_EQ(regions, 0);
  for (int l : label) EXPECT_EQ(l, -1);
}

}  // namespace
}  // namespace sightline
