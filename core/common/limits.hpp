// Caps on untrusted input and the cancellation hook that long loops poll.
#pragma once

#include <cstddef>
#include <functional>

namespace arg {

// Caps applied while reading untrusted input and building from it; exceeding one throws
// LimitError.
struct Limits {
  std::size_t max_input_bytes = std::size_t(512) << 20;
  std::size_t max_vertices = 4'000'000;
  std::size_t max_triangles = 8'000'000;
  std::size_t max_image_pixels = std::size_t(64) << 20;
  // Memory one build may take (pipeline/build_memory.hpp refuses by estimate, then
  // common/heap_usage.hpp stops it by its allocations); 0 means no cap.
  std::size_t max_build_bytes = std::size_t(1) << 30;
};

// Polled from long loops; returns true when the work should stop (the core then throws
// Interrupted). Empty means never stop.
using StopRequested = std::function<bool()>;

// Throws Interrupted when stop says so; cheap enough to call every few thousand iterations.
void check_interrupt(const StopRequested& stop);

// Calls check_interrupt on every 4096th value of a loop's counter: a loop over the faces or
// vertices of a mesh of millions polls every millisecond or so, at no cost worth measuring.
inline void poll_interrupt(std::size_t i, const StopRequested& stop) {
  if ((i & 4095u) == 0) check_interrupt(stop);
}

}  // namespace arg
