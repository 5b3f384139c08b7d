// The Reeb graph of one level of an ARG as a small self-contained SVG picture.
#pragma once

#include <string>

#include "graph/arg_graph.hpp"

namespace arg {

// Reads bottom (mu = 0) to top (mu = 1): each node sits at the centre of its mu interval.
// Across, the nodes of an interval start in the order of a projection of their barycentres
// (r sin(phi) sin(theta): the second principal axis, up to the sign of x that the ARG drops)
// and then move towards the mean of their neighbours, kept apart, so that edges cross little.
// One <circle> per node (disc area from the node's area, fill from its mu, a <title> with
// level, node, area and mu range) and one <line> per adjacency edge; the axis is a <path>.
// No external references, no scripts. Throws InputError for a level the graph does not have.
std::string arg_graph_svg(const ArgGraph& graph, int level);

}  // namespace arg
