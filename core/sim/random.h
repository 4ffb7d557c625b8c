// Deterministic randomness for the simulator: seed mixing, integer hashes for procedural textures
// and a fast Gaussian stream for per-pixel sensor noise. No global state: every generator is
// built from an explicit seed, so the same seed gives the same bytes in any order of calls.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

namespace sightline::sim {

// SplitMix64 finaliser: a well-mixed 64-bit hash of x.
inline uint64_t Mix64(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// A seed for one purpose derived from a parent seed, e.g. DeriveSeed(seed, kNoiseStream, frame).
inline uint64_t DeriveSeed(uint64_t seed, uint64_t a, uint64_t b = 0, uint64_t c = 0) {
  return Mix64(Mix64(Mix64(seed ^ Mix64(a)) ^ b) ^ (c * 0xD6E8FEB86659FD93ull));
}

// A 32-bit hash of an integer lattice cell and a per-surface seed (procedural textures).
constexpr uint32_t HashCell(int32_t i, int32_t j, uint32_t seed) {
  uint32_t h = seed * 0x9E3779B1u ^ static_cast<uint32_t>(i) * 0x85EBCA77u ^
               static_cast<uint32_t>(j) * 0xC2B2AE3Du;
  h ^= h >> 15;
  h *= 0x2C1B3C6Du;
  h ^= h >> 12;
  h *= 0x297A2D39u;
  h ^= h >> 15;
  return h;
}

// The hash mapped to [0, 1).
constexpr float HashUnit(uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

// A std::mt19937 seeded from a 64-bit seed (both halves used).
std::mt19937 MakeEngine(uint64_t seed);

// Uniform in [lo, hi) from an engine, portable across standard libraries (unlike
// std::uniform_real_distribution, whose algorithm is unspecified).
double Uniform(std::mt19937& engine, double lo, double hi);
// Standard normal from an engine (Box-Muller on two portable uniforms).
double Normal(std::mt19937& engine);

// Per-pixel Gaussian noise, fast enough for 10^6 samples per frame: a table of 2^16 standard
// normal samples drawn once from std::mt19937, read at positions picked by a xorshift stream
// seeded per frame. Not for statistics on more than ~10^5 samples, but ample for sensor noise.
//
//   GaussianStream noise(DeriveSeed(seed, kDepthNoise, frame));
//   float n = noise.Next();  // ~N(0, 1)
class GaussianStream {
 public:
  explicit GaussianStream(uint64_t seed);

  // Four ~N(0, 1) samples from one step of the generator (16 index bits each).
  void Next4(float* out) {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 7;
    state_ ^= state_ << 17;
    const std::vector<float>& t = *table_;
    out[0] = t[state_ & 0xFFFF];
    out[1] = t[(state_ >> 16) & 0xFFFF];
    out[2] = t[(state_ >> 32) & 0xFFFF];
    out[3] = t[(state_ >> 48) & 0xFFFF];
  }

  // The next ~N(0, 1) sample.
  float Next() {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 7;
    state_ ^= state_ << 17;
    return (*table_)[(state_ >> 24) & (kTableSize - 1)];
  }

 private:
  static constexpr uint32_t kTableSize = 1u << 16;
  const std::vector<float>* table_;  // The process-wide constant table (never mutated).
  uint64_t state_;
};

}  // namespace sightline::sim
