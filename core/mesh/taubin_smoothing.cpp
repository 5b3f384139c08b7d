// Umbrella-operator steps with alternating signs over the mesh's edge graph.
#include "mesh/taubin_smoothing.hpp"

#include <vector>

namespace arg {

Mesh taubin_smoothing(const Mesh& mesh, const MeshEdges& edges, int iterations, double lambda,
                      double mu, const StopRequested& stop) {
  Mesh out = mesh;
  const Eigen::Index n = mesh.V.rows();
  // Each vertex's neighbours in increasing order (compressed rows): a pass then reads its
  // neighbours and writes one row, instead of scattering every edge into two sums, and adds
  // them in the order the edge list (sorted by (v0, v1)) gave.
  std::vector<int> begin(std::size_t(n) + 1, 0);
  for (int e = 0; e < edges.count(); ++e)
    ++begin[std::size_t(edges.v0[e]) + 1], ++begin[std::size_t(edges.v1[e]) + 1];
  for (Eigen::Index v = 0; v < n; ++v) begin[std::size_t(v) + 1] += begin[std::size_t(v)];
  std::vector<int> neighbour(std::size_t(begin.back())), fill(begin.begin(), begin.end() - 1);
  for (int e = 0; e < edges.count(); ++e) {  // sorted edges: lower neighbours come first
    neighbour[std::size_t(fill[std::size_t(edges.v1[e])]++)] = edges.v0[e];
  }
  for (int e = 0; e < edges.count(); ++e)
    neighbour[std::size_t(fill[std::size_t(edges.v0[e])]++)] = edges.v1[e];
  Vertices next(n, 3);
  for (int it = 0; it < 2 * iterations; ++it) {
    const double step = it % 2 == 0 ? lambda : mu;
    for (Eigen::Index v = 0; v < n; ++v) {
      poll_interrupt(std::size_t(v), stop);
      const int b = begin[std::size_t(v)], e = begin[std::size_t(v) + 1];
      if (b == e) {
        next.row(v) = out.V.row(v);
        continue;
      }
      double x = 0, y = 0, z = 0;
      for (int k = b; k < e; ++k) {
        const int u = neighbour[std::size_t(k)];
        x += out.V(u, 0), y += out.V(u, 1), z += out.V(u, 2);
      }
      const double d = e - b;
      next(v, 0) = out.V(v, 0) + step * (x / d - out.V(v, 0));
      next(v, 1) = out.V(v, 1) + step * (y / d - out.V(v, 1));
      next(v, 2) = out.V(v, 2) + step * (z / d - out.V(v, 2));
    }
    out.V.swap(next);
  }
  return out;
}

}  // namespace arg
