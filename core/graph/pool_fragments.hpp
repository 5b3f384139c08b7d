// The node bound of an ARG: a fragmented input's smallest components pooled into one.
#pragma once

#include <cstddef>

#include "graph/arg_graph.hpp"

namespace arg {

// At most this many nodes in a graph, spread evenly over its levels: 640 a level at the
// default 5 levels. With colour, 65 bytes a node, it keeps a value under 256 kB.
inline constexpr std::size_t kMaxGraphNodes = 3840;

// Nodes (and edges) one level of a graph with `levels` levels may hold.
std::size_t max_nodes_per_level(int levels);

// The first level of `g` holding more nodes than max_nodes_per_level, or -1 when none does
// (format 3's reader and writer both hold a graph to it). Expects a consistent level table.
int level_over_node_bound(const ArgGraph& g);

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
