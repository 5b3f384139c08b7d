// The surface a Reeb graph node covers, cut out of its model as a mesh of its own.
#pragma once

#include "mesh/mesh.hpp"
#include "pipeline/node_positions.hpp"

namespace arg {

// The node of `level` that owns triangle `face`'s middle (mu at the mean of its corners): one
// node per triangle, as a 3D view colours a node's surface. -1 when face or level is out of
// range.
int face_node(const NodePositions& positions, int level, int face);

// The triangles of positions.mesh whose middle node `node` of `level` owns (face_node), with
// only the vertices they use, renumbered in their first use's order; colours follow the faces.
// The cut runs along triangle edges, so the region is open where it met its neighbours.
// Throws InputError when level or node is out of range or the node owns no triangle's middle.
Mesh node_region(const NodePositions& positions, int level, int node);

}  // namespace arg
