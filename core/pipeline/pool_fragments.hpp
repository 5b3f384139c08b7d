// A fragmented input's smallest components pooled into one, to keep a graph within its node bound.
#pragma once

#include <cstddef>

#include "graph/arg_graph.hpp"
#include "graph/node_bound.hpp"

namespace arg {

// A soup of thousands of loose parts has a node per part on every level: tens of thousands of
// nodes that cost size and matching time and say little one by one. When a level holds more
// than `per_level` nodes or edges, the connected components (the level-0 nodes and their
// descendants) are taken by area, largest first, and kept whole while every level stays
// within the bound less 2^level; the first that does not fit and every smaller one are pooled:
// on each level, all their nodes of one mu interval become one node, whose area, length,
// volume and histograms are the members' sums, mu range their union, and position the
// area-weighted mean of theirs. Sets kFlagPooled and summary.pooled. Returns the number of
// components pooled (0: the graph was within the bound and is unchanged).
std::size_t pool_fragments(ArgGraph& g, std::size_t per_level);

}  // namespace arg
