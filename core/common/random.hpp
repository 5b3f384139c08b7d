// Portable seeded randomness: the same seed gives the same numbers on every platform.
#pragma once

#include <cstdint>
#include <random>

namespace arg {

// std::mt19937_64 is specified bit for bit by the standard, but the standard distributions
// are not, so the doubles are made here from the raw 64-bit outputs.
class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}

  std::uint64_t bits() { return engine_(); }
  // Uniform in [0, 1) with 53 random bits.
  double unit() { return static_cast<double>(engine_() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // Uniform in [-1, 1].
  double signed_unit() { return 2.0 * unit() - 1.0; }
  // Uniform integer in [0, n) for small n; the modulo bias is far below anything visible.
  int below(int n) { return static_cast<int>(engine_() % static_cast<std::uint64_t>(n)); }
  bool chance(double p) { return unit() < p; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace arg
