// Single- and multi-source shortest paths on a SurfaceGraph.
#pragma once

#include <cstdint>
#include <limits>
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
constexpr std::uint32_t kUnreached = std::numeric_limits<std::uint32_t>::max();

struct BucketScratch {
  // A bucket's entries are its first `size` slots. A relaxation writes its node into the next
  // slot whether or not it improved the distance and counts it only if it did: no branch on
  // the comparison, which goes either way about as often (the slots grow, rarely, when full).
  struct Bucket {
    std::vector<int> slots;
    std::size_t size = 0;
  };
  // A ring of 2^k buckets, more than the longest quantised edge: a node's tentative distance is
  // at most that far past the bucket being emptied, so indices masked by `mask` never collide.
  std::vector<Bucket> buckets;
  std::size_t mask = 0;
  // Per graph edge, in the graph's order: the target in the low half, the quantised length in
  // the high half (one load per relaxation).
  std::vector<std::uint64_t> arc;
  std::vector<std::uint32_t> dist;
  double unit = 0;
  bool empty = true;  // every bucket empty: false while a run is under way or was stopped

  // Node v's distance after shortest_steps, in the graph's units (+inf where unreached).
  float distance(std::size_t v) const {
    return dist[v] == kUnreached ? std::numeric_limits<float>::infinity() : float(dist[v] * unit);
  }
};

// Quantises the graph's edge lengths once for many shortest_paths_quantised calls.
void prepare_buckets(const SurfaceGraph& graph, BucketScratch& scratch);

void shortest_paths_quantised(const SurfaceGraph& graph, int source, std::vector<float>& distance,
                              BucketScratch& scratch, const StopRequested& stop = {});

// The same run, its distances left in scratch.dist as whole units (kUnreached where none):
// scratch.distance(v) gives what shortest_paths_quantised would have written, without a pass
// over every node to write it.
void shortest_steps(const SurfaceGraph& graph, int source, BucketScratch& scratch,
                    const StopRequested& stop = {});

}  // namespace arg
