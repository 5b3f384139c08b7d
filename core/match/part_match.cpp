// Part matching (paper section 5): candidate nodes pre-filtered by node similarity and
// topology, then ranked by the SIM of the sub-graphs below them.
#include <algorithm>

#include "common/errors.hpp"
#include "match/mpair.hpp"
#include "match/node_similarity.hpp"
#include "match/similarity.hpp"
#include "match/subgraph.hpp"

namespace arg {

namespace {

// Step 4 of the paper's scheme: sim(m, n) with the nodes' own attributes (so relative size
// counts: a handle is not a cup's body), over the larger of the two self-similarities; in [0, 1].
double node_similarity(const ArgNode& m, const ArgNode& n, const Weights& w) {
  const double self = std::max(node_self_sim(m, w), node_self_sim(n, w));
  // The self-sims come from node areas, the sims from histogram bins that sum to the areas only
  // up to float rounding: clamp.
  return self > 0 ? std::clamp(node_sim(m, n, w) / self, 0.0, 1.0) : 0.0;
}

// A part is attached to the rest of its model through its neighbours; parts attached
// very differently (an end vs a junction of several branches) are not compared.
bool topologically_consistent(const ArgNode& m, const ArgNode& n) {
  return std::max(m.adj_count, n.adj_count) - std::min(m.adj_count, n.adj_count) <= 1;
}

}  // namespace

std::vector<PartMatch> part_match(const ArgGraph& query, int level, int node,
                                  const ArgGraph& candidate, const Weights& weights,
                                  double threshold, const StopRequested& stop) {
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
  Weights w = weights;  // colour only when both models have some, as in arg_similarity
  if (!(query.summary.has_colour && candidate.summary.has_colour)) w.lambda_4 = 0;
  std::vector<PartMatch> out;
  for (int r = std::max(0, level - 1); r <= std::min(candidate.levels(), level + 1); ++r) {
    for (std::uint32_t i = candidate.level_begin[std::size_t(r)];
         i < candidate.level_begin[std::size_t(r) + 1]; ++i) {
      check_interrupt(stop);
      const ArgNode& c = candidate.nodes[i];
      const double similarity = node_similarity(q, c, w);
      if (similarity < threshold || !topologically_consistent(q, c)) continue;
      // The parts' sub-graphs decide (step 6), with the nodes' own similarity as a tie-breaking
      // half so that of two parts shaped alike the one of the right size ranks first.
      const double score =
          0.5 * (arg_similarity(part, subgraph(candidate, int(i)), weights) + (1.0 - similarity));
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
