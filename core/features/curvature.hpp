// Discrete mean and Gaussian curvature (paper section 4.4), per vertex and per triangle.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

struct TriangleCurvature {
  std::vector<double> mean;  // per triangle: average of its corners' values
  std::vector<double> gaussian;
};

// Mean curvature at a vertex: dihedral angles of the edges around it, each weighted by the
// edge length, over the vertex's barycentric area (a third of the faces around it):
// H = sum |e| beta_e / (4 A). Gaussian curvature: angle defect over the same area
// (2 pi - sum of angles, or pi - sum on the boundary). Convex = positive.
TriangleCurvature triangle_curvature(const Mesh& mesh, const MeshEdges& edges,
                                     const StopRequested& stop = {});

}  // namespace arg
