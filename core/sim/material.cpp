#include "core/sim/material.h"

#include <algorithm>
#include <cmath>

#include "core/sim/random.h"

namespace sightline::sim {
namespace {

// Weight of a pattern of period `size_m` seen with pixels of 1 / inv_footprint metres: 1 when
// it spans at least four pixels, 0 below two.
inline float DetailWeight(float size_m, float inv_footprint) {
  return std::clamp(0.5f * size_m * inv_footprint - 1.0f, 0.0f, 1.0f);
}

inline float Smooth(float x) { return x * x * (3.0f - 2.0f * x); }

// floor() without a libm call (the x86-64 baseline has no SSE4.1 round instruction).
inline int32_t FastFloor(float x) {
  const int32_t i = static_cast<int32_t>(x);
  return i - (x < static_cast<float>(i));
}

// A cheap second hash of a cell hash.
inline uint32_t Rehash(uint32_t h) {
  h = (h ^ (h >> 16)) * 0x7FEB352Du;
  return h ^ (h >> 15);
}

// A 128 x 128 lattice of random values in [0, 1], computed at compile time: value noise reads
// it instead of hashing four corners per pixel.
constexpr int kLatticeSize = 128;
struct Lattice {
  float values[kLatticeSize * kLatticeSize];
};
constexpr Lattice MakeLattice() {
  Lattice lattice{};
  for (int j = 0; j < kLatticeSize; ++j) {
    for (int i = 0; i < kLatticeSize; ++i) {
      lattice.values[j * kLatticeSize + i] = HashUnit(HashCell(i, j, 0x1A77u));
    }
  }
  return lattice;
}
constexpr Lattice kLattice = MakeLattice();

// Value noise in [0, 1] at lattice coordinates (x, y); the seed shifts the lattice (period 128).
inline float ValueNoise(float x, float y, uint32_t seed) {
  constexpr uint32_t kMask = kLatticeSize - 1;
  const int32_t i = FastFloor(x), j = FastFloor(y);
  const float u = Smooth(x - static_cast<float>(i)), v = Smooth(y - static_cast<float>(j));
  const uint32_t i0 = (static_cast<uint32_t>(i) + seed) & kMask, i1 = (i0 + 1) & kMask;
  const uint32_t j0 = (static_cast<uint32_t>(j) + (seed >> 8)) & kMask, j1 = (j0 + 1) & kMask;
  const float* row0 = kLattice.values + j0 * kLatticeSize;
  const float* row1 = kLattice.values + j1 * kLatticeSize;
  const float top = row0[i0] + (row0[i1] - row0[i0]) * u;
  const float bottom = row1[i0] + (row1[i1] - row1[i0]) * u;
  return top + (bottom - top) * v;
}

// Random axis-aligned rectangles, at most one per unit cell of lattice coordinates (x, y).
// Returns true inside one and sets its random tone in [0, 1].
inline bool Blob(float x, float y, float density, uint32_t seed, float* tone) {
  const int32_t i = FastFloor(x), j = FastFloor(y);
  const uint32_t h = HashCell(i, j, seed);
  if (HashUnit(h) >= density) return false;
  const uint32_t h2 = Rehash(h);
  constexpr float k = 1.0f / 255.0f;
  const float x0 = 0.05f + 0.4f * k * static_cast<float>(h2 & 0xFF);
  const float y0 = 0.05f + 0.4f * k * static_cast<float>((h2 >> 8) & 0xFF);
  const float x1 = std::min(x0 + 0.2f + 0.5f * k * static_cast<float>((h2 >> 16) & 0xFF), 0.97f);
  const float y1 = std::min(y0 + 0.2f + 0.5f * k * static_cast<float>(h2 >> 24), 0.97f);
  const float lx = x - static_cast<float>(i), ly = y - static_cast<float>(j);
  if (lx < x0 || ly < y0 || lx > x1 || ly > y1) return false;
  *tone = k * static_cast<float>(h & 0xFF);
  return true;
}

// Blocky speckle in [-1, 1] at lattice coordinates (x, y).
inline float Speckle(float x, float y, uint32_t seed) {
  return 2.0f * HashUnit(HashCell(FastFloor(x), FastFloor(y), seed)) - 1.0f;
}

Eigen::Vector3f SpeckleAlbedo(const Material& m, float s, float t, float inv_fp) {
  const float cell = m.scale_m, inv_cell = 1.0f / cell;
  const float x = s * inv_cell, y = t * inv_cell;
  float shade = 0.88f + 0.24f * ValueNoise(0.25f * x, 0.25f * y, m.seed);
  Eigen::Vector3f albedo = m.color;
  float tone = 0;
  const float wb = DetailWeight(cell, inv_fp);
  if (wb > 0 && Blob(x, y, m.density, m.seed ^ 0xA5A5u, &tone)) {
    // Blobs range from the accent colour to a lighter tint of the base colour.
    const Eigen::Vector3f blob = tone < 0.6f ? Eigen::Vector3f(m.accent * (0.7f + 0.5f * tone))
                                             : Eigen::Vector3f(m.color * (1.15f + 0.2f * tone));
    albedo += wb * (blob - albedo);
  }
  // A second, smaller blob layer breaks the regularity of the first.
  const float ws = DetailWeight(0.37f * cell, inv_fp);
  if (ws > 0 && Blob(2.7f * x, 2.7f * y, 0.6f * m.density, m.seed ^ 0x3C3Cu, &tone)) {
    albedo *= 1.0f + ws * (tone < 0.5f ? -0.35f : 0.3f);
  }
  const float wf = DetailWeight(0.12f * cell, inv_fp);
  if (wf > 0) shade += 0.10f * wf * Speckle(8.3f * x, 8.3f * y, m.seed ^ 0x77u);
  return albedo * shade;
}

Eigen::Vector3f TilesAlbedo(const Material& m, float s, float t, float inv_fp) {
  const float size = m.scale_m, inv_size = 1.0f / size;
  const float x = s * inv_size, y = t * inv_size;
  const int32_t i = FastFloor(x), j = FastFloor(y);
  const float grout = std::min(0.012f * inv_size, 0.2f);
  const float wg = DetailWeight(0.04f, inv_fp);
  const float lx = x - static_cast<float>(i), ly = y - static_cast<float>(j);
  if (wg > 0 && (lx < grout || ly < grout)) {
    return m.color + wg * (m.accent - m.color);
  }
  const uint32_t h = HashCell(i, j, m.seed);
  // Per-tile shade and a gradient across the tile (cheaper than value noise, as irregular).
  const float gx = HashUnit(Rehash(h)) - 0.5f, gy = HashUnit(Rehash(h ^ 0x5555u)) - 0.5f;
  float shade = 0.9f + 0.2f * HashUnit(h) + 0.12f * (gx * (lx - 0.5f) + gy * (ly - 0.5f));
  float tone = 0;
  const float wb = DetailWeight(0.31f * size, inv_fp);
  if (wb > 0 && Blob(3.2f * x, 3.2f * y, 0.3f, m.seed ^ 0x5Au, &tone)) {
    shade *= 1.0f + wb * (tone < 0.5f ? -0.3f : 0.25f);
  }
  const float wf = DetailWeight(0.05f * size, inv_fp);
  if (wf > 0) shade += 0.08f * wf * Speckle(20.0f * x, 20.0f * y, m.seed ^ 0x1234u);
  return m.color * shade;
}

Eigen::Vector3f BrushedAlbedo(const Material& m, float s, float t, float inv_fp) {
  constexpr float kStripe = 0.002f;
  const uint32_t h = HashCell(FastFloor(t * (1.0f / kStripe)), 3, m.seed);
  float shade = 0.95f + 0.1f * DetailWeight(kStripe, inv_fp) * HashUnit(h);
  const float inv_cell = 1.0f / m.scale_m;
  shade +=
      0.06f * DetailWeight(m.scale_m, inv_fp) * Speckle(s * inv_cell, t * inv_cell, m.seed ^ 0x55u);
  shade *= 0.92f + 0.16f * ValueNoise(20.0f * s, 20.0f * t, m.seed ^ 0x66u);
  return m.color * shade;
}

Eigen::Vector3f ImageAlbedo(const Material& m, const TextureImage* image, float s, float t) {
  if (image == nullptr || image->bgr.empty()) return m.color;
  const cv::Mat& img = image->bgr;
  // Bilinear lookup, clamped at the border; texel centres at (i + 0.5) / size.
  const float u = (s - m.image_offset_m.x()) / m.image_size_m.x();
  const float v = 1.0f - (t - m.image_offset_m.y()) / m.image_size_m.y();
  const float x = std::clamp(u * img.cols - 0.5f, 0.0f, img.cols - 1.001f);
  const float y = std::clamp(v * img.rows - 0.5f, 0.0f, img.rows - 1.001f);
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const int x1 = std::min(x0 + 1, img.cols - 1), y1 = std::min(y0 + 1, img.rows - 1);
  const float ax = x - x0, ay = y - y0;
  const uint8_t* r0 = img.ptr<uint8_t>(y0);
  const uint8_t* r1 = img.ptr<uint8_t>(y1);
  Eigen::Vector3f out;
  for (int c = 0; c < 3; ++c) {
    const float top = r0[3 * x0 + c] + ax * (r0[3 * x1 + c] - r0[3 * x0 + c]);
    const float bottom = r1[3 * x0 + c] + ax * (r1[3 * x1 + c] - r1[3 * x0 + c]);
    out[2 - c] = (top + ay * (bottom - top)) * (1.0f / 255.0f);  // BGR -> RGB.
  }
  return out;
}

}  // namespace

const char* TextureKindName(TextureKind kind) {
  switch (kind) {
    case TextureKind::kPlain:
      return "plain";
    case TextureKind::kSpeckle:
      return "speckle";
    case TextureKind::kTiles:
      return "tiles";
    case TextureKind::kChecker:
      return "checker";
    case TextureKind::kBrushed:
      return "brushed";
    case TextureKind::kImage:
      return "image";
  }
  return "unknown";
}

Eigen::Vector3f EvaluateAlbedo(const Material& material, const TextureImage* image, float s,
                               float t, float pixels_per_m) {
  const float inv_fp = pixels_per_m;
  switch (material.texture) {
    case TextureKind::kPlain:
      return material.color;
    case TextureKind::kSpeckle:
      return SpeckleAlbedo(material, s, t, inv_fp);
    case TextureKind::kTiles:
      return TilesAlbedo(material, s, t, inv_fp);
    case TextureKind::kChecker: {
      const int32_t i = FastFloor(s / material.scale_m);
      const int32_t j = FastFloor(t / material.scale_m);
      const float w = DetailWeight(material.scale_m, inv_fp);
      const Eigen::Vector3f mean = 0.5f * (material.color + material.accent);
      const Eigen::Vector3f square = ((i + j) & 1) ? material.accent : material.color;
      return mean + w * (square - mean);
    }
    case TextureKind::kBrushed:
      return BrushedAlbedo(material, s, t, inv_fp);
    case TextureKind::kImage:
      return ImageAlbedo(material, image, s, t);
  }
  return material.color;
}

}  // namespace sightline::sim
