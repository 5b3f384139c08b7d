// Quantised shortest paths from up to kLanes sources at once, by sweeps in fixed node orders.
#pragma once

#include <cstdint>
#include <vector>

#include "common/limits.hpp"
#include "mu/dijkstra.hpp"
#include "mu/surface_graph.hpp"

namespace arg {

inline constexpr int kLanes = 16;
// Beyond any path when the quantised lengths of all arcs sum to less (LaneGraph::fits); it plus
// a length (below 2^16, prepare_buckets) does not overflow.
inline constexpr std::int32_t kLaneFar = 1 << 30;

// A surface graph renumbered for sweeps: node v is row rank[v], rows laid out in the first
// order (so that a sweep in it reads neighbouring rows), and further orders kept as row lists.
struct LaneGraph {
  std::vector<int> rank;
  std::vector<int> offset;               // CSR over rows
  std::vector<std::uint64_t> arc;        // target row | quantised length << 32
  std::vector<std::vector<int>> orders;  // sweep orders after the layout's own, as rows
  bool fits = false;  // every distance fits a lane (the arcs' lengths sum below 2^30)
  int rows() const { return int(rank.size()); }
};

// One run's distances, kLanes per row, and which rows a neighbour's change left to revisit.
struct LaneRows {
  std::vector<std::int32_t> values;  // 64-byte aligned from `first`
  std::size_t first = 0;
  std::vector<std::uint8_t> dirty;
  int sweeps = 0;  // of the last run: a measure, never an input
};

// `keys[i][v]` orders the nodes v for the i-th sweep order (ascending, ties by node); keys[0]
// also lays out the rows. `quantised` is prepare_buckets' result on the same graph, whose
// quantised lengths the runs use. At least one key.
LaneGraph lane_graph(const SurfaceGraph& graph, const BucketScratch& quantised,
                     const std::vector<std::vector<std::uint32_t>>& keys,
                     const StopRequested& stop = {});

// Distances in whole units from sources[0..count) (count <= kLanes), each in its own lane,
// exactly shortest_steps' for each source (lane_distance reads them). Only for graphs that fit. The
// order of the sweeps changes only how many it takes, never a distance.
void shortest_steps_lanes(const LaneGraph& graph, const int* sources, int count, LaneRows& rows,
                          const StopRequested& stop = {});

// Node v's distance in lane `lane` after shortest_steps_lanes (kUnreached where none).
inline std::uint32_t lane_distance(const LaneGraph& graph, const LaneRows& rows, int node,
                                   int lane) {
  const std::int32_t d =
      rows.values[rows.first + std::size_t(graph.rank[std::size_t(node)]) * kLanes +
                  std::size_t(lane)];
  return d >= kLaneFar ? kUnreached : std::uint32_t(d);
}

}  // namespace arg
