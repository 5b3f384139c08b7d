// Options of an ARG build (resolution, kind of mu, sampling) and their short text form.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace arg {

enum class MuKind : std::uint8_t { Geodesic = 0, Height = 1, Centroid = 2 };

// Which surface mu and the Reeb graph are computed on: the cleaned mesh itself, or a closed
// manifold proxy of it (mesh/watertight_proxy.hpp); auto takes the proxy when the mesh is in
// pieces (its second largest component holds 1% of the area or more) or has non-manifold
// edges (more than 0.1% of its edges), not for holes alone.
enum class SurfaceKind : std::uint8_t { Auto = 0, Mesh = 1, Proxy = 2 };

// What happens to the holes of an open surface that is built on itself (not on a proxy):
// closed by a fan of triangles (mesh/fill_holes.hpp) or kept as they are.
enum class HoleKind : std::uint8_t { Keep = 0, Fill = 1 };

struct BuildOptions {
  int levels = 5;  // n: the finest level has 2^n intervals of mu; levels 0..n are kept
  MuKind mu = MuKind::Geodesic;
  // K, base points of the geodesic integral. 96 (builder 1.7; 128 before) is a quarter less of
  // mu, the largest part of a build, with every set's retrieval within .005 and the paper's
  // Figure 6 property held over every pair of the generated human's poses; 64 and 80 lose that
  // property (docs/BENCHMARKS.md, "Towards a faster build").
  int base_points = 96;
  SurfaceKind surface = SurfaceKind::Auto;
  int proxy_resolution = 48;  // grid cells along the longest side of the proxy's grid
  HoleKind holes = HoleKind::Fill;
  int threads = 1;  // worker threads for mu; never changes the result
};

// Each number's range: the text parser and the binary format's reader both hold values to it.
inline constexpr int kMinLevels = 1, kMaxLevels = 7;
inline constexpr int kMinBasePoints = 8, kMaxBasePoints = 4096;
inline constexpr int kMinProxyResolution = 16, kMaxProxyResolution = 256;
inline constexpr int kMaxThreads = 256;

// One key of the build options text. The parser finds keys in the same table as this list, so a
// key it accepts cannot be missing from it (tests/unit/test_reference.cpp holds
// docs/REFERENCE.md to it).
struct BuildOptionKey {
  std::string_view name;
  long lo = 0, hi = 0;  // a number's range
  // A choice's values, in the order of its enum; none for a number.
  std::vector<std::string_view> words;
};

// Every key parse_build_options accepts, in the order of format_build_options (threads last).
const std::vector<BuildOptionKey>& build_option_keys();

// Parses "levels=5 mu=geodesic base_points=96 surface=auto proxy_resolution=48 holes=fill
// threads=2" (any order, any subset; empty gives the defaults). Throws InputError naming the bad
// key or value.
BuildOptions parse_build_options(std::string_view text);

// The canonical text form of the options that change the result (threads is left out).
std::string format_build_options(const BuildOptions& options);

const char* mu_kind_name(MuKind kind);
const char* surface_kind_name(SurfaceKind kind);
const char* hole_kind_name(HoleKind kind);

}  // namespace arg
