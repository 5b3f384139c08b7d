// The first stage's descriptor: level sums, the panorama's lowest frequencies, the spectrum.
#include "search/search_descriptor.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "features/laplace_spectrum.hpp"
#include "features/panorama_descriptor.hpp"

namespace arg {

namespace {

static_assert(kSearchViews * kPanoramaPerView == kPanoramaFourier, "the panorama's views changed");
static_assert(kSearchAngular <= kPanoramaAngular && kSearchAxial <= kPanoramaAxial &&
                  kSearchEigen <= kSpectrumSize && kColourBins == 2 * kSearchColourBins,
              "the descriptor keeps part of what a value stores");

// Block scales, in the units of each block (see the header for how they were chosen).
constexpr double kCurvatureScale = 0.5, kCountScale = 2.0, kAreaScale = 0.5;
constexpr double kPanoramaScale = 3.0, kEigenScale = 0.3;

// A value without a spectrum (a proxy's or a wide-open surface's, which SIM does not compare)
// sits at one central point, the mean log eigenvalues of the labelled sets' models that have
// one, so that the block weighs little between it and any model, as SIM then weighs no spectrum.
constexpr std::array<double, kSearchEigen> kMeanLogEigen = {-0.868, -0.851, -0.816, -0.715, -0.679,
                                                            -0.562, -0.521, -0.442, -0.363, -0.310};

// The float of x, or 0 for what is not a finite float. Rankings read stored values without
// checking their sections' or nodes' ranges (serialize.hpp), so a bad number must not become a
// NaN or an infinity that a cube would carry into an index (or that would break the sort of
// the areas): it counts as missing.
float finite_or_zero(double x) {
  const float f = float(x);
  return std::isfinite(f) ? f : 0.0f;
}

}  // namespace

std::array<float, kSearchDims> search_descriptor(const ArgGraph& g, const Weights& w) {
  std::array<float, kSearchDims> d{};
  std::size_t k = 0;
  const double levels = g.levels() + 1.0;
  const ArgNode& root = g.nodes.front();
  // Curvature histograms sum up the levels unchanged: every level holds the root's.
  const double curvature = kCurvatureScale * w.lambda_3 * 0.5 * levels;
  for (float x : root.curv_mean) d[k++] = finite_or_zero(curvature * x);
  for (float x : root.curv_gauss) d[k++] = finite_or_zero(curvature * x);
  for (int r = 0; r < kSearchLevels; ++r) {
    const double count =
        r <= g.levels() ? double(g.level_begin[std::size_t(r) + 1] - g.level_begin[std::size_t(r)])
                        : 0.0;
    d[k++] = finite_or_zero(kCountScale * 0.02 * count / double(1 << r));
  }
  for (int r = 1; r <= 3; ++r) {
    std::vector<float> areas;
    if (r <= g.levels())
      for (std::uint32_t i = g.level_begin[std::size_t(r)]; i < g.level_begin[std::size_t(r) + 1];
           ++i)
        areas.push_back(finite_or_zero(kAreaScale * 2.0 * w.alpha_s * g.nodes[i].a * levels));
    std::sort(areas.begin(), areas.end(), std::greater<float>());
    areas.resize(kSearchAreas, 0.0f);
    for (float a : areas) d[k++] = a;
  }
  // Values without a panorama (format 1) leave zeros.
  const bool panorama = g.panorama.size() == std::size_t(kPanoramaSize);
  for (int view = 0; view < kSearchViews; ++view)
    for (int u = 0; u <= kSearchAngular; ++u)
      for (int v = 0; v <= kSearchAxial; ++v) {
        const std::size_t at = std::size_t(view * kPanoramaPerView + u * (kPanoramaAxial + 1) + v);
        d[k++] = panorama ? finite_or_zero(kPanoramaScale * g.panorama[at]) : 0.0f;
      }
  bool spectrum = g.spectrum.size() >= std::size_t(kSearchEigen);
  for (std::size_t e = 0; spectrum && e < std::size_t(kSearchEigen); ++e)
    spectrum = std::isfinite(g.spectrum[e]) && g.spectrum[e] > 0;
  for (std::size_t e = 0; e < std::size_t(kSearchEigen); ++e)
    d[k++] = finite_or_zero(kEigenScale *
                            (spectrum ? std::log(double(g.spectrum[e])) : kMeanLogEigen[e]));
  if (g.summary.has_colour)
    for (std::size_t b = 0; b < root.colour.size(); b += 2)
      d[k++] =
          finite_or_zero(w.lambda_4 * levels * (double(root.colour[b]) + root.colour[b + 1]) / 3.0);
  return d;
}

}  // namespace arg
