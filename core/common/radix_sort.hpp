// A stable least-significant-digit radix sort of records by a 64-bit unsigned key, polling.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/limits.hpp"

namespace arg {

// Sorts `records` by key(record), ascending; records with equal keys keep their order. Eight
// passes of one byte each, a pass skipped where every key has the same byte there (the sign
// and exponent of doubles in a narrow range, say): linear time where std::sort's comparisons
// of millions of records are not. `scratch` is resized to match and left unspecified.
// check_interrupt is called every 4,096 records read or moved.
template <class T, class Key>
void radix_sort_by_key(std::vector<T>& records, Key key, std::vector<T>& scratch,
                       const StopRequested& stop) {
  const std::size_t n = records.size();
  if (n < 2) return;
  std::array<std::array<std::size_t, 256>, 8> count{};
  for (std::size_t i = 0; i < n; ++i) {
    poll_interrupt(i, stop);
    const std::uint64_t k = key(records[i]);
    for (int d = 0; d < 8; ++d) ++count[std::size_t(d)][(k >> (8 * d)) & 255u];
  }
  scratch.resize(n);
  for (int d = 0; d < 8; ++d) {
    std::array<std::size_t, 256>& at = count[std::size_t(d)];
    if (at[(key(records[0]) >> (8 * d)) & 255u] == n) continue;  // one digit for all
    std::size_t sum = 0;
    for (std::size_t& c : at) {
      const std::size_t here = c;
      c = sum;
      sum += here;
    }
    for (std::size_t i = 0; i < n; ++i) {
      poll_interrupt(i, stop);
      scratch[at[(key(records[i]) >> (8 * d)) & 255u]++] = records[i];
    }
    records.swap(scratch);
  }
}

}  // namespace arg
