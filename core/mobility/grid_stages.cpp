#include "core/mobility/grid_stages.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sightline {

void WorkingCloud::Compact(const std::vector<uint8_t>& keep) {
  size_t out = 0;
  const bool has_normals = normals.size() == points.size();
  const bool has_pixels = pixel.size() == points.size();
  const bool grid = gridded();
  for (size_t i = 0; i < points.size(); ++i) {
    if (!keep[i]) {
      if (grid) cell_point[point_cell[i]] = -1;
      continue;
    }
    points[out] = points[i];
    if (has_normals) normals[out] = normals[i];
    if (has_pixels) pixel[out] = pixel[i];
    if (grid) {
      point_cell[out] = point_cell[i];
      cell_point[point_cell[i]] = static_cast<int>(out);
    }
    ++out;
  }
  points.resize(out);
  if (has_normals) normals.resize(out);
  if (has_pixels) pixel.resize(out);
  if (grid) point_cell.resize(out);
}

StatusOr<WorkingCloud> GridDownsample(const PointCloud& cloud, int stride) {
  if (!cloud.organized()) {
    return FailedPrecondition("mobility mode 'grid' needs an organized cloud (this one is " +
                              std::to_string(cloud.size()) + " points in one row); use mode pcl");
  }
  WorkingCloud out;
  out.grid_w = (cloud.width + stride - 1) / stride;
  out.grid_h = (cloud.height + stride - 1) / stride;
  const size_t cells = static_cast<size_t>(out.grid_w) * out.grid_h;
  out.cell_point.resize(cells);
  // Written in place (sized for every cell, trimmed at the end): no growth checks per point.
  out.points.resize(cells);
  out.pixel.resize(cells);
  out.point_cell.resize(cells);
  int count = 0;
  for (int gy = 0; gy < out.grid_h; ++gy) {
    for (int gx = 0; gx < out.grid_w; ++gx) {
      const int index = gy * stride * cloud.width + gx * stride;
      const Eigen::Vector3f& p = cloud.points[index];
      const int cell = gy * out.grid_w + gx;
      // Finite with positive depth (x - x is NaN for an infinite or NaN x).
      const bool valid = p.x() - p.x() == 0 && p.y() - p.y() == 0 && p.z() > 0 &&
                         p.z() < std::numeric_limits<float>::infinity();
      out.cell_point[cell] = valid ? count : -1;
      out.points[count] = p;
      out.pixel[count] = index;
      out.point_cell[count] = cell;
      count += valid;
    }
  }
  out.points.resize(count);
  out.pixel.resize(count);
  out.point_cell.resize(count);
  return out;
}

void RangeCut(double max_range_m, WorkingCloud* cloud) {
  const float max2 = static_cast<float>(max_range_m * max_range_m);
  std::vector<uint8_t> keep(cloud->size());
  size_t kept = 0;
  for (size_t i = 0; i < cloud->size(); ++i) {
    // A NaN or infinite coordinate fails the comparison too.
    keep[i] = cloud->points[i].squaredNorm() <= max2;
    kept += keep[i];
  }
  if (kept < cloud->size()) cloud->Compact(keep);
}

void GridRemoveOutliers(double alpha, WorkingCloud* cloud) {
  const size_t n = cloud->size();
  const int w = cloud->grid_w, h = cloud->grid_h;
  // Each neighbour pair once (right, down-left, down, down-right), added to both ends. Rows
  // are laid out densely (NaN where a cell holds no point), so that the distances between two
  // rows run as plain loops the compiler vectorizes; a NaN distance is no pair.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const size_t width = static_cast<size_t>(w);
  std::vector<float> row_a(3 * width), row_b(3 * width);  // x..., y..., z... of a row.
  auto fill = [&](int y, std::vector<float>* row) {
    float* out = row->data();
    const int* cells = &cloud->cell_point[static_cast<size_t>(y) * w];
    for (size_t x = 0; x < width; ++x) {
      const int i = cells[x];
      const Eigen::Vector3f p = i >= 0 ? cloud->points[i] : Eigen::Vector3f(nan, nan, nan);
      out[x] = p.x(), out[width + x] = p.y(), out[2 * width + x] = p.z();
    }
  };
  // d[x + 1] = |a[x] - b[x + shift]| for x + shift inside the row, NaN elsewhere (d has a
  // NaN margin of one on both sides, so that neighbours' entries need no bounds checks).
  std::vector<float> right(width + 2, nan), down(width + 2, nan), down_left(width + 2, nan);
  std::vector<float> down_right(width + 2, nan);
  auto distances = [&](const std::vector<float>& a, const std::vector<float>& b, int shift,
                       std::vector<float>* d) {
    const float *ax = a.data(), *ay = ax + width, *az = ay + width;
    const float *bx = b.data(), *by = bx + width, *bz = by + width;
    const size_t x0 = shift < 0 ? 1 : 0, x1 = shift > 0 ? width - 1 : width;
    float* out = d->data() + 1;
    for (size_t x = 0; x < x0; ++x) out[x] = nan;
    for (size_t x = x0; x < x1; ++x) {
      const float dx = ax[x] - bx[x + shift], dy = ay[x] - by[x + shift];
      const float dz = az[x] - bz[x + shift];
      out[x] = std::sqrt(dx * dx + dy * dy + dz * dz);
    }
    for (size_t x = x1; x < width; ++x) out[x] = nan;
  };
  auto value = [](float d) { return d == d ? d : 0.f; };  // NaN (no pair) adds nothing.
  auto count = [](float d) { return d == d ? 1.f : 0.f; };
  std::vector<float> total_a(width, 0.f), total_b(width), count_a(width, 0.f), count_b(width);
  std::vector<float> total(n, 0.f), neighbours(n, 0.f);
  if (h > 0) fill(0, &row_a);
  for (int y = 0; y < h; ++y) {
    distances(row_a, row_a, 1, &right);
    const bool last = y + 1 == h;
    if (!last) {
      fill(y + 1, &row_b);
      distances(row_a, row_b, 0, &down);
      distances(row_a, row_b, -1, &down_left);
      distances(row_a, row_b, 1, &down_right);
    }
    // Entry x of the distance arrays is at x + 1.
    const float *r = right.data() + 1, *dn = down.data() + 1, *dl = down_left.data() + 1;
    const float* dr = down_right.data() + 1;
    for (size_t x = 0; x < width; ++x) {
      total_a[x] += value(r[x]) + value(r[x - 1]);
      count_a[x] += count(r[x]) + count(r[x - 1]);
    }
    std::fill(total_b.begin(), total_b.end(), 0.f);
    std::fill(count_b.begin(), count_b.end(), 0.f);
    if (!last) {
      for (size_t x = 0; x < width; ++x) {
        total_a[x] += value(dn[x]) + value(dl[x]) + value(dr[x]);
        count_a[x] += count(dn[x]) + count(dl[x]) + count(dr[x]);
        // Below: its up neighbour, its up-right (our down-left) and up-left (down-right).
        total_b[x] = value(dn[x]) + value(dl[x + 1]) + value(dr[x - 1]);
        count_b[x] = count(dn[x]) + count(dl[x + 1]) + count(dr[x - 1]);
      }
    }
    const int* cells = &cloud->cell_point[static_cast<size_t>(y) * w];
    for (size_t x = 0; x < width; ++x) {
      if (cells[x] >= 0) total[cells[x]] = total_a[x], neighbours[cells[x]] = count_a[x];
    }
    std::swap(row_a, row_b);
    std::swap(total_a, total_b);
    std::swap(count_a, count_b);
  }
  // Mean neighbour distance over depth (-1 for an isolated point), then its mean and spread.
  std::vector<float> mean_distance(n);
  for (size_t i = 0; i < n; ++i) {
    const float k = neighbours[i];
    mean_distance[i] = k > 0 ? total[i] / (k * cloud->points[i].z()) : -1.f;
  }
  double sum = 0, sum2 = 0;
  int counted = 0;
  for (size_t i = 0; i < n; ++i) {
    const double d = mean_distance[i];
    const bool has = d >= 0;
    sum += has ? d : 0.0;
    sum2 += has ? d * d : 0.0;
    counted += has;
  }
  std::vector<uint8_t> keep(n, 0);
  if (counted > 0) {
    const double mu = sum / counted;
    const double sigma = std::sqrt(std::max(0.0, sum2 / counted - mu * mu));
    const float limit = static_cast<float>(mu + alpha * sigma);
    for (size_t i = 0; i < n; ++i) keep[i] = mean_distance[i] >= 0 && mean_distance[i] <= limit;
  }
  cloud->Compact(keep);
}

void GridNeighbors(const WorkingCloud& cloud, int i, double max_depth_jump, std::vector<int>* out) {
  out->clear();
  const int cell = cloud.point_cell[i];
  const int gx = cell % cloud.grid_w, gy = cell / cloud.grid_w;
  const float z = cloud.points[i].z();
  const float jump = static_cast<float>(max_depth_jump);
  static constexpr int kDx[4] = {1, -1, 0, 0};
  static constexpr int kDy[4] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const int x = gx + kDx[k], y = gy + kDy[k];
    if (x < 0 || y < 0 || x >= cloud.grid_w || y >= cloud.grid_h) continue;
    const int j = cloud.cell_point[y * cloud.grid_w + x];
    if (j < 0) continue;
    const float zj = cloud.points[j].z();
    if (std::abs(zj - z) <= jump * std::min(z, zj)) out->push_back(j);
  }
}

}  // namespace sightline
