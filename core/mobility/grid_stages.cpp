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

// Ten moments of the points of a cell or window: count, x, y, z, xx, xy, xz, yy, yz, zz.
struct Moments {
  double m[10] = {};
  void Add(const Eigen::Vector3f& p) {
    const double x = p.x(), y = p.y(), z = p.z();
    m[0] += 1, m[1] += x, m[2] += y, m[3] += z;
    m[4] += x * x, m[5] += x * y, m[6] += x * z, m[7] += y * y, m[8] += y * z, m[9] += z * z;
  }
  void Subtract(const Eigen::Vector3f& p) {
    const double x = p.x(), y = p.y(), z = p.z();
    m[0] -= 1, m[1] -= x, m[2] -= y, m[3] -= z;
    m[4] -= x * x, m[5] -= x * y, m[6] -= x * z, m[7] -= y * y, m[8] -= y * z, m[9] -= z * z;
  }
  void operator+=(const Moments& o) {
    for (int k = 0; k < 10; ++k) m[k] += o.m[k];
  }
  void operator-=(const Moments& o) {
    for (int k = 0; k < 10; ++k) m[k] -= o.m[k];
  }
};

// The normal (unit eigenvector of the smallest eigenvalue) of a window's covariance, or false
// when the window bends more than max_curvature (smallest eigenvalue / trace) or is degenerate.
// The smallest eigenvalue comes from Newton's method on the characteristic polynomial started
// at 0: for a positive semi-definite matrix the polynomial is concave and increasing below its
// smallest root, so every iterate is a lower bound and the search stops as soon as one exceeds
// the curvature limit (edges cost a step or two, flat windows converge in two or three).
bool WindowNormal(const Moments& s, double max_curvature, Eigen::Vector3d* normal) {
  const double inv = 1.0 / s.m[0];
  const double mx = s.m[1] * inv, my = s.m[2] * inv, mz = s.m[3] * inv;
  const double a00 = s.m[4] * inv - mx * mx, a01 = s.m[5] * inv - mx * my;
  const double a02 = s.m[6] * inv - mx * mz, a11 = s.m[7] * inv - my * my;
  const double a12 = s.m[8] * inv - my * mz, a22 = s.m[9] * inv - mz * mz;
  const double trace = a00 + a11 + a22;
  if (!(trace > 1e-20)) return false;
  const double m00 = a11 * a22 - a12 * a12, m01 = a02 * a12 - a01 * a22;
  const double m02 = a01 * a12 - a02 * a11;
  const double c1 = m00 + a00 * a22 - a02 * a02 + a00 * a11 - a01 * a01;
  const double c0 = a00 * m00 + a01 * m01 + a02 * m02;
  // f(l) = l^3 - trace l^2 + c1 l - c0 = -det(A - l I).
  const double limit = max_curvature * trace;
  double l = 0;
  for (int it = 0; it < 50; ++it) {
    const double f = ((l - trace) * l + c1) * l - c0;
    const double df = (3 * l - 2 * trace) * l + c1;
    if (!(f < 0) || !(df > 0)) break;
    const double next = l - f / df;
    if (!(next > l)) break;
    const bool converged = next - l <= 1e-8 * trace;  // Far below float precision.
    l = next;
    if (l > limit) return false;  // An edge or a corner.
    if (converged) break;
  }
  // The null vector of A - l I: the longest cross product of two of its rows.
  const Eigen::Vector3d r0(a00 - l, a01, a02), r1(a01, a11 - l, a12), r2(a02, a12, a22 - l);
  const Eigen::Vector3d c01 = r0.cross(r1), c02 = r0.cross(r2), c12 = r1.cross(r2);
  const double n01 = c01.squaredNorm(), n02 = c02.squaredNorm(), n12 = c12.squaredNorm();
  const Eigen::Vector3d& best = n01 >= n02 ? (n01 >= n12 ? c01 : c12) : (n02 >= n12 ? c02 : c12);
  const double norm2 = std::max(n01, std::max(n02, n12));
  if (!(norm2 > 1e-30 * trace * trace * trace * trace)) return false;  // A line: no plane.
  *normal = best / std::sqrt(norm2);
  return true;
}

}  // namespace

void GridNormals(int window, double max_curvature, WorkingCloud* cloud) {
  const int w = cloud->grid_w, h = cloud->grid_h;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud->normals.assign(cloud->size(), Eigen::Vector3f(nan, nan, nan));
  // Box sums over (2 window + 1)^2 cells, slid along the grid: per column the sum over the
  // window's rows, then per row a running sum of those column sums. Constant work per cell and
  // a working set of one grid row.
  std::vector<Moments> column(w);
  auto add_row = [&](int y, bool add) {
    const int* row = &cloud->cell_point[static_cast<size_t>(y) * w];
    for (int x = 0; x < w; ++x) {
      if (row[x] < 0) continue;
      if (add) {
        column[x].Add(cloud->points[row[x]]);
      } else {
        column[x].Subtract(cloud->points[row[x]]);
      }
    }
  };
  for (int y = 0; y < std::min(window, h); ++y) add_row(y, true);
  for (int y = 0; y < h; ++y) {
    if (y + window < h) add_row(y + window, true);
    if (y - window - 1 >= 0) add_row(y - window - 1, false);
    Moments s;
    for (int x = 0; x < std::min(window, w); ++x) s += column[x];
    const int* row = &cloud->cell_point[static_cast<size_t>(y) * w];
    for (int x = 0; x < w; ++x) {
      if (x + window < w) s += column[x + window];
      if (x - window - 1 >= 0) s -= column[x - window - 1];
      const int i = row[x];
      if (i < 0 || s.m[0] < 2.5) continue;  // At least 3 points.
      Eigen::Vector3d n;
      if (!WindowNormal(s, max_curvature, &n)) continue;
      Eigen::Vector3f nf = n.cast<float>();
      if (!nf.allFinite()) continue;
      if (nf.dot(cloud->points[i]) > 0) nf = -nf;  // Towards the viewpoint at the origin.
      cloud->normals[i] = nf;
    }
  }
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
