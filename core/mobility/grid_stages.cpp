#include "core/mobility/grid_stages.h"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>

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
  out.cell_point.assign(static_cast<size_t>(out.grid_w) * out.grid_h, -1);
  out.points.reserve(out.cell_point.size());
  for (int gy = 0; gy < out.grid_h; ++gy) {
    for (int gx = 0; gx < out.grid_w; ++gx) {
      const int index = gy * stride * cloud.width + gx * stride;
      const Eigen::Vector3f& p = cloud.points[index];
      if (!std::isfinite(p.z()) || !std::isfinite(p.x()) || !std::isfinite(p.y()) || p.z() <= 0) {
        continue;
      }
      const int cell = gy * out.grid_w + gx;
      out.cell_point[cell] = static_cast<int>(out.points.size());
      out.point_cell.push_back(cell);
      out.points.push_back(p);
      out.pixel.push_back(index);
    }
  }
  return out;
}

void RangeCut(double max_range_m, WorkingCloud* cloud) {
  const float max2 = static_cast<float>(max_range_m * max_range_m);
  std::vector<uint8_t> keep(cloud->size());
  for (size_t i = 0; i < cloud->size(); ++i) {
    const Eigen::Vector3f& p = cloud->points[i];
    keep[i] = p.allFinite() && p.squaredNorm() <= max2;
  }
  cloud->Compact(keep);
}

void GridRemoveOutliers(double alpha, WorkingCloud* cloud) {
  const size_t n = cloud->size();
  std::vector<float> mean_distance(n, -1.f);
  double sum = 0, sum2 = 0;
  int counted = 0;
  for (size_t i = 0; i < n; ++i) {
    const int cell = cloud->point_cell[i];
    const int gx = cell % cloud->grid_w, gy = cell / cloud->grid_w;
    float total = 0;
    int k = 0;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || gx + dx < 0 || gy + dy < 0 || gx + dx >= cloud->grid_w ||
            gy + dy >= cloud->grid_h) {
          continue;
        }
        const int j = cloud->cell_point[(gy + dy) * cloud->grid_w + gx + dx];
        if (j < 0) continue;
        total += (cloud->points[j] - cloud->points[i]).norm();
        ++k;
      }
    }
    if (k == 0) continue;
    mean_distance[i] = total / k / cloud->points[i].z();
    sum += mean_distance[i];
    sum2 += static_cast<double>(mean_distance[i]) * mean_distance[i];
    ++counted;
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

namespace {

// Ten moments per cell: count, x, y, z, xx, xy, xz, yy, yz, zz.
using Moments = std::array<double, 10>;

Moments PointMoments(const Eigen::Vector3f& p) {
  const double x = p.x(), y = p.y(), z = p.z();
  return {1, x, y, z, x * x, x * y, x * z, y * y, y * z, z * z};
}

}  // namespace

void GridNormals(int window, double max_curvature, WorkingCloud* cloud) {
  const int w = cloud->grid_w, h = cloud->grid_h;
  // Integral image with a zero first row and column: sums over [0, x) x [0, y).
  std::vector<Moments> integral(static_cast<size_t>(w + 1) * (h + 1), Moments{});
  for (int y = 0; y < h; ++y) {
    Moments row{};
    for (int x = 0; x < w; ++x) {
      const int j = cloud->cell_point[y * w + x];
      if (j >= 0) {
        const Moments m = PointMoments(cloud->points[j]);
        for (int c = 0; c < 10; ++c) row[c] += m[c];
      }
      const Moments& above = integral[static_cast<size_t>(y) * (w + 1) + x + 1];
      Moments& here = integral[static_cast<size_t>(y + 1) * (w + 1) + x + 1];
      for (int c = 0; c < 10; ++c) here[c] = above[c] + row[c];
    }
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud->normals.assign(cloud->size(), Eigen::Vector3f(nan, nan, nan));
  for (size_t i = 0; i < cloud->size(); ++i) {
    const int cell = cloud->point_cell[i];
    const int gx = cell % w, gy = cell / w;
    const int x0 = std::max(0, gx - window), x1 = std::min(w, gx + window + 1);
    const int y0 = std::max(0, gy - window), y1 = std::min(h, gy + window + 1);
    const Moments& a = integral[static_cast<size_t>(y0) * (w + 1) + x0];
    const Moments& b = integral[static_cast<size_t>(y0) * (w + 1) + x1];
    const Moments& c = integral[static_cast<size_t>(y1) * (w + 1) + x0];
    const Moments& d = integral[static_cast<size_t>(y1) * (w + 1) + x1];
    Moments s;
    for (int k = 0; k < 10; ++k) s[k] = d[k] - b[k] - c[k] + a[k];
    if (s[0] < 3) continue;
    const double inv = 1.0 / s[0];
    const Eigen::Vector3d mean(s[1] * inv, s[2] * inv, s[3] * inv);
    Eigen::Matrix3d cov;
    cov(0, 0) = s[4] * inv - mean.x() * mean.x();
    cov(0, 1) = cov(1, 0) = s[5] * inv - mean.x() * mean.y();
    cov(0, 2) = cov(2, 0) = s[6] * inv - mean.x() * mean.z();
    cov(1, 1) = s[7] * inv - mean.y() * mean.y();
    cov(1, 2) = cov(2, 1) = s[8] * inv - mean.y() * mean.z();
    cov(2, 2) = s[9] * inv - mean.z() * mean.z();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(cov);
    const Eigen::Vector3d& eigenvalues = solver.eigenvalues();
    const double variation = eigenvalues(0) / std::max(1e-20, eigenvalues.sum());
    if (variation > max_curvature) continue;  // An edge or a corner.
    Eigen::Vector3f n = solver.eigenvectors().col(0).cast<float>();
    if (!n.allFinite()) continue;
    if (n.dot(cloud->points[i]) > 0) n = -n;  // Towards the viewpoint at the origin.
    cloud->normals[i] = n.normalized();
  }
}

void GridNeighbors(const WorkingCloud& cloud, int i, double max_depth_jump, std::vector<int>* out) {
  out->clear();
  const int cell = cloud.point_cell[i];
  const int gx = cell % cloud.grid_w, gy = cell / cloud.grid_w;
  const float z = cloud.points[i].z();
  const float jump = static_cast<float>(max_depth_jump) * z;
  static constexpr int kDx[4] = {1, -1, 0, 0};
  static constexpr int kDy[4] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const int x = gx + kDx[k], y = gy + kDy[k];
    if (x < 0 || y < 0 || x >= cloud.grid_w || y >= cloud.grid_h) continue;
    const int j = cloud.cell_point[y * cloud.grid_w + x];
    if (j >= 0 && std::abs(cloud.points[j].z() - z) <= jump) out->push_back(j);
  }
}

}  // namespace sightline
