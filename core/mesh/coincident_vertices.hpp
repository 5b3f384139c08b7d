// Vertices at exactly one position: the unwelded corners of a soup's triangles.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

// For every vertex, the first vertex at exactly its position (itself if none comes before it):
// the corners of a soup's triangles that meet at one point of the surface without sharing an
// index. Exact: clean_mesh's weld (mesh/clean_mesh.hpp) also joins corners a rounding apart.
std::vector<int> first_at_same_position(const Mesh& mesh);

}  // namespace arg
