// Vertex positions of a fine mesh carried to the coarse copy collapse_short_edges made of it.
#pragma once

#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"

namespace arg {

// `coarse` with each vertex at the mean of `fine_V`'s rows over the fine vertices collapsed
// into it (`vertex_map[v]`, as collapse_short_edges gives it); a coarse vertex no fine vertex
// maps to keeps its place. With `fine_V` the fine surface smoothed, this stands for the copy
// smoothed as far, without smoothing it again. Throws std::invalid_argument when the map does
// not have a row of `fine_V` for each entry or names a vertex `coarse` lacks (a caller's bug).
Mesh restrict_vertex_positions(const Mesh& coarse, const std::vector<int>& vertex_map,
                               const Vertices& fine_V, const StopRequested& stop = {});

}  // namespace arg
