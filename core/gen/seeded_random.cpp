// A seeded random stream whose doubles are the same on every platform.
#include "common/strict_fp.hpp"  // first: it sets how arithmetic is compiled

#include "gen/seeded_random.hpp"

namespace arg::gen {

std::uint64_t mix_seed(std::string_view name, std::uint64_t number) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : name) h = (h ^ c) * 1099511628211ULL;
  std::uint64_t z = h ^ (number + 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace arg::gen
