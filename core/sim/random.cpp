#include "core/sim/random.h"

#include <cmath>

namespace sightline::sim {
namespace {

// The table of normal samples, drawn from a fixed seed so every stream sees the same table and
// only the read positions depend on the caller's seed. A constant built once (thread-safe static
// initialisation), so it is not shared mutable state.
const std::vector<float>& NormalTable(uint32_t size) {
  static const std::vector<float> table = [size] {
    std::vector<float> t(size);
    std::mt19937 engine(0x5167u);
    for (uint32_t i = 0; i < size; ++i) t[i] = static_cast<float>(Normal(engine));
    return t;
  }();
  return table;
}

}  // namespace

std::mt19937 MakeEngine(uint64_t seed) {
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32)};
  return std::mt19937(seq);
}

double Uniform(std::mt19937& engine, double lo, double hi) {
  // 53 random bits from two 32-bit draws: exact and identical on every platform.
  const uint64_t a = engine() >> 5, b = engine() >> 6;
  const double u =
      (static_cast<double>(a) * 67108864.0 + static_cast<double>(b)) * (1.0 / 9007199254740992.0);
  return lo + (hi - lo) * u;
}

double Normal(std::mt19937& engine) {
  const double u1 = 1.0 - Uniform(engine, 0, 1);  // (0, 1]
  const double u2 = Uniform(engine, 0, 1);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

GaussianStream::GaussianStream(uint64_t seed)
    : table_(&NormalTable(kTableSize)), state_(Mix64(seed) | 1u) {}

}  // namespace sightline::sim
