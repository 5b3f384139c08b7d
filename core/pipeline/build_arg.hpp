// The whole pipeline: mesh bytes or a mesh in memory to an Augmented Reeb Graph.
#pragma once

#include <string>
#include <string_view>

#include "common/build_options.hpp"
#include "common/limits.hpp"
#include "graph/arg_graph.hpp"
#include "io/read_mesh.hpp"
#include "mesh/mesh.hpp"

namespace arg {

// Milliseconds spent in each stage of one build.
struct BuildTimings {
  double read = 0, clean = 0, normalise = 0, mu = 0, reeb = 0, features = 0, serialise = 0;
  // The features stage's parts (they sum to `features`), where most of a build goes.
  double smoothing = 0, curvature = 0, nodes = 0, global = 0, spectrum = 0, views = 0;
};

struct BuildReport {
  ReadReport read;
  std::size_t welded_vertices = 0;
  std::size_t dropped_degenerate = 0;
  std::size_t dropped_duplicate = 0;
  std::size_t flipped_faces = 0;
  std::size_t boundary_edges = 0;
  std::size_t nonmanifold_edges = 0;
  std::size_t components = 0;        // of the surface measured (after stitching)
  std::size_t stitched_pairs = 0;    // rim vertices joined across tears (holes=fill)
  std::size_t bridged_pieces = 0;    // tubes joining pieces that holes cut apart (holes=fill)
  std::size_t set_aside_pieces = 0;  // small pieces of a torn surface left out (holes=fill)
  std::size_t filled_loops = 0;      // holes closed (holes=fill)
  bool proxy = false;                // mu and the graph were computed on the watertight proxy
  int smoothing_steps = 0;           // Taubin steps before curvature and views: 0, 10 or 80
  BuildTimings ms;
};

// Builds the ARG of a mesh already in memory (cleans a copy first).
ArgGraph build_arg(const Mesh& mesh, const BuildOptions& options = {},
                   const StopRequested& stop = {}, BuildReport* report = nullptr);

// Reads `mesh_bytes` (format detected), builds and serialises. `texture` may be empty. Throws
// LimitError over a cap of `limits`, memory included: refused when the estimate for the mesh's
// counts is over limits.max_build_bytes (pipeline/build_memory.hpp), stopped when the heap grows
// past it during the build (common/heap_usage.hpp).
std::string build_arg_bytes(std::string_view mesh_bytes, std::string_view texture,
                            const BuildOptions& options = {}, const Limits& limits = {},
                            const StopRequested& stop = {}, BuildReport* report = nullptr);

}  // namespace arg
