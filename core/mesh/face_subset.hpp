// A mesh restricted to some of its faces, vertices kept as they are numbered.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

// The faces f with keep[f] != 0 (colours follow them), in their order; every vertex stays, so
// indices keep their meaning and clean_mesh drops those no kept face uses.
Mesh face_subset(const Mesh& mesh, const std::vector<char>& keep);

}  // namespace arg
