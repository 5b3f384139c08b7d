// A mesh with vertices and faces added after its own (what hole filling and bridging make).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace arg {

// `mesh` followed by `vertices` (numbered from mesh.V.rows() on) and `faces`; when the mesh
// carries colour, `colours` (one per added face) follow its own.
Mesh append_faces(const Mesh& mesh, const std::vector<Eigen::RowVector3d>& vertices,
                  const std::vector<Eigen::RowVector3i>& faces,
                  const std::vector<Eigen::RowVector3f>& colours);

}  // namespace arg
