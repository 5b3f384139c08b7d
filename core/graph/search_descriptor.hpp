// The vector a two-stage search indexes: sums over each level of what SIM compares.
#pragma once

#include <array>

#include "graph/arg_graph.hpp"
#include "match/weights.hpp"

namespace arg {

inline constexpr int kSearchLevels = 6;  // levels 0..5 (a graph with fewer levels pads zeros)
inline constexpr int kSearchDims = 2 * kCurvatureBins + kSearchLevels * (kCordBins + 2) + 3 * 4 +
                                   3 * kColourBins;  // 96, within cube's 100

// Why it works: the numerator of SIM sums, over disjoint matched groups, bin-wise minima of
// node histograms, and sum_pairs min(h_m, h_n) <= min(sum h_M, sum h_N) bin by bin. So how far
// apart the level sums of two graphs are (taxicab distance) bounds how much SIM can gain from
// each feature. Blocks, each scaled by its weight: curvature (mean, Gaussian) of the whole
// model; per level the cords histogram summed over the nodes, the relative volume summed and
// the node count per interval; the four largest node areas of levels 1..3 (the branch
// structure); colour. On SHREC 2007, the 100 nearest of 400 by taxicab distance hold 99% of
// each model's 10 nearest by SIM.
std::array<float, kSearchDims> search_descriptor(const ArgGraph& graph,
                                                 const Weights& weights = {});

}  // namespace arg
