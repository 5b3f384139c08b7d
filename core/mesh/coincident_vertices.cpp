// Exact-position grouping of vertices, ordered by first occurrence (deterministic).
#include "mesh/coincident_vertices.hpp"

#include <array>
#include <map>

namespace arg {

std::vector<int> first_at_same_position(const Mesh& mesh) {
  std::map<std::array<double, 3>, int> first;
  std::vector<int> out(std::size_t(mesh.V.rows()));
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    out[std::size_t(v)] =
        first.emplace(std::array<double, 3>{mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2)}, int(v))
            .first->second;
  return out;
}

}  // namespace arg
