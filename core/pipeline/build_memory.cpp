// The build's memory bound: a linear fit over measured peaks, with a margin.
#include "pipeline/build_memory.hpp"

#include <algorithm>
#include <string>

#include "common/errors.hpp"
#include "common/heap_usage.hpp"

namespace arg {

namespace {

// Fitted to the peaks of docs/BENCHMARKS.md ("Build memory": resident memory of `argtool build`
// above that of a tiny mesh) and rounded up. Closed meshes took 416-471 bytes a triangle from
// 30,000 to 2,000,000 triangles (V about T/2): 560 per triangle and 64 per vertex give 592,
// 1.26 times the most. levels=7 took 10% more than levels=5, a second thread 8 bytes a vertex.
constexpr double kFixedBytes = 32.0 * (1 << 20);
constexpr double kPerTriangle = 560;
constexpr double kPerTriangleLevel = 24;  // for each level above 5
constexpr double kPerVertex = 64;
constexpr double kPerThreadVertex = 32;  // a worker's distances and buckets, for each thread
// The proxy (surface=auto or proxy): its grid and its own surface, which has some resolution^2
// triangles. 305.ply took 31, 107 and 369 MB more at resolutions 48, 128 and 256, a plant's
// soup 175 MB at 128: with the terms above, whole builds by the proxy stay 1.6 to 2.5 times
// under the estimate.
constexpr double kProxyFixedBytes = 32.0 * (1 << 20);
constexpr double kPerProxyCellSquared = 14.0 * 1024;

}  // namespace

std::size_t estimate_build_bytes(std::size_t vertices, std::size_t triangles,
                                 const BuildOptions& options) {
  const double v = double(vertices), t = double(triangles);
  const double per_triangle = kPerTriangle + kPerTriangleLevel * std::max(0, options.levels - 5);
  double bytes = kFixedBytes + per_triangle * t + kPerVertex * v +
                 kPerThreadVertex * v * double(std::max(0, options.threads - 1));
  if (options.surface != SurfaceKind::Mesh) {
    const double r = double(options.proxy_resolution);
    bytes += kProxyFixedBytes + kPerProxyCellSquared * r * r;
  }
  // Doubles hold any count a reader accepts; clamp what no size_t can hold.
  return bytes >= 1.8e19 ? std::size_t(-1) : std::size_t(bytes);
}

void check_build_memory(std::size_t vertices, std::size_t triangles, const BuildOptions& options,
                        std::size_t max_bytes) {
  if (max_bytes == 0) return;
  const std::size_t need = estimate_build_bytes(vertices, triangles, options);
  if (need > max_bytes)
    throw MemoryLimitError(
        "a build of " + std::to_string(vertices) + " vertices and " + std::to_string(triangles) +
        " triangles needs an estimated " + std::to_string(megabytes(need)) +
        " MB, more than the build memory cap of " + std::to_string(megabytes(max_bytes)) + " MB");
}

}  // namespace arg
