// FNV-1a, a small stable 64-bit hash for digests and cache keys (not for security).
#pragma once

#include <cstdint>
#include <string_view>

namespace arg {

inline std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t h = 1469598103934665603ull) {
  for (char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace arg
