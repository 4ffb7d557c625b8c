#include "core/stereo/corner_response.h"

#include <algorithm>
#include <cmath>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SIGHTLINE_HAVE_AVX2_PATH 1
#endif

namespace sightline {

namespace {

#if defined(SIGHTLINE_HAVE_AVX2_PATH)
// The AVX2 loops run where the CPU has AVX2, unless SetCornerResponseAvx2(false).
bool& Avx2Wanted() {
  static bool wanted = true;
  return wanted;
}
bool UseAvx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has && Avx2Wanted();
}

// Products() eight pixels at a time (exact, as there).
__attribute__((target("avx2"))) int ProductsAvx2(const short* d, int count, float* xx, float* xy,
                                                 float* yy) {
  int x = 0;
  for (; x + 8 <= count; x += 8) {
    const __m256i v = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(d + 2 * x));
    const __m256 gx = _mm256_cvtepi32_ps(_mm256_srai_epi32(_mm256_slli_epi32(v, 16), 16));
    const __m256 gy = _mm256_cvtepi32_ps(_mm256_srai_epi32(v, 16));
    _mm256_storeu_ps(xx + x, _mm256_mul_ps(gx, gx));
    _mm256_storeu_ps(xy + x, _mm256_mul_ps(gx, gy));
    _mm256_storeu_ps(yy + x, _mm256_mul_ps(gy, gy));
  }
  return x;
}

// Adds `count` values of each of the three rows to the sums (eight at a time; the same
// additions as the scalar loop).
__attribute__((target("avx2"))) void AddRowsAvx2(const float* p, const float* pxy, const float* pyy,
                                                 size_t count, float* xx, float* xy, float* yy) {
  size_t x = 0;
  for (; x + 8 <= count; x += 8) {
    _mm256_storeu_ps(xx + x, _mm256_add_ps(_mm256_loadu_ps(xx + x), _mm256_loadu_ps(p + x)));
    _mm256_storeu_ps(xy + x, _mm256_add_ps(_mm256_loadu_ps(xy + x), _mm256_loadu_ps(pxy + x)));
    _mm256_storeu_ps(yy + x, _mm256_add_ps(_mm256_loadu_ps(yy + x), _mm256_loadu_ps(pyy + x)));
  }
  for (; x < count; ++x) {
    xx[x] += p[x];
    xy[x] += pxy[x];
    yy[x] += pyy[x];
  }
}

// The response of columns [0, w) of one row from the column sums, eight columns at a time with
// the operations of the four-column SSE loop below, in the same order (no fused multiply-add),
// so the values are identical. Returns the first column it did not write.
__attribute__((target("avx2"))) int ResponseRowAvx2(const float* pxx, const float* pxy,
                                                    const float* pyy, int w, int b, float scale,
                                                    float* out) {
  const __m256 half = _mm256_set1_ps(0.5f), scale8 = _mm256_set1_ps(scale);
  int x = 0;
  for (; x + 8 <= w; x += 8) {
    __m256 a = _mm256_loadu_ps(pxx + x), d = _mm256_loadu_ps(pxy + x), c = _mm256_loadu_ps(pyy + x);
    for (int k = 1; k < b; ++k) {
      a = _mm256_add_ps(a, _mm256_loadu_ps(pxx + x + k));
      d = _mm256_add_ps(d, _mm256_loadu_ps(pxy + x + k));
      c = _mm256_add_ps(c, _mm256_loadu_ps(pyy + x + k));
    }
    const __m256 half_diff = _mm256_mul_ps(half, _mm256_sub_ps(a, c));
    const __m256 root =
        _mm256_sqrt_ps(_mm256_add_ps(_mm256_mul_ps(half_diff, half_diff), _mm256_mul_ps(d, d)));
    _mm256_storeu_ps(
        out + x,
        _mm256_mul_ps(scale8, _mm256_sub_ps(_mm256_mul_ps(half, _mm256_add_ps(a, c)), root)));
  }
  return x;
}
#endif

// The derivative products (dx dx, dx dy, dy dy) of `count` pixels of one row of interleaved
// (dx, dy) shorts. Exact in float: a Scharr derivative of 8-bit pixels is below 2^12.
void Products(const short* d, int count, float* xx, float* xy, float* yy) {
  int x = 0;
#if defined(SIGHTLINE_HAVE_AVX2_PATH)
  if (UseAvx2()) x = ProductsAvx2(d, count, xx, xy, yy);
#endif
#if defined(__SSE2__)
  for (; x + 4 <= count; x += 4) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(d + 2 * x));
    const __m128 gx = _mm_cvtepi32_ps(_mm_srai_epi32(_mm_slli_epi32(v, 16), 16));
    const __m128 gy = _mm_cvtepi32_ps(_mm_srai_epi32(v, 16));
    _mm_storeu_ps(xx + x, _mm_mul_ps(gx, gx));
    _mm_storeu_ps(xy + x, _mm_mul_ps(gx, gy));
    _mm_storeu_ps(yy + x, _mm_mul_ps(gy, gy));
  }
#endif
  for (; x < count; ++x) {
    const float gx = d[2 * x], gy = d[2 * x + 1];
    xx[x] = gx * gx;
    xy[x] = gx * gy;
    yy[x] = gy * gy;
  }
}

// The rows of the response; kBlock > 0 fixes the block size at compile time (so the loops
// vectorise), 0 takes `block` at run time. Each derivative row's products are computed once
// and kept in a ring of `block` rows; the sums run in the same order as a direct sum over the
// block, so the result does not depend on the ring.
template <int kBlock>
void ResponseRows(const cv::Mat& derivatives, const cv::Rect& valid, const cv::Rect& region,
                  int block, float scale, cv::Mat* response) {
  const int b = kBlock > 0 ? kBlock : block;
  const int h = b / 2;
  const int w = valid.width, span = w + 2 * h;
  const size_t n = static_cast<size_t>(span);
#if defined(SIGHTLINE_HAVE_AVX2_PATH)
  const bool avx2 = UseAvx2();
#endif
  // Ring slot s holds one derivative row's products: xx at 3 s n, xy at (3 s + 1) n, yy after.
  std::vector<float> ring(3 * static_cast<size_t>(b) * n);
  // Products summed over the block's rows, per column.
  std::vector<float> xx(n), xy(n), yy(n);
  const auto slot = [&](int image_row) {
    return ring.data() + 3 * n * static_cast<size_t>((image_row - valid.y + h) % b);
  };
  const auto fill = [&](int image_row) {
    float* p = slot(image_row);
    Products(derivatives.ptr<short>(image_row) + 2 * (valid.x - h), span, p, p + n, p + 2 * n);
  };
  for (int r = valid.y - h; r < valid.y + h; ++r) fill(r);
  for (int y = valid.y; y < valid.y + valid.height; ++y) {
    fill(y + h);
    {
      const float* p = slot(y - h);
      std::copy(p, p + n, xx.begin());
      std::copy(p + n, p + 2 * n, xy.begin());
      std::copy(p + 2 * n, p + 3 * n, yy.begin());
    }
    for (int dy = -h + 1; dy <= h; ++dy) {
      const float* p = slot(y + dy);
      const float* pxy = p + n;
      const float* pyy = p + 2 * n;
#if defined(SIGHTLINE_HAVE_AVX2_PATH)
      if (avx2) {
        AddRowsAvx2(p, pxy, pyy, n, xx.data(), xy.data(), yy.data());
        continue;
      }
#endif
      for (size_t x = 0; x < n; ++x) {
        xx[x] += p[x];
        xy[x] += pxy[x];
        yy[x] += pyy[x];
      }
    }
    float* out = response->ptr<float>(y - region.y) + (valid.x - region.x);
    const float* pxx = xx.data();
    const float* pxy = xy.data();
    const float* pyy = yy.data();
    int x = 0;
#if defined(SIGHTLINE_HAVE_AVX2_PATH)
    if (kBlock > 0 && avx2) x = ResponseRowAvx2(pxx, pxy, pyy, w, b, scale, out);
#endif
#if defined(__SSE2__)
    if (kBlock > 0) {
      // Four columns at a time, the same operations in the same order as below.
      const __m128 half = _mm_set1_ps(0.5f), scale4 = _mm_set1_ps(scale);
      for (; x + 4 <= w; x += 4) {
        __m128 a = _mm_loadu_ps(pxx + x), d = _mm_loadu_ps(pxy + x), c = _mm_loadu_ps(pyy + x);
        for (int k = 1; k < b; ++k) {
          a = _mm_add_ps(a, _mm_loadu_ps(pxx + x + k));
          d = _mm_add_ps(d, _mm_loadu_ps(pxy + x + k));
          c = _mm_add_ps(c, _mm_loadu_ps(pyy + x + k));
        }
        const __m128 half_diff = _mm_mul_ps(half, _mm_sub_ps(a, c));
        const __m128 root =
            _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(half_diff, half_diff), _mm_mul_ps(d, d)));
        _mm_storeu_ps(out + x,
                      _mm_mul_ps(scale4, _mm_sub_ps(_mm_mul_ps(half, _mm_add_ps(a, c)), root)));
      }
    }
#endif
    for (; x < w; ++x) {
      float a = 0, c = 0, d = 0;
      for (int k = 0; k < b; ++k) {
        a += pxx[x + k];
        d += pxy[x + k];
        c += pyy[x + k];
      }
      const float half_diff = 0.5f * (a - c);
      out[x] = scale * (0.5f * (a + c) - std::sqrt(half_diff * half_diff + d * d));
    }
  }
}

}  // namespace

bool SetCornerResponseAvx2(bool enabled) {
#if defined(SIGHTLINE_HAVE_AVX2_PATH)
  Avx2Wanted() = enabled;
  return __builtin_cpu_supports("avx2");
#else
  (void)enabled;
  return false;
#endif
}

void MinEigenResponse(const cv::Mat& derivatives, const cv::Rect& region, int block_size,
                      cv::Mat* response) {
  CV_Assert(derivatives.type() == CV_16SC2 && block_size >= 1 && block_size % 2 == 1);
  response->create(region.size(), CV_32FC1);
  response->setTo(0);
  const int h = block_size / 2;
  // Pixels whose whole block lies inside the image.
  const cv::Rect valid =
      region & cv::Rect(h, h, derivatives.cols - 2 * h, derivatives.rows - 2 * h);
  if (valid.width <= 0 || valid.height <= 0) return;
  // cornerMinEigenVal scales a 3x3 Sobel derivative by 1 / (4 * block * 255); a Scharr
  // derivative of a ramp is 4 times a Sobel one.
  const float d_scale = 1.0f / (16.0f * static_cast<float>(block_size) * 255.0f);
  const float scale = d_scale * d_scale;
  switch (block_size) {
    case 3:
      ResponseRows<3>(derivatives, valid, region, 3, scale, response);
      break;
    case 5:
      ResponseRows<5>(derivatives, valid, region, 5, scale, response);
      break;
    default:
      ResponseRows<0>(derivatives, valid, region, block_size, scale, response);
  }
}

}  // namespace sightline
