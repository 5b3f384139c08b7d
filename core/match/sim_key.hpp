// What sim(m, n) reads of a node in 40 bytes: area, length, volume, a/255 and 24 histogram codes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "graph/arg_graph.hpp"
#include "match/weights.hpp"

namespace arg {

inline constexpr std::size_t kSimKeyCodes = kCordBins + 2 * kCurvatureBins;
static_assert(kCordBins % 4 == 0 && kCurvatureBins % 4 == 0, "key_sim sums bins four at a time");

// A node as the group sims of match_graphs read it. A node record is 248 bytes, and loading a
// matched node's record was most of node_sim's time (cache misses): this is a sixth of that.
// Holds a histogram as format 3 stores it, bin k being float(code[k]) * step with step =
// a / 255 (graph/quantise.hpp's bins_values), so that the sims come out bit for bit as from
// the float records.
struct SimKey {
  float a = 0, l = 0, v = 0, step = 0;
  std::array<std::uint8_t, kSimKeyCodes> code{};  // cords, mean curvature, Gaussian curvature
};
static_assert(sizeof(SimKey) == 40, "SimKey packs into 40 bytes");

// Fills `out` with every node's key and returns true when every node's cords and curvature
// histograms are byte codes of its area (true of every value read from format 3); otherwise
// returns false with `out` empty (a graph just built, or read from format 1 or 2, compares on
// its float records instead).
bool make_sim_keys(const ArgGraph& g, std::vector<SimKey>& out);

// node_sim(m, n, w) of the nodes the keys were made from, the colour term left out: equal to
// the bit when w.lambda_4 is 0. With colour, the caller adds its term last, as node_sim does.
double key_sim(const SimKey& m, const SimKey& n, const Weights& w);

}  // namespace arg
