// The function mu on mesh vertices that the Reeb graph slices: geodesic integral or simpler ones.
#pragma once

#include <vector>

#include "common/build_options.hpp"
#include "common/limits.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

// mu(v) = sum_i s_i g(v, b_i) over K base points b_i spread evenly over the surface (farthest
// point sampling), s_i the area of b_i's geodesic Voronoi cell, g the shortest-path distance on
// the Steiner-refined edge graph (Hilaga et al. 2001). Not normalised. `threads` only changes
// speed: per-base-point distances are summed in base-point order.
std::vector<double> geodesic_integral(const Mesh& mesh, const MeshEdges& edges, int base_points,
                                      int threads = 1, const StopRequested& stop = {});

// The longest graph edge geodesic_integral leaves without Steiner points on a surface of this
// area: twice the edge of an equilateral mesh of the same area and 4000 triangles.
double geodesic_graph_max_edge(double area);

// mu_N in [0, 1] of the chosen kind on a pose-normalised mesh (height = x, the first principal
// axis; centroid = distance to the origin, the centre of mass).
std::vector<double> normalised_mu(const Mesh& mesh, const MeshEdges& edges,
                                  const BuildOptions& options, const StopRequested& stop = {});

// (mu - min) / (max - min); all zeros when mu is constant.
void normalise_min_max(std::vector<double>& mu);

}  // namespace arg
