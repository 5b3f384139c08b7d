// The node bound of an ARG, per level.
#include "graph/node_bound.hpp"

#include <algorithm>

namespace arg {

std::size_t max_nodes_per_level(int levels) {
  return kMaxGraphNodes / std::size_t(std::max(levels, 0) + 1);
}

int level_over_node_bound(const ArgGraph& g) {
  for (int r = 0; r <= g.levels(); ++r)
    if (g.level_begin[std::size_t(r) + 1] - g.level_begin[std::size_t(r)] >
        max_nodes_per_level(g.levels()))
      return r;
  return -1;
}

}  // namespace arg
