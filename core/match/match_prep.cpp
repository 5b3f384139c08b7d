// A graph's part of matching, worked out once: packed keys with their branches, parents of
// neighbours, children in halves, sim keys, where intervals start, self sims and each level's
// order.
#include "match/match_prep.hpp"

#include <algorithm>
#include <utility>

#include "match/child_halves.hpp"
#include "match/mpair.hpp"

namespace arg {

const MatchPrep::Sums* MatchPrep::sums(bool colour_counts) const {
  if (!colour_counts) return &plain;
  return coloured.self.size() == plain.self.size() ? &coloured : nullptr;
}

void prepare_nodes(const ArgGraph& g, std::vector<std::array<int, 2>>& only,
                   std::vector<MatchKey>& keys) {
  // One pass: what it reads lies in the first 64 bytes of a node's record.
  only.resize(g.nodes.size());
  keys.resize(g.nodes.size());
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const ArgNode& n = g.nodes[i];
    keys[i] = {n.parent, n.interval, n.a, n.l, n.r, n.theta, n.phi};
    const std::uint32_t* adj = g.adjacency.data() + n.adj_begin;
    int found[2] = {-1, -1}, count[2] = {0, 0};
    for (std::uint32_t k = 0; k < n.adj_count; ++k) {
      const int side = adj[k] > i ? 1 : 0;  // nodes of a level are sorted by interval
      found[side] = int(adj[k]), ++count[side];
    }
    for (int side = 0; side < 2; ++side)
      only[i][std::size_t(side)] = count[side] == 1 ? found[side] : -1;
  }
}

int prepare_branches(const std::vector<std::array<int, 2>>& only, std::vector<MatchKey>& keys) {
  int count = 0;
  for (std::size_t i = 0; i < only.size(); ++i) {
    // The neighbour below lies in a lower interval of the level, so at a lower index: its
    // branch is known.
    const int below = only[i][0];
    const bool joins = below >= 0 && below < int(i) && only[std::size_t(below)][1] == int(i);
    keys[i].branch = joins ? keys[std::size_t(below)].branch : count++;
  }
  return count;
}

void prepare_neighbour_parents(const ArgGraph& g, MatchPrep& out) {
  const std::size_t n = g.nodes.size();
  out.parent_begin.resize(n + 1);
  out.parent_split.resize(n);
  out.parents.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const ArgNode& node = g.nodes[i];
    const std::uint32_t* adj = g.adjacency.data() + node.adj_begin;
    out.parent_begin[i] = std::uint32_t(out.parents.size());
    for (int side = 0; side < 2; ++side) {
      if (side == 1) out.parent_split[i] = std::uint32_t(out.parents.size());
      const std::size_t first = out.parents.size();
      for (std::uint32_t k = 0; k < node.adj_count; ++k) {
        if ((adj[k] > i ? 1 : 0) != side) continue;  // nodes of a level are sorted by interval
        const int p = g.nodes[adj[k]].parent;
        if (p < 0) continue;
        if (std::find(out.parents.begin() + std::ptrdiff_t(first), out.parents.end(), p) ==
            out.parents.end())
          out.parents.push_back(p);
      }
    }
  }
  out.parent_begin[n] = std::uint32_t(out.parents.size());
}

void prepare_interval_begin(const ArgGraph& g, int r, int* out) {
  fill_interval_begin(
      int(g.level_begin[std::size_t(r)]), int(g.level_begin[std::size_t(r) + 1]), r,
      [&g](int n) { return g.nodes[std::size_t(n)].interval; }, out);
}

void prepare_sums(const ArgGraph& g, const Weights& w, MatchPrep::Sums& out,
                  std::vector<std::pair<double, int>>* scratch) {
  const std::size_t n = g.nodes.size();
  out.self.resize(n);
  out.total = 0;
  for (std::size_t m = 0; m < n; ++m) out.total += out.self[m] = node_self_sim(g.nodes[m], w);
  prepare_order(g.level_begin, g.levels(), out, scratch);
}

void prepare_order(const std::vector<std::uint32_t>& level_begin, int levels, MatchPrep::Sums& out,
                   std::vector<std::pair<double, int>>* scratch) {
  const std::size_t n = out.self.size();
  // Sorted as (-sim, index) pairs, which keeps the keys beside each other in memory.
  std::vector<std::pair<double, int>> own;
  std::vector<std::pair<double, int>>& keyed = scratch ? *scratch : own;
  keyed.resize(n);
  for (std::size_t m = 0; m < n; ++m) keyed[m] = {-out.self[m], int(m)};
  out.order.resize(n);
  for (int r = 0; r <= levels; ++r) {
    const std::size_t b = level_begin[std::size_t(r)], e = level_begin[std::size_t(r) + 1];
    std::sort(keyed.begin() + std::ptrdiff_t(b), keyed.begin() + std::ptrdiff_t(e));
    for (std::size_t k = b; k < e; ++k) out.order[k] = keyed[k].second;
  }
}

void prepare_match(const ArgGraph& g, const Weights& weights, MatchPrep& out) {
  out.weights = weights;
  out.level_begin = g.level_begin;
  std::vector<std::array<int, 2>> only;
  prepare_nodes(g, only, out.keys);
  out.branches = prepare_branches(only, out.keys);
  prepare_neighbour_parents(g, out);
  prepare_child_halves(g, out.keys, out.child_begin, out.child_mid, out.children);
  make_sim_keys(g, out.sim_keys);
  out.interval_begin.resize(interval_offset(g.levels() + 1));
  for (int r = 0; r <= g.levels(); ++r)
    prepare_interval_begin(g, r, out.interval_begin.data() + interval_offset(r));
  Weights plain = weights;
  plain.lambda_4 = 0;
  prepare_sums(g, plain, out.plain);
  if (g.summary.has_colour && weights.lambda_4 != 0) {
    prepare_sums(g, weights, out.coloured);
  } else {
    out.coloured.self.clear();
    out.coloured.order.clear();
    out.coloured.total = 0;
  }
}

bool prep_shape_fits(const MatchPrep* prep, const ArgGraph& g) {
  if (!prep) return false;
  // A head (no node records, match/packed_graph.hpp) is matched on its prep's keys alone.
  const bool head = g.nodes.empty();
  const std::size_t n = head ? prep->keys.size() : g.nodes.size();
  if (head && (n == 0 || prep->sim_keys.size() != n)) return false;
  return prep->level_begin == g.level_begin && prep->parent_split.size() == n &&
         prep->parent_begin.size() == n + 1 && prep->keys.size() == n &&
         (prep->child_begin.empty() ||
          (prep->child_begin.size() == n + 1 && prep->child_mid.size() == n &&
           prep->child_begin[n] == prep->children.size())) &&
         (prep->sim_keys.empty() || prep->sim_keys.size() == n) && prep->plain.self.size() == n &&
         (prep->plain.order.size() == n || prep->plain.order.empty()) &&
         prep->interval_begin.size() == interval_offset(g.levels() + 1);
}

bool prep_fits(const MatchPrep* prep, const ArgGraph& g, const Weights& weights) {
  return prep_shape_fits(prep, g) && prep->weights == weights;
}

}  // namespace arg
