// Where a measured value falls in the fixed bins of the node histograms.
#pragma once

#include <algorithm>
#include <cmath>

#include "graph/arg_graph.hpp"

namespace arg {

// Cords (distance to a barycentre, unit = RMS radius): one octave per bin from 2^-6 to 2, so
// small finest-level nodes and the whole model both spread over several bins.
inline int cords_bin(double d) {
  if (!(d > 0)) return 0;
  int b = int(std::floor(std::log2(d))) + 6;
  return std::clamp(b, 0, kCordBins - 1);
}

// Curvature (unit 1 / RMS radius) squashed by atan onto equal bins of (-1, 1): the sign and the
// order of magnitude matter, the exact value does not.
inline int curvature_bin(double k) {
  if (!std::isfinite(k)) k = 0;
  double t = std::atan(k / 2.0) / (M_PI / 2.0);  // (-1, 1)
  int b = int(std::floor((t + 1.0) / 2.0 * kCurvatureBins));
  return std::clamp(b, 0, kCurvatureBins - 1);
}

// Gaussian curvature has units of curvature squared; compare its signed square root.
inline int gaussian_bin(double k) {
  return curvature_bin(k >= 0 ? std::sqrt(k) : -std::sqrt(-k));
}

inline int colour_bin(float c) {
  return std::clamp(int(std::floor(double(c) * kColourBins)), 0, kColourBins - 1);
}

}  // namespace arg
