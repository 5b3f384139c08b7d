// Heap in use from glibc's mallinfo2, and the stop hook that bounds a build by it.
#include "common/heap_usage.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
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

namespace {

using Clock = std::chrono::steady_clock;

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch())
      .count();
}

// A reading of the heap and when it was taken.
struct HeapReading {
  std::size_t bytes = 0;
  std::int64_t taken_ns = 0;
};

// The process's readings. mallinfo2 reads every thread's arena, so one reading serves every
// build that runs at the time: builds on several threads (argtool ingest) share one schedule and
// the latest reading instead of each reading the same heap on its own.
class HeapReadings {
 public:
  static HeapReadings& instance() {
    static HeapReadings readings;
    return readings;
  }

  // A fresh reading, published to every hook, after which none is due for heap_check_wait(its
  // cost).
  HeapReading take() {
    const std::int64_t before = now_ns();
    const std::size_t bytes = heap_bytes_in_use();
    const std::int64_t after = now_ns();
    const HeapReading reading{bytes, after};
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (after > latest_.taken_ns) latest_ = reading;
    }
    latest_ns_.store(after, std::memory_order_release);
    const std::int64_t wait = heap_check_wait(std::chrono::nanoseconds(after - before)).count();
    next_due_ns_.store(after + wait, std::memory_order_relaxed);
    return reading;
  }

  // A fresh reading when one is due, or the latest if it is newer than `seen_ns`, or nothing
  // (taken_ns 0): the caller has already compared it.
  HeapReading poll(std::int64_t seen_ns) {
    const std::int64_t now = now_ns();
    std::int64_t due = next_due_ns_.load(std::memory_order_relaxed);
    // One thread takes a due reading; the others go on with the latest.
    if (now >= due &&
        next_due_ns_.compare_exchange_strong(due, INT64_MAX, std::memory_order_relaxed))
      return take();
    if (latest_ns_.load(std::memory_order_acquire) <= seen_ns) return {};
    std::lock_guard<std::mutex> lock(mutex_);
    return latest_;
  }

 private:
  std::mutex mutex_;
  HeapReading latest_;
  std::atomic<std::int64_t> latest_ns_{0};
  std::atomic<std::int64_t> next_due_ns_{0};
};

}  // namespace

StopRequested bounded_by_heap(StopRequested stop, std::size_t max_bytes) {
  if (max_bytes == 0 || !heap_tracking_available()) return stop;
  // mallinfo2 walks every free chunk: on a heap of millions of small blocks, or in a process
  // that has built for an hour, one reading takes milliseconds; taken at every poll it was 57%
  // of a 1,000,000-triangle build. So the hook compares with the process's latest reading and
  // a fresh one is taken only once heap_check_wait(what the last one cost) has passed.
  // The level at the start is always fresh: a reading from before it may hold memory freed
  // since (the previous build's peak) and would let this build pass the cap by as much.
  HeapReadings& readings = HeapReadings::instance();
  const HeapReading start = readings.take();
  // The newest reading this hook has compared, shared by the copies that worker threads poll.
  auto seen = std::make_shared<std::atomic<std::int64_t>>(start.taken_ns);
  return [stop = std::move(stop), start, max_bytes, seen, &readings] {
    if (stop && stop()) return true;
    const HeapReading now = readings.poll(seen->load(std::memory_order_relaxed));
    // Only readings taken since the start: an older one is another level of the heap.
    if (now.taken_ns <= start.taken_ns) return false;
    seen->store(now.taken_ns, std::memory_order_relaxed);
    if (now.bytes > start.bytes && now.bytes - start.bytes > max_bytes)
      throw MemoryLimitError(
          "the build has allocated " + std::to_string(megabytes(now.bytes - start.bytes)) +
          " MB, more than the build memory cap of " + std::to_string(megabytes(max_bytes)) + " MB");
    return false;
  };
}

}  // namespace arg
