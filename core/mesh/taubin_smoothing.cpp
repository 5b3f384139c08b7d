// Umbrella-operator steps with alternating signs over the mesh's edge graph.
#include "mesh/taubin_smoothing.hpp"

#include <vector>

namespace arg {

namespace {

// A vertex as two pairs of doubles (x, y) and (z, unused), the width of the baseline x86-64
// and ARM vector registers: a step does the same IEEE operations in each lane as three scalar
// sums would, in the same order, so the result is bit for bit that of a scalar loop
// (-ffp-contract=off keeps the multiply and the add apart) in fewer instructions.
using Pair = double __attribute__((vector_size(16)));
struct alignas(32) Lanes {
  Pair xy, zw;
};

}  // namespace

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
  // Each vertex's first kSlots neighbours in slots of a fixed width, the unused ones naming
  // vertex n, which stays at the origin: a pass then adds kSlots terms a vertex with no branch
  // on its degree (whose mispredicted loop exits cost more than the sums), and adding +0.0 to
  // a sum that started at +0.0 leaves it bit for bit as it was. Degrees above kSlots add the
  // rest from the compressed rows, in the same order.
  constexpr int kSlots = 8;
  std::vector<int> slot(std::size_t(n) * kSlots, int(n));
  std::vector<double> degree(static_cast<std::size_t>(n));
  for (Eigen::Index v = 0; v < n; ++v) {
    const int b = begin[std::size_t(v)], e = begin[std::size_t(v) + 1];
    degree[std::size_t(v)] = e - b;
    for (int k = b; k < e && k < b + kSlots; ++k)
      slot[std::size_t(v) * kSlots + std::size_t(k - b)] = neighbour[std::size_t(k)];
  }
  std::vector<Lanes> at(static_cast<std::size_t>(n) + 1), next(at.size());
  for (Eigen::Index v = 0; v <= n; ++v)
    at[std::size_t(v)] = next[std::size_t(v)] =
        v < n ? Lanes{Pair{out.V(v, 0), out.V(v, 1)}, Pair{out.V(v, 2), 0.0}}
              : Lanes{Pair{0.0, 0.0}, Pair{0.0, 0.0}};
  for (int it = 0; it < 2 * iterations; ++it) {
    const double step = it % 2 == 0 ? lambda : mu;
    for (Eigen::Index v = 0; v < n; ++v) {
      poll_interrupt(std::size_t(v), stop);
      const double d = degree[std::size_t(v)];
      const Lanes p = at[std::size_t(v)];
      if (d == 0) {
        next[std::size_t(v)] = p;
        continue;
      }
      const int* s = &slot[std::size_t(v) * kSlots];
      Pair xy = {0.0, 0.0}, zw = {0.0, 0.0};
      for (int k = 0; k < kSlots; ++k) {
        const Lanes& u = at[std::size_t(s[k])];
        xy += u.xy, zw += u.zw;
      }
      if (d > kSlots)
        for (int k = begin[std::size_t(v)] + kSlots; k < begin[std::size_t(v) + 1]; ++k) {
          const Lanes& u = at[std::size_t(neighbour[std::size_t(k)])];
          xy += u.xy, zw += u.zw;
        }
      next[std::size_t(v)] = Lanes{p.xy + step * (xy / d - p.xy), p.zw + step * (zw / d - p.zw)};
    }
    at.swap(next);
  }
  for (Eigen::Index v = 0; v < n; ++v)
    out.V.row(v) << at[std::size_t(v)].xy[0], at[std::size_t(v)].xy[1], at[std::size_t(v)].zw[0];
  return out;
}

}  // namespace arg
