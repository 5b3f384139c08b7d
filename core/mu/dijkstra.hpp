// Single- and multi-source shortest paths on a SurfaceGraph.
#pragma once

#include <cstdint>
#include <vector>

#include "common/limits.hpp"
#include "mu/surface_graph.hpp"

namespace arg {

// Distances from `sources` (all at distance 0) to every node; unreachable nodes get +inf.
// When `nearest` is given it receives, per node, the index in `sources` of the closest source.
void shortest_paths(const SurfaceGraph& graph, const std::vector<int>& sources,
                    std::vector<float>& distance, std::vector<int>* nearest = nullptr,
                    const StopRequested& stop = {});

// The same distances computed on edge lengths rounded to `unit` (Dial's bucket queue): no
// heap, and the rounding (at most unit / 2 per edge, unbiased) is negligible for mu, an
// integral over many paths. `buckets` is scratch space reused between calls.
struct BucketScratch {
  std::vector<std::vector<int>> buckets;
  std::vector<std::uint32_t> length;  // quantised edge lengths
  std::vector<std::uint32_t> dist;
  double unit = 0;
};

// Quantises the graph's edge lengths once for many shortest_paths_quantised calls.
void prepare_buckets(const SurfaceGraph& graph, BucketScratch& scratch);

void shortest_paths_quantised(const SurfaceGraph& graph, int source, std::vector<float>& distance,
                              BucketScratch& scratch, const StopRequested& stop = {});

}  // namespace arg
