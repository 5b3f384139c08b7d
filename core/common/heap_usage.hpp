// The heap the process has allocated, and a stop hook that bounds its growth during a build.
#pragma once

#include <chrono>
#include <cstddef>

#include "common/limits.hpp"

namespace arg {

// True where heap_bytes_in_use() measures (glibc 2.33 and later, without a sanitizer's
// allocator in front of it); elsewhere it returns 0 and bounded_by_heap() bounds nothing.
bool heap_tracking_available();

// Bytes the allocator has handed out and not taken back, over every thread's arena, mmapped
// blocks included (glibc mallinfo2: uordblks + hblkhd). Counts what a build allocates through
// malloc, operator new and Eigen alike; the memory of another library's own mmap is not seen.
std::size_t heap_bytes_in_use();

// A hook that asks `stop` first, then compares the heap in use with its level when the hook was
// made: more than `max_bytes` above it throws MemoryLimitError ("... allocated, more than the build
// memory cap of ..."). Polled where `stop` is (poll_interrupt). The level at the start is a fresh
// reading; after it, the hook compares the process's latest reading, and a fresh one is taken
// (by whichever hook polls first) only once heap_check_wait(the last reading's cost) has passed:
// builds on several threads share the readings, and a build overshoots the cap by at most what
// the process allocates between two readings. max_bytes 0, or no tracking, returns `stop`.
StopRequested bounded_by_heap(StopRequested stop, std::size_t max_bytes);

// How long the hook waits after a reading of the heap that took `cost`: 20 times as long, so that
// at most a 21st of a build goes to measuring its heap, and never more than 50 ms.
std::chrono::nanoseconds heap_check_wait(std::chrono::nanoseconds cost);

// Whole megabytes (rounded up) of `bytes`, for messages.
std::size_t megabytes(std::size_t bytes);

}  // namespace arg
