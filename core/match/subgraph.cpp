// Cutting out and renormalising the descendants of one node.
#include "match/subgraph.hpp"

#include <algorithm>

namespace arg {

ArgGraph subgraph(const ArgGraph& g, int root) {
  const ArgNode& top = g.nodes[std::size_t(root)];
  const int depth = g.levels() - int(top.level);
  std::vector<std::vector<int>> members(std::size_t(depth) + 1);
  members[0] = {root};
  for (int k = 1; k <= depth; ++k) {
    for (int p : members[std::size_t(k) - 1]) {
      const ArgNode& n = g.nodes[std::size_t(p)];
      for (std::uint32_t c = 0; c < n.child_count; ++c)
        members[std::size_t(k)].push_back(int(g.children[n.child_begin + c]));
    }
    std::sort(members[std::size_t(k)].begin(), members[std::size_t(k)].end());
  }
  ArgGraph s;
  s.options = g.options;
  s.options.levels = depth;
  s.builder_version = g.builder_version;
  s.summary = g.summary;
  std::vector<int> new_index(g.nodes.size(), -1);
  s.level_begin.assign(std::size_t(depth) + 2, 0);
  for (int k = 0; k <= depth; ++k) {
    for (int i : members[std::size_t(k)])
      new_index[std::size_t(i)] = int(s.nodes.size()), s.nodes.push_back(g.nodes[std::size_t(i)]);
    s.level_begin[std::size_t(k) + 1] = std::uint32_t(s.nodes.size());
  }
  const double per_level = 1.0 / (depth + 1);
  const double a_scale = top.a > 0 ? per_level / top.a : 0.0;
  const double v_scale = top.v > 0 ? per_level / top.v : 0.0;
  for (int k = 0; k <= depth; ++k) {
    double l_sum = 0;
    for (std::uint32_t i = s.level_begin[std::size_t(k)]; i < s.level_begin[std::size_t(k) + 1];
         ++i)
      l_sum += s.nodes[i].l;
    const double l_scale = l_sum > 0 ? per_level / l_sum : 0.0;
    for (std::uint32_t i = s.level_begin[std::size_t(k)]; i < s.level_begin[std::size_t(k) + 1];
         ++i) {
      ArgNode& n = s.nodes[i];
      n.level = std::uint16_t(k);
      n.interval = std::uint16_t(n.interval - (int(top.interval) << k));
      n.parent = k == 0 ? -1 : new_index[std::size_t(n.parent)];
      n.a = float(n.a * a_scale), n.l = float(n.l * l_scale), n.v = float(n.v * v_scale);
      for (float& x : n.cords) x = float(x * a_scale);
      for (float& x : n.curv_mean) x = float(x * a_scale);
      for (float& x : n.curv_gauss) x = float(x * a_scale);
      for (float& x : n.colour) x = float(x * a_scale);
    }
  }
  // Links, keeping only those inside the sub-graph.
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    ArgNode& n = s.nodes[i];
    const ArgNode& old = g.nodes[std::size_t(members[n.level][i - s.level_begin[n.level]])];
    n.child_begin = std::uint32_t(s.children.size());
    for (std::uint32_t c = 0; c < old.child_count; ++c)
      s.children.push_back(std::uint32_t(new_index[g.children[old.child_begin + c]]));
    n.child_count = std::uint32_t(s.children.size()) - n.child_begin;
    n.adj_begin = std::uint32_t(s.adjacency.size());
    for (std::uint32_t k = 0; k < old.adj_count; ++k) {
      int j = new_index[g.adjacency[old.adj_begin + k]];
      if (j >= 0) s.adjacency.push_back(std::uint32_t(j));
    }
    n.adj_count = std::uint32_t(s.adjacency.size()) - n.adj_begin;
  }
  return s;
}

}  // namespace arg
