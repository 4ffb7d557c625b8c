#include "core/mobility/grid_normals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

namespace sightline {
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

// The windows of one grid row whose normals are wanted, as arrays (one entry per point), so
// that the arithmetic runs on two windows at a time and the divisions and square roots of
// different windows overlap.
struct WindowBatch {
  std::vector<int> point;
  std::vector<double> sums[10];  // The window's moments (Moments::m).
  std::vector<double> a00, a01, a02, a11, a12, a22, trace, c0, c1, l, nx, ny, nz;
  std::vector<float> c1_scaled, c0_scaled, l_scaled, step_scaled;  // Over the trace.

  void Resize(size_t n) {
    point.resize(n);
    for (std::vector<double>& v : sums) v.resize(n);
    for (std::vector<double>* v :
         {&a00, &a01, &a02, &a11, &a12, &a22, &trace, &c0, &c1, &l, &nx, &ny, &nz}) {
      v->resize(n);
    }
    for (std::vector<float>* v : {&c1_scaled, &c0_scaled, &l_scaled, &step_scaled}) {
      v->resize(n);
    }
  }
};

// Two doubles in one SSE2 / NEON register (GCC and Clang vector extension): the arithmetic
// below runs on two windows at once, with the scalar type for an odd last window.
using Double2 = double __attribute__((vector_size(16)));
using Mask2 = int64_t __attribute__((vector_size(16)));  // All ones where a comparison holds.
// Four floats in one register: the Newton steps on the characteristic polynomial scaled by the
// trace, four windows per division.
using Float4 = float __attribute__((vector_size(16)));
using Mask4 = int32_t __attribute__((vector_size(16)));

template <typename T>
T Broadcast(double v) {
  if constexpr (std::is_same_v<T, double>) {
    return v;
  } else if constexpr (std::is_same_v<T, float>) {
    return static_cast<float>(v);
  } else if constexpr (std::is_same_v<T, Double2>) {
    return T{v, v};
  } else {
    const float f = static_cast<float>(v);
    return T{f, f, f, f};
  }
}
template <typename T, typename Scalar>
T Load(const std::vector<Scalar>& v, size_t k) {
  T out;
  std::memcpy(&out, v.data() + k, sizeof(T));
  return out;
}
template <typename T, typename Scalar>
void Store(std::vector<Scalar>* v, size_t k, const T& value) {
  std::memcpy(v->data() + k, &value, sizeof(T));
}
inline double Select(bool mask, double a, double b) { return mask ? a : b; }
inline float Select(bool mask, float a, float b) { return mask ? a : b; }
inline Double2 Select(Mask2 mask, Double2 a, Double2 b) {
  return reinterpret_cast<Double2>((reinterpret_cast<Mask2>(a) & mask) |
                                   (reinterpret_cast<Mask2>(b) & ~mask));
}
inline Float4 Select(Mask4 mask, Float4 a, Float4 b) {
  return reinterpret_cast<Float4>((reinterpret_cast<Mask4>(a) & mask) |
                                  (reinterpret_cast<Mask4>(b) & ~mask));
}
inline double Sqrt(double v) { return std::sqrt(v); }
inline Double2 Sqrt(Double2 v) { return Double2{std::sqrt(v[0]), std::sqrt(v[1])}; }
// The magnitude of a with the sign of b.
inline double CopySign(double a, double b) { return std::copysign(a, b); }
inline Double2 CopySign(Double2 a, Double2 b) {
  const Mask2 sign = reinterpret_cast<Mask2>(Broadcast<Double2>(-0.0));
  return reinterpret_cast<Double2>((reinterpret_cast<Mask2>(a) & ~sign) |
                                   (reinterpret_cast<Mask2>(b) & sign));
}

// One Newton step towards the smallest root of f(l) = l^3 - trace l^2 + c1 l - c0 =
// -det(A - l I) from below, kept only when it moves up.
template <typename T>
T NewtonStep(T l, T trace, T c1, T c0) {
  const T f = ((l - trace) * l + c1) * l - c0;
  const T df = (Broadcast<T>(3) * l - Broadcast<T>(2) * trace) * l + c1;
  const T next = l - f / df;
  return Select((df > Broadcast<T>(0)) & (next > l), next, l);
}

// Covariance, characteristic polynomial and smallest eigenvalue of entry k (and k + 1 for
// Double2). The smallest eigenvalue comes from Newton's method on the characteristic polynomial
// started at 0: for a positive semi-definite matrix the polynomial is concave and increasing
// below its smallest root, so every iterate is a lower bound. Three steps reach it for nearly
// every window; `step` is the last step's length.
template <typename T>
void SmallestEigenvalue(WindowBatch* b, size_t k) {
  T m[10];
  for (int c = 0; c < 10; ++c) m[c] = Load<T>(b->sums[c], k);
  const T inv = Broadcast<T>(1) / m[0];
  const T mx = m[1] * inv, my = m[2] * inv, mz = m[3] * inv;
  const T b00 = m[4] * inv - mx * mx, b01 = m[5] * inv - mx * my;
  const T b02 = m[6] * inv - mx * mz, b11 = m[7] * inv - my * my;
  const T b12 = m[8] * inv - my * mz, b22 = m[9] * inv - mz * mz;
  const T m00 = b11 * b22 - b12 * b12, m01 = b02 * b12 - b01 * b22;
  const T m02 = b01 * b12 - b02 * b11;
  const T t = b00 + b11 + b22;
  const T q1 = m00 + b00 * b22 - b02 * b02 + b00 * b11 - b01 * b01;
  const T q0 = b00 * m00 + b01 * m01 + b02 * m02;
  Store(&b->a00, k, b00), Store(&b->a01, k, b01), Store(&b->a02, k, b02);
  Store(&b->a11, k, b11), Store(&b->a12, k, b12), Store(&b->a22, k, b22);
  Store(&b->trace, k, t), Store(&b->c1, k, q1), Store(&b->c0, k, q0);
  // The polynomial of A / trace: its roots are the eigenvalues over the trace, in [0, 1].
  const T inv_t = Broadcast<T>(1) / t;
  const T c1_scaled = q1 * inv_t * inv_t, c0_scaled = q0 * inv_t * inv_t * inv_t;
  if constexpr (std::is_same_v<T, double>) {
    b->c1_scaled[k] = static_cast<float>(c1_scaled);
    b->c0_scaled[k] = static_cast<float>(c0_scaled);
  } else {
    for (size_t lane = 0; lane < 2; ++lane) {
      b->c1_scaled[k + lane] = static_cast<float>(c1_scaled[lane]);
      b->c0_scaled[k + lane] = static_cast<float>(c0_scaled[lane]);
    }
  }
}

// Three Newton steps on the scaled polynomial of entry k (and the next three for Float4), in
// float: the smallest root is wanted to 1e-6 of the trace, and the scaled coefficients hold it
// to about 1e-7. `l` and `step` come back scaled by the trace.
template <typename T>
void NewtonSteps(WindowBatch* b, size_t k) {
  const T one = Broadcast<T>(1);
  const T c1 = Load<T>(b->c1_scaled, k), c0 = Load<T>(b->c0_scaled, k);
  const T l1 = NewtonStep(Broadcast<T>(0), one, c1, c0);
  const T l2 = NewtonStep(l1, one, c1, c0);
  const T l3 = NewtonStep(l2, one, c1, c0);
  Store(&b->l_scaled, k, l3);
  Store(&b->step_scaled, k, l3 - l2);
}

// The smallest eigenvalues in units of the covariance. The few windows Newton has not settled
// in three steps continue alone, stopping as soon as an iterate exceeds the curvature limit (a
// step of 1e-6 trace turns the normal by about step / eigenvalue gap: far below one colour
// step). Rejected windows get l = infinity.
void RefineEigenvalues(WindowBatch* b, size_t n, double max_curvature) {
  double* l = b->l.data();
  const double* trace = b->trace.data();
  const float* l_scaled = b->l_scaled.data();
  for (size_t k = 0; k < n; ++k) l[k] = l_scaled[k] * trace[k];
  for (size_t k = 0; k < n; ++k) {
    if (!(b->step_scaled[k] > 1e-6f)) continue;  // Settled: nearly all.
    const double limit = max_curvature * trace[k];
    for (int it = 0; it < 50 && l[k] <= limit; ++it) {
      const double next = NewtonStep(l[k], trace[k], b->c1[k], b->c0[k]);
      const bool converged = next - l[k] <= 1e-6 * trace[k];
      l[k] = next;
      if (converged) break;
    }
  }
  // An edge or a corner (smallest eigenvalue / trace > max_curvature), or no spread at all.
  const double inf = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < n; ++k) {
    const bool reject = (l[k] > max_curvature * trace[k]) | !(trace[k] > 1e-20);
    l[k] = reject ? inf : l[k];
  }
}

// Unit null vector of A - l I (the normal) of entry k (and k + 1), NaN for a rejected window
// (l infinite) or a line (no plane). Every cross product of two rows of A - l I is parallel to the
// null vector; their sum with signs aligned (no branch on which is longest) keeps it when one or
// two vanish.
template <typename T>
void NullVector(WindowBatch* b, size_t k) {
  const T l = Load<T>(b->l, k);
  const T a01 = Load<T>(b->a01, k), a02 = Load<T>(b->a02, k), a12 = Load<T>(b->a12, k);
  const T r0x = Load<T>(b->a00, k) - l, r0y = a01, r0z = a02;
  const T r1x = a01, r1y = Load<T>(b->a11, k) - l, r1z = a12;
  const T r2x = a02, r2y = a12, r2z = Load<T>(b->a22, k) - l;
  const T c01x = r0y * r1z - r0z * r1y, c01y = r0z * r1x - r0x * r1z, c01z = r0x * r1y - r0y * r1x;
  const T c02x = r0y * r2z - r0z * r2y, c02y = r0z * r2x - r0x * r2z, c02z = r0x * r2y - r0y * r2x;
  const T c12x = r1y * r2z - r1z * r2y, c12y = r1z * r2x - r1x * r2z, c12z = r1x * r2y - r1y * r2x;
  const T one = Broadcast<T>(1);
  const T s02 = CopySign(one, c01x * c02x + c01y * c02y + c01z * c02z);
  const T ux = c01x + s02 * c02x, uy = c01y + s02 * c02y, uz = c01z + s02 * c02z;
  const T s12 = CopySign(one, ux * c12x + uy * c12y + uz * c12z);
  const T vx = ux + s12 * c12x, vy = uy + s12 * c12y, vz = uz + s12 * c12z;
  const T norm2 = vx * vx + vy * vy + vz * vz;
  const T t = Load<T>(b->trace, k);
  const T valid_factor = Select((l < Broadcast<T>(std::numeric_limits<double>::infinity())) &
                                    (norm2 > Broadcast<T>(1e-30) * t * t * t * t),
                                one, Broadcast<T>(std::numeric_limits<double>::quiet_NaN()));
  const T inv = valid_factor / Sqrt(norm2);
  Store(&b->nx, k, vx * inv), Store(&b->ny, k, vy * inv), Store(&b->nz, k, vz * inv);
}

// Runs f<Double2> on pairs of entries and f<double> on an odd last one.
template <typename Pair, typename Single>
void ForEntries(size_t n, const Pair& pair, const Single& single) {
  size_t k = 0;
  for (; k + 1 < n; k += 2) pair(k);
  if (k < n) single(k);
}

}  // namespace

void GridNormals(int window, double max_curvature, WorkingCloud* cloud) {
  const int w = cloud->grid_w, h = cloud->grid_h;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud->normals.assign(cloud->size(), Eigen::Vector3f(nan, nan, nan));
  // Box sums over (2 window + 1)^2 cells, slid along the grid: per column the sum over the
  // window's rows, then per row a running sum of those column sums. Constant work per cell and
  // a working set of one grid row.
  // Column sums with window + 1 empty columns on each side, so that the running sum along a
  // row adds and drops a column at every cell without bounds checks.
  std::vector<Moments> padded(static_cast<size_t>(w) + 2 * (window + 1));
  Moments* column = padded.data() + window + 1;
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
    for (int x = 0; x < window; ++x) s += column[x];
    const int* row = &cloud->cell_point[static_cast<size_t>(y) * w];
    size_t count = 0;
    for (int x = 0; x < w; ++x) {
      s += column[x + window];
      s -= column[x - window - 1];
      if (row[x] < 0 || s.m[0] < 2.5) continue;  // At least 3 points.
      batch.point[count] = row[x];
      for (int k = 0; k < 10; ++k) batch.sums[k][count] = s.m[k];
      ++count;
    }
    ForEntries(
        count, [&](size_t k) { SmallestEigenvalue<Double2>(&batch, k); },
        [&](size_t k) { SmallestEigenvalue<double>(&batch, k); });
    for (size_t k = 0; k + 3 < count; k += 4) NewtonSteps<Float4>(&batch, k);
    for (size_t k = count - count % 4; k < count; ++k) NewtonSteps<float>(&batch, k);
    RefineEigenvalues(&batch, count, max_curvature);
    ForEntries(
        count, [&](size_t k) { NullVector<Double2>(&batch, k); },
        [&](size_t k) { NullVector<double>(&batch, k); });
    for (size_t k = 0; k < count; ++k) {
      const Eigen::Vector3f n(static_cast<float>(batch.nx[k]), static_cast<float>(batch.ny[k]),
                              static_cast<float>(batch.nz[k]));
      if (!n.allFinite()) continue;  // An edge, a corner or a line.
      const int i = batch.point[k];
      // Towards the viewpoint at the origin (a sign, not a branch: the sign is a coin toss).
      cloud->normals[i] = std::copysign(1.f, -n.dot(cloud->points[i])) * n;
    }
  }
}

}  // namespace sightline
