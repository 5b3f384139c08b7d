// Portable seeded randomness: the same seed gives the same numbers on every platform.
#pragma once

#include <cstdint>
#include <random>

namespace arg {

// std::mt19937_64 is fully specified; the standard distributions are not, so convert by hand.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return double(engine_() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  std::uint64_t next() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace arg
