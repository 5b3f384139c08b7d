// Level sums of the ARG's features, scaled by their weights, for candidate search.
#include "graph/search_descriptor.hpp"

#include <algorithm>
#include <functional>
#include <vector>

namespace arg {

std::array<float, kSearchDims> search_descriptor(const ArgGraph& g, const Weights& w) {
  std::array<float, kSearchDims> d{};
  std::size_t k = 0;
  const double levels = g.levels() + 1.0;
  const ArgNode& root = g.nodes.front();
  // Curvature histograms sum up the levels unchanged: every level holds the root's.
  for (float x : root.curv_mean) d[k++] = float(w.lambda_3 * 0.5 * levels * x);
  for (float x : root.curv_gauss) d[k++] = float(w.lambda_3 * 0.5 * levels * x);
  for (int r = 0; r < kSearchLevels; ++r) {
    std::array<double, kCordBins> cords{};
    double volume = 0, count = 0;
    if (r <= g.levels())
      for (std::uint32_t i = g.level_begin[std::size_t(r)]; i < g.level_begin[std::size_t(r) + 1];
           ++i) {
        for (int b = 0; b < kCordBins; ++b)
          cords[std::size_t(b)] += g.nodes[i].cords[std::size_t(b)];
        volume += g.nodes[i].v;
        ++count;
      }
    for (double c : cords) d[k++] = float(w.lambda_2 * c);
    d[k++] = float(w.lambda_1 * volume);
    d[k++] = float(0.02 * count / double(1 << r));
  }
  for (int r = 1; r <= 3; ++r) {
    std::vector<float> areas;
    if (r <= g.levels())
      for (std::uint32_t i = g.level_begin[std::size_t(r)]; i < g.level_begin[std::size_t(r) + 1];
           ++i)
        areas.push_back(float(g.nodes[i].a * levels));
    std::sort(areas.begin(), areas.end(), std::greater<float>());
    areas.resize(4, 0.0f);
    for (float a : areas) d[k++] = float(2.0 * w.alpha_s * a);
  }
  if (g.summary.has_colour)
    for (float x : root.colour) d[k++] = float(w.lambda_4 * levels * x / 3.0);
  return d;
}

}  // namespace arg
