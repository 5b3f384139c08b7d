// The per-node terms of matching: loss (which candidate wins) and sim (what a match is worth).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

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

// What a level's sims count for: level_ratio^level (Weights::level_ratio), by repeated
// products, as every sum of SIM's numerator and denominator takes it; exactly 1 when the ratio
// is 1, so that SIM is then the plain sum it always was.
inline double level_scale(double level_ratio, int level) {
  double s = 1;
  for (int r = 0; r < level; ++r) s *= level_ratio;
  return s;
}

// loss(m, n) over a and l (scaled to their level's total), r (capped at 2 RMS radii, halved),
// theta and phi (over pi); L1 or squared differences per the weights. `m` and `n` are nodes or
// anything with their float fields a, l, r, theta and phi (match/match_prep.hpp's MatchKey).
// Always inlined: called from match_graphs' candidate lambda, GCC kept it out of line (4% of a
// comparison in calls).
template <class M, class N>
[[gnu::always_inline]] inline double node_loss(const M& m, const N& n, int levels,
                                               const Weights& w) {
  const double per_level = levels + 1.0;
  const double d[5] = {
      (double(m.a) - n.a) * per_level,
      (double(m.l) - n.l) * per_level,
      (std::min(double(m.r), 2.0) - std::min(double(n.r), 2.0)) / 2.0,
      (double(m.theta) - n.theta) / M_PI,
      (double(m.phi) - n.phi) / M_PI,
  };
  const double k[5] = {w.alpha_l, w.beta_l, w.gamma_l, w.delta_l, w.eps_l};
  double loss = 0;
  for (int i = 0; i < 5; ++i) loss += k[i] * (w.l2 ? d[i] * d[i] : std::fabs(d[i]));
  return loss;
}

}  // namespace arg
