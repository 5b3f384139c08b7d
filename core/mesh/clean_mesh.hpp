// Cleaning raw meshes: welding, dropping degenerate and duplicate faces, consistent orientation.
#pragma once

#include <cstddef>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

struct CleanReport {
  std::size_t welded_vertices = 0;     // vertices merged into an earlier copy
  std::size_t unused_vertices = 0;     // vertices no face referenced
  std::size_t dropped_degenerate = 0;  // faces with a repeated corner or zero area
  std::size_t dropped_duplicate = 0;   // faces with the same corners as an earlier face
  std::size_t flipped_faces = 0;       // faces turned to agree with their neighbours
  std::size_t boundary_edges = 0;      // edges with one face: the mesh is open
  std::size_t nonmanifold_edges = 0;   // edges with three faces or more
};

// Returns the cleaned mesh (colours follow their faces). Coordinates must be finite; throws
// InputError on NaN/Inf and when nothing with positive area is left. Orientation is made
// consistent across manifold edges, then each closed part is turned to enclose positive volume.
// `edges`, when given, receives the returned mesh's edge table, as mesh_edges would build it
// (the table cleaning needs anyway, its corners renumbered where a face was turned).
Mesh clean_mesh(const Mesh& mesh, CleanReport* report = nullptr, const StopRequested& stop = {},
                MeshEdges* edges = nullptr);

}  // namespace arg
