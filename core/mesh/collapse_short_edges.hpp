// Collapsing short edges, topology kept: slivers of marching, coarser copies for the spectrum.
#pragma once

#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"

namespace arg {

struct CollapseOptions {
  double min_length = 0;   // shorter edges are collapsed wherever allowed
  double flat_length = 0;  // shorter edges are collapsed where the surface around them is flat:
  double flat_cosine = 1;  // every triangle around within this cosine of their mean normal
};

// Collapses short edges (shortest first, ties by vertex index, so the result is deterministic)
// into their midpoints. An edge is only collapsed when the link condition holds, which keeps a
// closed manifold closed, manifold and of the same genus, and when no surrounding triangle
// would flip, turn by more than 60 degrees or lose its area. Only edges between two triangles
// collapse, so a boundary stays where it is. A triangle that survives keeps its colour (a
// collapse moves its corners, never makes a new triangle).
// `vertex_map`, when given, receives for each input vertex the output vertex it was collapsed
// into (itself renumbered if it survived), or -1 for a vertex on no triangle.
Mesh collapse_short_edges(const Mesh& mesh, const CollapseOptions& options,
                          const StopRequested& stop = {}, std::vector<int>* vertex_map = nullptr);

}  // namespace arg
