// Each node's children in index order, split at the two halves of its mu interval.
#pragma once

#include <cstdint>
#include <vector>

#include "graph/arg_graph.hpp"
#include "match/match_prep.hpp"

namespace arg {

// The lists match_graphs takes a node's candidates from: the children of node i are
// children[begin[i], begin[i + 1]) in index order (as a scan of their interval meets them), those
// in the upper half of i's interval (2 interval(i) + 1) from mid[i]. `keys` are g's
// (prepare_nodes). Returns false, with the three vectors empty, when g's child lists leave
// g.children or name no node, or a child lies in neither half of its parent's interval (the
// matcher then scans whole intervals); the readers and the builder make graphs that pass.
bool prepare_child_halves(const ArgGraph& g, const std::vector<MatchKey>& keys,
                          std::vector<std::uint32_t>& begin, std::vector<std::uint32_t>& mid,
                          std::vector<std::uint32_t>& children);

}  // namespace arg
