// The per-node terms of matching: loss (which candidate wins) and sim (what a match is worth).
#pragma once

#include <array>

#include "graph/arg_graph.hpp"
#include "match/weights.hpp"

namespace arg {

// Additive attributes of one node or of a group of nodes matched together.
struct NodeMass {
  double a = 0, l = 0, v = 0;
  std::array<float, kCordBins> cords{};
  std::array<float, kCurvatureBins> curv_mean{}, curv_gauss{};
  std::array<float, 3 * kColourBins> colour{};

  void add(const ArgNode& n);
};

// Sum of bin-wise minima of two histograms: how much of them two nodes share.
template <std::size_t N>
double histogram_min(const std::array<float, N>& x, const std::array<float, N>& y) {
  double s = 0;
  for (std::size_t k = 0; k < N; ++k) s += x[k] < y[k] ? x[k] : y[k];
  return s;
}

// sim(m, n) = alpha_s min(a) + beta_s min(l) + lambda_1 min(v) + lambda_2 min(cords)
//           + lambda_3 (min(curv_mean) + min(curv_gauss)) / 2 + lambda_4 min(colour) / 3,
// a histogram min being the sum of bin-wise minima. sim(m, m) is the node's own mass.
double node_sim(const NodeMass& m, const NodeMass& n, const Weights& w);
double node_sim(const ArgNode& m, const ArgNode& n, const Weights& w);

// loss(m, n) over a and l (scaled to their level's total), r (capped at 2 RMS radii, halved),
// theta and phi (over pi); L1 or squared differences per the weights.
double node_loss(const ArgNode& m, const ArgNode& n, int levels, const Weights& w);

}  // namespace arg
