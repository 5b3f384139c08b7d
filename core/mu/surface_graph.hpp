// The weighted graph on which geodesic distances are approximated by shortest paths.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

// CSR graph. Nodes 0 .. mesh_vertices-1 are the mesh vertices; later nodes are Steiner points
// inserted on long edges so that paths can cut across large triangles.
struct SurfaceGraph {
  int mesh_vertices = 0;
  std::vector<int> offset;  // size nodes + 1
  std::vector<int> target;
  std::vector<float> length;
  std::vector<Eigen::Vector3d> steiner;  // positions of nodes mesh_vertices onwards

  int nodes() const { return int(offset.size()) - 1; }
};

// `max_edge`: edges longer than this get Steiner points about max_edge apart (at most 8 each);
// inside a face, points on different sides are joined by straight segments. Components are
// joined to the largest one by their nearest vertex pair (see connected_components.hpp).
SurfaceGraph surface_graph(const Mesh& mesh, const MeshEdges& edges, double max_edge,
                           const StopRequested& stop = {});

}  // namespace arg
