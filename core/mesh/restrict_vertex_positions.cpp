// Means of a fine mesh's vertex positions over the vertices each coarse vertex gathered.
#include "mesh/restrict_vertex_positions.hpp"

#include <stdexcept>

namespace arg {

Mesh restrict_vertex_positions(const Mesh& coarse, const std::vector<int>& vertex_map,
                               const Vertices& fine_V, const StopRequested& stop) {
  if (vertex_map.size() != std::size_t(fine_V.rows()))
    throw std::invalid_argument("restrict_vertex_positions: a map entry per fine vertex");
  Mesh out = coarse;
  out.V.setZero();
  std::vector<int> count(std::size_t(coarse.V.rows()), 0);
  for (std::size_t v = 0; v < vertex_map.size(); ++v) {
    poll_interrupt(v, stop);
    const int c = vertex_map[v];
    if (c < 0) continue;
    if (c >= coarse.V.rows())
      throw std::invalid_argument("restrict_vertex_positions: a map entry past the copy");
    out.V.row(c) += fine_V.row(Eigen::Index(v));
    ++count[std::size_t(c)];
  }
  for (Eigen::Index c = 0; c < out.V.rows(); ++c) {
    if (count[std::size_t(c)] > 0)
      out.V.row(c) /= double(count[std::size_t(c)]);
    else
      out.V.row(c) = coarse.V.row(c);
  }
  return out;
}

}  // namespace arg
