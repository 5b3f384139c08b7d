// How rough a surface is at the size of its edges: each vertex's offset from its neighbours.
#pragma once

#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

// Each vertex's distance from the mean of its neighbours along its normal (the area-weighted
// mean of its triangles' normals), over the mean length of its edges; 0 for a vertex on no
// edge or with no normal. On a smooth surface of curvature radius R sampled at edge h it is
// about h / (4 R); noise of deviation s along the normal adds about s / h.
std::vector<double> normal_offsets(const Mesh& mesh, const MeshEdges& edges,
                                   const StopRequested& stop = {});

}  // namespace arg
