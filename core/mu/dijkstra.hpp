// Single- and multi-source shortest paths on a SurfaceGraph.
#pragma once

#include <vector>

#include "common/limits.hpp"
#include "mu/surface_graph.hpp"

namespace arg {

// Distances from `sources` (all at distance 0) to every node; unreachable nodes get +inf.
// When `nearest` is given it receives, per node, the index in `sources` of the closest source.
void shortest_paths(const SurfaceGraph& graph, const std::vector<int>& sources,
                    std::vector<float>& distance, std::vector<int>* nearest = nullptr,
                    const StopRequested& stop = {});

}  // namespace arg
