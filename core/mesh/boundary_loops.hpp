// The boundary loops of a manifold mesh, walked the way their faces run along them.
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

struct BoundaryLoop {
  // vertices[i] -> vertices[i + 1] (cyclically) is a boundary edge as faces[i] runs along it.
  std::vector<int> vertices;
  std::vector<int> faces;
};

struct BoundaryLoops {
  std::vector<BoundaryLoop> loops;  // simple cycles of three edges or more
  std::size_t skipped = 0;          // loops that pass a vertex twice (or break off): left out
};

// Walks the edges with one face into loops, in the order of their first edge in `edges`.
// A loop that passes a vertex twice (two holes touching at a corner, a non-manifold rim) is
// counted in `skipped` and left out. Deterministic.
BoundaryLoops boundary_loops(const Mesh& mesh, const MeshEdges& edges);

}  // namespace arg
