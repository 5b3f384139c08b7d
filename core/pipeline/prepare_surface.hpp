// The first stages every consumer of the method shares: clean, pose, and the surface mu runs on.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "common/build_options.hpp"
#include "common/limits.hpp"
#include "mesh/clean_mesh.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"
#include "mesh/normalize_pose.hpp"

namespace arg {

// Above this many vertices a mesh is built on a collapsed copy of about kCoarseTriangles
// triangles (PreparedSurface::coarse). Measured on the labelled sets (docs/BENCHMARKS.md, "A
// build on a collapsed copy"): at 30,000 triangles over 6,000 vertices every set's training
// scores stay or rise, held out within .005, robustness within .01, and a 30,000-50,000 vertex
// scan builds 1.76 times faster (shrec07's tenth 1.19 times).
constexpr int kCoarseAbove = 6000;
constexpr double kCoarseTriangles = 30000;

struct PreparedSurface {
  CleanReport clean;
  Pose pose;
  std::size_t components = 0;        // connected components of the cleaned (and joined) mesh
  double boundary_length = 0;        // of its boundary edges (before any was filled), posed units
  double area = 0;                   // of `posed`
  bool use_proxy = false;            // mu and the graph run on `proxy`
  std::size_t filled_loops = 0;      // holes closed by fill_holes (options.holes=fill)
  std::size_t stitched_pairs = 0;    // rim vertices joined across tears (holes=fill)
  std::size_t bridged_pieces = 0;    // tubes joining pieces cut apart by holes (holes=fill)
  std::size_t set_aside_pieces = 0;  // small pieces of a torn surface left out (holes=fill)
  Mesh posed;  // the cleaned mesh (holes filled), centred, aligned and scaled (apply_pose)
  MeshEdges posed_edges;      // its edges
  std::optional<Mesh> proxy;  // its watertight proxy, when options.surface chose one
  // Without a proxy, a mesh of more than kCoarseAbove vertices is built on a copy of `posed`
  // whose edges shorter than those of an equilateral mesh of kCoarseTriangles triangles of the
  // same area are collapsed (collapse_short_edges: topology and colours kept), so that a scan
  // costs about what a mesh of a few thousand vertices does.
  std::optional<Mesh> coarse;
  MeshEdges coarse_edges;          // its edges
  std::vector<int> coarse_vertex;  // for each vertex of `posed`, the vertex of `coarse` it went to

  // A boundary longer than 4 sqrt(area) (kFlagWideOpen): a sheet, or openings far larger
  // than holes in a scan (twenty holes of 2% of the size make about 2.5 sqrt(area); sheets
  // among the PSB soups make 28 to 340); its spectrum is not the closed shape's.
  bool wide_open() const { return boundary_length > 4.0 * std::sqrt(area); }

  // What mu, the Reeb graph, the node attributes and the views are computed on.
  const Mesh& surface() const { return proxy ? *proxy : coarse ? *coarse : posed; }
};

// Cleans `input`; with holes=fill, joins a manifold surface torn into open pieces (rims stitched
// across gaps under 1% of its size; a piece holding 90% of the area kept alone) and closes the
// holes of a manifold surface in one piece that is not wide open; normalises its pose and, for
// surface=proxy (or auto on a mesh in pieces or with non-manifold edges: build_options.hpp), makes
// its proxy in the same frame. Throws InputError for a mesh without area.
PreparedSurface prepare_surface(const Mesh& input, const BuildOptions& options,
                                const StopRequested& stop = {});

}  // namespace arg
