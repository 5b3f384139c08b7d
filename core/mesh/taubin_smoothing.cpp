// Umbrella-operator steps with alternating signs over the mesh's edge graph.
#include "mesh/taubin_smoothing.hpp"

#include <vector>

namespace arg {

Mesh taubin_smoothing(const Mesh& mesh, const MeshEdges& edges, int iterations, double lambda,
                      double mu) {
  Mesh out = mesh;
  const Eigen::Index n = mesh.V.rows();
  std::vector<int> degree(std::size_t(n), 0);
  for (int e = 0; e < edges.count(); ++e)
    ++degree[std::size_t(edges.v0[e])], ++degree[std::size_t(edges.v1[e])];
  Vertices sum(n, 3);
  for (int it = 0; it < 2 * iterations; ++it) {
    const double step = it % 2 == 0 ? lambda : mu;
    sum.setZero();
    for (int e = 0; e < edges.count(); ++e) {
      sum.row(edges.v0[e]) += out.V.row(edges.v1[e]);
      sum.row(edges.v1[e]) += out.V.row(edges.v0[e]);
    }
    for (Eigen::Index v = 0; v < n; ++v)
      if (degree[std::size_t(v)] > 0)
        out.V.row(v) += step * (sum.row(v) / degree[std::size_t(v)] - out.V.row(v));
  }
  return out;
}

}  // namespace arg
