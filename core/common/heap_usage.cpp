// Heap in use from glibc's mallinfo2, and the stop hook that bounds a build by it.
#include "common/heap_usage.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include "common/errors.hpp"

#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33)) && \
    !defined(ARG_SANITIZED)
#include <malloc.h>
#define ARG_HEAP_TRACKING 1
#else
#define ARG_HEAP_TRACKING 0
#endif

namespace arg {

bool heap_tracking_available() {
  return ARG_HEAP_TRACKING != 0;
}

std::size_t heap_bytes_in_use() {
#if ARG_HEAP_TRACKING
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
#else
  return 0;
#endif
}

std::size_t megabytes(std::size_t bytes) {
  return (bytes + (std::size_t(1) << 20) - 1) >> 20;
}

std::chrono::nanoseconds heap_check_wait(std::chrono::nanoseconds cost) {
  return std::min<std::chrono::nanoseconds>(20 * cost, std::chrono::milliseconds(50));
}

StopRequested bounded_by_heap(StopRequested stop, std::size_t max_bytes) {
  if (max_bytes == 0 || !heap_tracking_available()) return stop;
  using Clock = std::chrono::steady_clock;
  const std::size_t start = heap_bytes_in_use();
  // mallinfo2 walks every free chunk: on a heap of millions of small blocks one reading takes
  // milliseconds, and taken at every poll it was 57% of a 1,000,000-triangle build. So a
  // reading waits heap_check_wait(what the last one cost) after it. Shared by the copies of
  // the hook that worker threads poll, hence atomic.
  auto next = std::make_shared<std::atomic<std::int64_t>>(0);
  return [stop = std::move(stop), start, max_bytes, next] {
    if (stop && stop()) return true;
    const auto since_epoch = [] {
      return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch());
    };
    const std::chrono::nanoseconds before = since_epoch();
    if (before.count() < next->load(std::memory_order_relaxed)) return false;
    const std::size_t now = heap_bytes_in_use();
    const std::chrono::nanoseconds after = since_epoch();
    next->store((after + heap_check_wait(after - before)).count(), std::memory_order_relaxed);
    if (now > start && now - start > max_bytes)
      throw MemoryLimitError("the build has allocated " + std::to_string(megabytes(now - start)) +
                             " MB, more than the build memory cap of " +
                             std::to_string(megabytes(max_bytes)) + " MB");
    return false;
  };
}

}  // namespace arg
