// Copying each node's children in index order and finding where its upper half starts.
#include "match/child_halves.hpp"

#include <algorithm>

namespace arg {

namespace {

bool fill(const ArgGraph& g, const std::vector<MatchKey>& keys, std::vector<std::uint32_t>& begin,
          std::vector<std::uint32_t>& mid, std::vector<std::uint32_t>& children) {
  const std::size_t n = g.nodes.size();
  if (keys.size() != n) return false;
  begin.resize(n + 1);
  mid.resize(n);
  children.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const ArgNode& node = g.nodes[i];
    // Checked, not trusted: the matcher indexes its keys with these.
    if (std::uint64_t(node.child_begin) + node.child_count > g.children.size()) return false;
    begin[i] = std::uint32_t(children.size());
    for (std::uint32_t k = 0; k < node.child_count; ++k) {
      const std::uint32_t c = g.children[node.child_begin + k];
      if (c >= n) return false;
      children.push_back(c);
    }
    const auto first = children.begin() + std::ptrdiff_t(begin[i]);
    std::sort(first, children.end());  // nodes of a level are sorted by interval: lower half first
    mid[i] = std::uint32_t(children.size());
    for (auto c = first; c != children.end(); ++c) {
      const std::uint32_t interval = keys[*c].interval;
      if (interval >> 1 != keys[i].interval) return false;
      const bool upper = (interval & 1) != 0;
      if (upper && mid[i] == children.size()) mid[i] = std::uint32_t(c - children.begin());
      if (!upper && mid[i] != children.size()) return false;  // a lower child after an upper one
    }
  }
  begin[n] = std::uint32_t(children.size());
  return true;
}

}  // namespace

bool prepare_child_halves(const ArgGraph& g, const std::vector<MatchKey>& keys,
                          std::vector<std::uint32_t>& begin, std::vector<std::uint32_t>& mid,
                          std::vector<std::uint32_t>& children) {
  if (fill(g, keys, begin, mid, children)) return true;
  begin.clear(), mid.clear(), children.clear();
  return false;
}

}  // namespace arg
