// The memory a build may reach, from the mesh's counts and the build options, and its cap.
#pragma once

#include <cstddef>

#include "common/build_options.hpp"

namespace arg {

// Bytes a build of a mesh of `vertices` and `triangles` may allocate at its peak, above what was
// in use when it started (input bytes included): a bound fitted over measured peaks with a
// margin (docs/BENCHMARKS.md, "Build memory"). Non-decreasing in each count, in threads, in
// levels and proxy_resolution; surface=auto counts the proxy, which it may take.
std::size_t estimate_build_bytes(std::size_t vertices, std::size_t triangles,
                                 const BuildOptions& options);

// Throws MemoryLimitError naming the estimate, the counts and the cap when the estimate is over
// `max_bytes`; 0 means no cap.
void check_build_memory(std::size_t vertices, std::size_t triangles, const BuildOptions& options,
                        std::size_t max_bytes);

}  // namespace arg
