// Jittered copies of a built ARG.
#include "eval/value_jitter.hpp"

#include <algorithm>
#include <cmath>

#include "common/random.hpp"

namespace arg {

namespace {

// Each histogram of `bins` moved bin by bin, then scaled to sum to `total` (all zero stays zero).
template <std::size_t N>
void jitter_bins(std::array<float, N>& bins, std::size_t per_histogram, float total,
                 SeededRandom& rng, double amount) {
  for (std::size_t h = 0; h + per_histogram <= N; h += per_histogram) {
    double sum = 0;
    for (std::size_t k = h; k < h + per_histogram; ++k) {
      bins[k] = float(bins[k] * (1 + amount * rng.signed_unit()));
      sum += bins[k];
    }
    if (sum <= 0) continue;
    for (std::size_t k = h; k < h + per_histogram; ++k) bins[k] = float(bins[k] * total / sum);
  }
}

}  // namespace

ArgGraph jittered_copy(const ArgGraph& g, std::uint64_t seed, double amount) {
  ArgGraph c = g;
  SeededRandom rng(seed);
  auto scaled = [&](float x, float hi) {
    return std::clamp(float(x * (1 + amount * rng.signed_unit())), 0.0f, hi);
  };
  const float half_pi = float(M_PI / 2);
  for (ArgNode& n : c.nodes) {
    n.a = scaled(n.a, 1.0f), n.l = scaled(n.l, 1.0f), n.v = scaled(n.v, 1.0f);
    n.r = scaled(n.r, 1e6f);
    n.theta = std::clamp(float(n.theta + amount * M_PI * rng.signed_unit()), -half_pi, half_pi);
    n.phi = std::clamp(float(n.phi + amount * M_PI * rng.signed_unit()), 0.0f, float(M_PI));
    jitter_bins(n.cords, kCordBins, n.a, rng, amount);
    jitter_bins(n.curv_mean, kCurvatureBins, n.a, rng, amount);
    jitter_bins(n.curv_gauss, kCurvatureBins, n.a, rng, amount);
    if (c.summary.has_colour) jitter_bins(n.colour, kColourBins, n.a, rng, amount);
  }
  for (float& x : c.panorama) x = scaled(x, 1.0f);
  for (float& x : c.spectrum) x = std::max(scaled(x, 1e3f), 1e-6f);
  for (float& x : c.global) x = float(x * (1 + amount * rng.signed_unit()));
  return c;
}

}  // namespace arg
