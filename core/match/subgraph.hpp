// The sub-graph of an ARG below one node, renormalised to be an ARG of its own (part matching).
#pragma once

#include "graph/arg_graph.hpp"

namespace arg {

// The node `root` (global index) and all its descendants, levels renumbered from 0, intervals
// rebased on the root's, a, l, v and histograms rescaled so that each level sums to
// 1 / (levels + 1) as in a whole ARG. Barycentres stay in the model's frame.
ArgGraph subgraph(const ArgGraph& g, int root);

}  // namespace arg
