// Vertex positions of a fine mesh carried to the coarse copy collapse_short_edges made of it.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

// `coarse` with each vertex at the mean of `fine_V`'s rows over the fine vertices collapsed
// into it (`vertex_map[v]`, as collapse_short_edges gives it); a coarse vertex no fine vertex
// maps to keeps its place. With `fine_V` the fine surface smoothed, this stands for the copy
// smoothed as far, without smoothing it again.
Mesh restrict_vertex_positions(const Mesh& coarse, const std::vector<int>& vertex_map,
                               const Vertices& fine_V);

}  // namespace arg
