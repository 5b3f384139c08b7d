// Stitching a surface torn into pieces: rim vertices of different pieces that face each other
// across a narrow gap are moved onto one point, so that welding joins the pieces again.
#pragma once

#include <cstddef>
#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

// Pairs every boundary vertex of `mesh` with the nearest boundary vertex of another component
// (`component`: vertex_components' numbering) when that one lies within `tolerance` and chooses
// it back (mutual nearest), and moves both to their midpoint; a rim vertex left without a partner
// then moves onto the nearest such midpoint across the gap (so no slit stays between two joined
// points). Returns the mesh with the moved
// vertices (faces untouched): clean_mesh then welds each pair into one vertex and drops faces
// that collapsed. A scan torn along a cut, or a model cut into parts that still touch, becomes
// one surface again; parts that merely come near each other inside a soup are left alone
// unless both have an open rim there. `pairs` (optional) receives the number of pairs moved.
// Deterministic (ties go to the lower vertex index).
// Polls `stop` as it goes.
Mesh stitch_pieces(const Mesh& mesh, const MeshEdges& edges, const std::vector<int>& component,
                   double tolerance, std::size_t* pairs = nullptr, const StopRequested& stop = {});

// The mesh without the faces around its non-manifold edges (three faces or more): where a
// stitch pinched a few rims together, a small hole (for fill_holes) instead of a fin.
Mesh without_nonmanifold_faces(const Mesh& mesh, const MeshEdges& edges);

}  // namespace arg
