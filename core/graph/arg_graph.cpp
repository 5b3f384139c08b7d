// Version stamp of the builder that made an ARG, and the links of its nodes.
#include "graph/arg_graph.hpp"

#include <algorithm>

namespace arg {

std::uint32_t current_builder_version() {
  // Bump when a change to the method changes the bytes built from the same mesh.
  return 1 * 10000 + 8 * 100 + 0;
}

void link_graph(ArgGraph& g, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges) {
  const std::size_t n = g.nodes.size();
  std::vector<std::uint32_t> child_count(n, 0), adj_count(n, 0);
  for (const ArgNode& node : g.nodes)
    if (node.parent >= 0) ++child_count[std::size_t(node.parent)];
  std::vector<std::pair<std::uint32_t, std::uint32_t>> both;
  both.reserve(2 * edges.size());
  for (auto [a, b] : edges)
    if (a != b) both.push_back({a, b}), both.push_back({b, a});
  std::sort(both.begin(), both.end());
  both.erase(std::unique(both.begin(), both.end()), both.end());
  for (auto [a, b] : both) ++adj_count[a];
  std::uint32_t child_at = 0, adj_at = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ArgNode& node = g.nodes[i];
    node.child_begin = child_at, node.child_count = 0;
    child_at += child_count[i];
    node.adj_begin = adj_at, node.adj_count = adj_count[i];
    adj_at += adj_count[i];
  }
  g.children.assign(child_at, 0);
  g.adjacency.resize(both.size());
  // Children in index order: nodes are visited in order, so each parent's list comes sorted.
  for (std::size_t i = 0; i < n; ++i)
    if (g.nodes[i].parent >= 0) {
      ArgNode& p = g.nodes[std::size_t(g.nodes[i].parent)];
      g.children[p.child_begin + p.child_count++] = std::uint32_t(i);
    }
  for (std::size_t k = 0; k < both.size(); ++k) g.adjacency[k] = both[k].second;
}

}  // namespace arg
