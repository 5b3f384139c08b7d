// Part matching (paper section 5): candidate nodes pre-filtered by node similarity and
// topology, then ranked by the SIM of the sub-graphs below them.
#include <algorithm>

#include "common/errors.hpp"
#include "match/similarity.hpp"
#include "match/subgraph.hpp"

namespace arg {

namespace {

// Shape of a node's distributions, independent of its size: the cords and curvature
// histograms each rescaled to unit mass, compared by the sum of bin-wise minima; in [0, 1].
double node_shape_similarity(const ArgNode& m, const ArgNode& n) {
  auto compare = [](const float* x, const float* y, int bins, double mx, double my) {
    if (!(mx > 0) || !(my > 0)) return 0.0;
    double s = 0;
    for (int k = 0; k < bins; ++k) s += std::min(x[k] / mx, y[k] / my);
    return s;
  };
  return (compare(m.cords.data(), n.cords.data(), kCordBins, m.a, n.a) +
          compare(m.curv_mean.data(), n.curv_mean.data(), kCurvatureBins, m.a, n.a) +
          compare(m.curv_gauss.data(), n.curv_gauss.data(), kCurvatureBins, m.a, n.a)) /
         3.0;
}

// A part is attached to the rest of its model through its neighbours; parts attached
// very differently (an end vs a junction of several branches) are not compared.
bool topologically_consistent(const ArgNode& m, const ArgNode& n) {
  return std::max(m.adj_count, n.adj_count) - std::min(m.adj_count, n.adj_count) <= 1;
}

}  // namespace

std::vector<PartMatch> part_match(const ArgGraph& query, int level, int node,
                                  const ArgGraph& candidate, const Weights& weights,
                                  double threshold) {
  if (level < 0 || level > query.levels())
    throw InputError("part match: level " + std::to_string(level) + " not in [0, " +
                     std::to_string(query.levels()) + "]");
  const int count =
      int(query.level_begin[std::size_t(level) + 1] - query.level_begin[std::size_t(level)]);
  if (node < 0 || node >= count)
    throw InputError("part match: node " + std::to_string(node) + " not in [0, " +
                     std::to_string(count - 1) + "] at level " + std::to_string(level));
  const int root = int(query.level_begin[std::size_t(level)]) + node;
  const ArgNode& q = query.nodes[std::size_t(root)];
  const ArgGraph part = subgraph(query, root);
  std::vector<PartMatch> out;
  for (int r = std::max(0, level - 1); r <= std::min(candidate.levels(), level + 1); ++r) {
    for (std::uint32_t i = candidate.level_begin[std::size_t(r)];
         i < candidate.level_begin[std::size_t(r) + 1]; ++i) {
      const ArgNode& c = candidate.nodes[i];
      if (node_shape_similarity(q, c) < threshold || !topologically_consistent(q, c)) continue;
      double score = arg_similarity(part, subgraph(candidate, int(i)), weights);
      out.push_back({r, int(i - candidate.level_begin[std::size_t(r)]), score});
    }
  }
  std::sort(out.begin(), out.end(), [](const PartMatch& a, const PartMatch& b) {
    if (a.score != b.score) return a.score < b.score;
    return a.level != b.level ? a.level < b.level : a.node < b.node;
  });
  return out;
}

}  // namespace arg
