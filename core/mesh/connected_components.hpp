// Connected components of a triangle mesh and the short links that join them.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/mesh_edges.hpp"

namespace arg {

// Component id per vertex (0 = the component with the largest area, then by decreasing area);
// faces sharing a vertex are connected. Returns the number of components.
int vertex_components(const Mesh& mesh, std::vector<int>& component);

// Area of each of `count` components (`component`: vertex_components' numbering, a face counted
// in its first corner's component).
std::vector<double> component_areas(const Mesh& mesh, const std::vector<int>& component,
                                    std::size_t count);

// For every component but the largest, the nearest (vertex of it, vertex of another component
// already linked) pair, so that the linked graph is connected. Deterministic.
std::vector<std::pair<int, int>> component_links(const Mesh& mesh,
                                                 const std::vector<int>& component, int components);

}  // namespace arg
