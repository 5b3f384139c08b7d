// Keeping the largest components of a fragmented graph whole and pooling the rest, per interval.
#include "pipeline/pool_fragments.hpp"

#include <algorithm>
#include <numeric>

namespace arg {

namespace {

struct PoolSum {
  ArgNode node;
  double weight = 0, r = 0, theta = 0, phi = 0;  // area-weighted position sums
  std::size_t members = 0;
};

void add(PoolSum& p, const ArgNode& n) {
  ArgNode& s = p.node;
  if (p.members++ == 0) {
    s = n;
    s.a = s.l = s.v = 0;
    s.cords = {}, s.curv_mean = {}, s.curv_gauss = {}, s.colour = {};
  }
  s.a += n.a, s.l += n.l, s.v += n.v;
  s.mu_min = std::min(s.mu_min, n.mu_min), s.mu_max = std::max(s.mu_max, n.mu_max);
  for (std::size_t k = 0; k < s.cords.size(); ++k) s.cords[k] += n.cords[k];
  for (std::size_t k = 0; k < s.curv_mean.size(); ++k)
    s.curv_mean[k] += n.curv_mean[k], s.curv_gauss[k] += n.curv_gauss[k];
  for (std::size_t k = 0; k < s.colour.size(); ++k) s.colour[k] += n.colour[k];
  // A member of no area still counts, so that a pool of such members has a position.
  const double w = double(n.a) + 1e-12;
  p.weight += w, p.r += w * n.r, p.theta += w * n.theta, p.phi += w * n.phi;
}

ArgNode finished(const PoolSum& p) {
  ArgNode n = p.node;
  n.r = float(p.r / p.weight), n.theta = float(p.theta / p.weight);
  n.phi = float(p.phi / p.weight);
  n.a = std::min(n.a, 1.0f), n.l = std::min(n.l, 1.0f), n.v = std::min(n.v, 1.0f);
  return n;
}

}  // namespace

std::size_t pool_fragments(ArgGraph& g, std::size_t per_level) {
  const int levels = g.levels();
  const std::size_t n = g.nodes.size(), level_count = std::size_t(levels) + 1;
  // Per level, nodes and (undirected) edges.
  std::vector<std::size_t> nodes_on(level_count, 0), edges_on(level_count, 0);
  for (const ArgNode& node : g.nodes) ++nodes_on[node.level];
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = 0; k < g.nodes[i].adj_count; ++k)
      if (g.adjacency[g.nodes[i].adj_begin + k] > i) ++edges_on[g.nodes[i].level];
  bool within = true;
  for (std::size_t r = 0; r < level_count; ++r)
    within = within && nodes_on[r] <= per_level && edges_on[r] <= per_level;
  if (within) return 0;

  // Each node's component: its level-0 ancestor.
  const std::size_t roots = g.level_begin[1];
  std::vector<std::uint32_t> component(n);
  for (std::size_t i = 0; i < n; ++i)
    component[i] = i < roots ? std::uint32_t(i) : component[std::size_t(g.nodes[i].parent)];
  // Nodes and edges per component and level.
  std::vector<std::size_t> node_count(roots * level_count, 0), edge_count(node_count);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t at = component[i] * level_count + g.nodes[i].level;
    ++node_count[at];
    for (std::uint32_t k = 0; k < g.nodes[i].adj_count; ++k)
      if (g.adjacency[g.nodes[i].adj_begin + k] > i) ++edge_count[at];
  }
  std::vector<std::uint32_t> order(roots);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t x, std::uint32_t y) { return g.nodes[x].a > g.nodes[y].a; });
  // The pool takes at most 2^r nodes and 2^r - 1 edges on level r.
  std::vector<std::size_t> nodes_used(level_count, 0), edges_used(level_count, 0);
  std::vector<std::uint8_t> kept(roots, 0);
  std::size_t pooled = roots;
  for (std::uint32_t c : order) {
    bool fits = true;
    for (std::size_t r = 0; r < level_count && fits; ++r) {
      const std::size_t pool = std::size_t(1) << r, at = c * level_count + r;
      fits = nodes_used[r] + node_count[at] + pool <= per_level &&
             edges_used[r] + edge_count[at] + pool <= per_level;
    }
    if (!fits) break;
    for (std::size_t r = 0; r < level_count; ++r)
      nodes_used[r] += node_count[c * level_count + r],
          edges_used[r] += edge_count[c * level_count + r];
    kept[c] = 1, --pooled;
  }

  // New nodes level by level, in interval order: kept nodes as they were, then the pool's.
  ArgGraph out;
  out.format = g.format, out.options = g.options, out.builder_version = g.builder_version;
  out.summary = g.summary, out.global = g.global;
  out.panorama = std::move(g.panorama), out.spectrum = std::move(g.spectrum);
  out.level_begin.assign(level_count + 1, 0);
  std::vector<std::uint32_t> new_index(n);
  std::vector<std::uint32_t> pool_of_interval;  // previous level's pool node per interval
  for (std::size_t r = 0; r < level_count; ++r) {
    const std::uint32_t intervals = 1u << r;
    std::vector<PoolSum> pool(intervals);
    for (std::uint32_t i = g.level_begin[r]; i < g.level_begin[r + 1]; ++i)
      if (!kept[component[i]]) add(pool[g.nodes[i].interval], g.nodes[i]);
    std::vector<std::uint32_t> pool_index(intervals, 0);
    std::uint32_t i = g.level_begin[r];
    for (std::uint32_t t = 0; t < intervals; ++t) {
      for (; i < g.level_begin[r + 1] && g.nodes[i].interval == t; ++i) {
        if (!kept[component[i]]) continue;
        ArgNode node = g.nodes[i];
        if (r > 0) node.parent = std::int32_t(new_index[std::size_t(node.parent)]);
        new_index[i] = std::uint32_t(out.nodes.size());
        out.nodes.push_back(node);
      }
      if (pool[t].members == 0) continue;
      ArgNode node = finished(pool[t]);
      node.parent = r > 0 ? std::int32_t(pool_of_interval[t / 2]) : -1;
      pool_index[t] = std::uint32_t(out.nodes.size());
      out.nodes.push_back(node);
    }
    for (std::uint32_t j = g.level_begin[r]; j < g.level_begin[r + 1]; ++j)
      if (!kept[component[j]]) new_index[j] = pool_index[g.nodes[j].interval];
    pool_of_interval = std::move(pool_index);
    out.level_begin[r + 1] = std::uint32_t(out.nodes.size());
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = 0; k < g.nodes[i].adj_count; ++k) {
      const std::uint32_t j = g.adjacency[g.nodes[i].adj_begin + k];
      if (j > i) edges.push_back({new_index[i], new_index[j]});
    }
  link_graph(out, edges);
  out.summary.flags |= kFlagPooled;
  out.summary.pooled = std::uint16_t(std::min<std::size_t>(pooled, 65535));
  g = std::move(out);
  return pooled;
}

}  // namespace arg
