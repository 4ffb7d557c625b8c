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
  const int w = cloud->grid_w, h = cloud->grid_h;
  // Each neighbour pair once (right, down-left, down, down-right), added to both ends.
  std::vector<float> total(n, 0.f);
  std::vector<uint8_t> neighbours(n, 0);
  for (int y = 0; y < h; ++y) {
    const int* row = &cloud->cell_point[static_cast<size_t>(y) * w];
    const int* below = y + 1 < h ? row + w : nullptr;
    for (int x = 0; x < w; ++x) {
      const int i = row[x];
      if (i < 0) continue;
      const Eigen::Vector3f& p = cloud->points[i];
      auto pair = [&](int j) {
        if (j < 0) return;
        const float d = (cloud->points[j] - p).norm();
        total[i] += d, total[j] += d;
        ++neighbours[i], ++neighbours[j];
      };
      if (x + 1 < w) pair(row[x + 1]);
      if (below != nullptr) {
        if (x > 0) pair(below[x - 1]);
        pair(below[x]);
        if (x + 1 < w) pair(below[x + 1]);
      }
    }
  }
  std::vector<float> mean_distance(n, -1.f);
  double sum = 0, sum2 = 0;
  int counted = 0;
  for (size_t i = 0; i < n; ++i) {
    if (neighbours[i] == 0) continue;
    mean_distance[i] = total[i] / neighbours[i] / cloud->points[i].z();
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

// The windows of one grid row whose normals are wanted, as arrays (one entry per point) so that
// the Newton steps below run without branches over many windows at once: their divisions
// overlap instead of waiting on each other.
struct WindowBatch {
  std::vector<int> point;
  std::vector<double> a00, a01, a02, a11, a12, a22, trace, c0, c1, l, step;

  void Resize(size_t n) {
    for (std::vector<double>* v :
         {&a00, &a01, &a02, &a11, &a12, &a22, &trace, &c0, &c1, &l, &step}) {
      v->resize(n);
    }
    point.resize(n);
  }

  // Covariance of the window sums s and the coefficients of its characteristic polynomial
  // f(l) = l^3 - trace l^2 + c1 l - c0 = -det(A - l I).
  void Set(size_t k, int i, const Moments& s) {
    const double inv = 1.0 / s.m[0];
    const double mx = s.m[1] * inv, my = s.m[2] * inv, mz = s.m[3] * inv;
    const double b00 = s.m[4] * inv - mx * mx, b01 = s.m[5] * inv - mx * my;
    const double b02 = s.m[6] * inv - mx * mz, b11 = s.m[7] * inv - my * my;
    const double b12 = s.m[8] * inv - my * mz, b22 = s.m[9] * inv - mz * mz;
    const double m00 = b11 * b22 - b12 * b12, m01 = b02 * b12 - b01 * b22;
    const double m02 = b01 * b12 - b02 * b11;
    point[k] = i;
    a00[k] = b00, a01[k] = b01, a02[k] = b02, a11[k] = b11, a12[k] = b12, a22[k] = b22;
    trace[k] = b00 + b11 + b22;
    c1[k] = m00 + b00 * b22 - b02 * b02 + b00 * b11 - b01 * b01;
    c0[k] = b00 * m00 + b01 * m01 + b02 * m02;
  }
};

// One Newton step towards the smallest root of f from below, kept only when it moves up.
inline double NewtonStep(double l, double trace, double c1, double c0) {
  const double f = ((l - trace) * l + c1) * l - c0;
  const double df = (3 * l - 2 * trace) * l + c1;
  const double next = l - f / df;
  return df > 0 && next > l ? next : l;
}

// The smallest eigenvalue comes from Newton's method on the characteristic polynomial started
// at 0: for a positive semi-definite matrix the polynomial is concave and increasing below its
// smallest root, so every iterate is a lower bound. Three steps reach it for nearly every
// window (a step of 1e-6 trace turns the normal by about step / eigenvalue gap: far below one
// colour step); the rest continue here, stopping as soon as an iterate exceeds the curvature
// limit. Returns the normal (unit eigenvector of the smallest eigenvalue) of entry k, or false
// for an edge or corner (smallest eigenvalue / trace > max_curvature) or a degenerate window.
bool FinishWindow(const WindowBatch& b, size_t k, double max_curvature, Eigen::Vector3d* normal) {
  const double trace = b.trace[k];
  if (!(trace > 1e-20)) return false;
  const double limit = max_curvature * trace;
  double l = b.l[k];
  if (l > limit) return false;  // An edge or a corner.
  if (b.step[k] > 1e-6 * trace) {
    for (int it = 0; it < 50; ++it) {
      const double next = NewtonStep(l, trace, b.c1[k], b.c0[k]);
      const bool converged = next - l <= 1e-6 * trace;
      l = next;
      if (l > limit) return false;
      if (converged) break;
    }
  }
  // The null vector of A - l I: the longest cross product of two of its rows.
  const Eigen::Vector3d r0(b.a00[k] - l, b.a01[k], b.a02[k]);
  const Eigen::Vector3d r1(b.a01[k], b.a11[k] - l, b.a12[k]);
  const Eigen::Vector3d r2(b.a02[k], b.a12[k], b.a22[k] - l);
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
  WindowBatch batch;
  batch.Resize(w);
  for (int y = 0; y < std::min(window, h); ++y) add_row(y, true);
  for (int y = 0; y < h; ++y) {
    if (y + window < h) add_row(y + window, true);
    if (y - window - 1 >= 0) add_row(y - window - 1, false);
    Moments s;
    for (int x = 0; x < std::min(window, w); ++x) s += column[x];
    const int* row = &cloud->cell_point[static_cast<size_t>(y) * w];
    size_t count = 0;
    for (int x = 0; x < w; ++x) {
      if (x + window < w) s += column[x + window];
      if (x - window - 1 >= 0) s -= column[x - window - 1];
      if (row[x] < 0 || s.m[0] < 2.5) continue;  // At least 3 points.
      batch.Set(count++, row[x], s);
    }
    for (size_t k = 0; k < count; ++k) {
      const double trace = batch.trace[k], c1 = batch.c1[k], c0 = batch.c0[k];
      const double l1 = NewtonStep(0, trace, c1, c0);
      const double l2 = NewtonStep(l1, trace, c1, c0);
      const double l3 = NewtonStep(l2, trace, c1, c0);
      batch.l[k] = l3;
      batch.step[k] = l3 - l2;
    }
    for (size_t k = 0; k < count; ++k) {
      Eigen::Vector3d n;
      if (!FinishWindow(batch, k, max_curvature, &n)) continue;
      Eigen::Vector3f nf = n.cast<float>();
      if (!nf.allFinite()) continue;
      const int i = batch.point[k];
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
