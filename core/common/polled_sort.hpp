// std::sort that polls the cancellation hook while it compares: sorts of millions of keys.
#pragma once

#include <algorithm>
#include <cstddef>

#include "common/limits.hpp"

namespace arg {

// Sorts [first, last) by `less` exactly as std::sort does (the same comparisons, so the same
// order), calling check_interrupt every 65,536 comparisons: sorting the 15 million half-edges of a
// 5-million-triangle mesh otherwise polls nothing for seconds. When stop says so, Interrupted
// leaves the range in an unspecified order, which nobody reads (the build is abandoned).
template <class It, class Less>
void polled_sort(It first, It last, Less less, const StopRequested& stop) {
  std::size_t comparisons = 0;
  std::sort(first, last, [&](const auto& a, const auto& b) {
    if ((++comparisons & 65535u) == 0) check_interrupt(stop);
    return less(a, b);
  });
}

}  // namespace arg
