// The node bound of an ARG: how many nodes a graph, and each of its levels, may hold.
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

}  // namespace arg
