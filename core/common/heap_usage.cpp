// Heap in use from glibc's mallinfo2, and the stop hook that bounds a build by it.
#include "common/heap_usage.hpp"

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

StopRequested bounded_by_heap(StopRequested stop, std::size_t max_bytes) {
  if (max_bytes == 0 || !heap_tracking_available()) return stop;
  const std::size_t start = heap_bytes_in_use();
  return [stop = std::move(stop), start, max_bytes] {
    if (stop && stop()) return true;
    const std::size_t now = heap_bytes_in_use();
    if (now > start && now - start > max_bytes)
      throw MemoryLimitError("the build has allocated " + std::to_string(megabytes(now - start)) +
                             " MB, more than the build memory cap of " +
                             std::to_string(megabytes(max_bytes)) + " MB");
    return false;
  };
}

}  // namespace arg
