// Per-triangle values of a mesh carried to the coarse copy collapse_short_edges made of it.
#pragma once

#include <vector>

#include "common/limits.hpp"
#include "mesh/mesh.hpp"

namespace arg {

// For each triangle of `coarse`, the mean over its three corners of the area-weighted mean of
// `fine_values` (one per triangle of `fine`) over the fine triangles around the fine vertices
// collapsed into that corner (`vertex_map[v]`, as collapse_short_edges gives it). A fine
// triangle counts at each of its corners, a third of its area each; a coarse vertex no fine
// triangle reached counts 0. A constant stays that constant, and each value lies within the
// range of the fine values it averages.
std::vector<double> restrict_face_values(const Mesh& fine, const Mesh& coarse,
                                         const std::vector<int>& vertex_map,
                                         const std::vector<double>& fine_values,
                                         const StopRequested& stop = {});

}  // namespace arg
