// The vector a two-stage search indexes: what SIM weighs most, in at most 100 numbers.
#pragma once

#include <array>

#include "graph/arg_graph.hpp"
#include "match/weights.hpp"

namespace arg {

// Blocks, in order (each scaled so that the taxicab distance weighs them as the study below
// chose): curvature of the whole model (mean, Gaussian); the node count per interval of levels
// 0..5; the four largest node areas of levels 1..3 (the branch structure); the panorama's
// lowest frequencies (first frame, each view's angular 0..2 by axial 0..1); the log of the
// first Laplace-Beltrami eigenvalues; colour, two bins merged into one.
inline constexpr int kSearchLevels = 6;      // levels 0..5 (a graph with fewer levels pads zeros)
inline constexpr int kSearchAngular = 2;     // panorama frequencies kept around the axis
inline constexpr int kSearchAxial = 1;       // and along it
inline constexpr int kSearchEigen = 10;      // eigenvalues kept
inline constexpr int kSearchColourBins = 4;  // per channel
inline constexpr int kSearchViews = 6;       // the panorama's views (panorama_descriptor.hpp)
inline constexpr int kSearchAreas = 4;       // largest node areas kept per level 1..3
// Where each block starts; a block ends where the next starts (colour at kSearchDims).
inline constexpr int kSearchCountsAt = 2 * kCurvatureBins;
inline constexpr int kSearchAreasAt = kSearchCountsAt + kSearchLevels;
inline constexpr int kSearchPanoramaAt = kSearchAreasAt + 3 * kSearchAreas;
inline constexpr int kSearchEigenAt =
    kSearchPanoramaAt + kSearchViews * (kSearchAngular + 1) * (kSearchAxial + 1);
inline constexpr int kSearchColourAt = kSearchEigenAt + kSearchEigen;
inline constexpr int kSearchDims = kSearchColourAt + 3 * kSearchColourBins;  // 92

// Why these: SIM is 1 part graph, 2.5 parts panorama and 0.75 parts spectrum (weights.hpp),
// and a first stage that sees only the graph's level sums misses the whole-shape terms that
// rank most of SIM. Blocks and scales chosen by recall of SIM's ten nearest among a first
// stage's 20 nearest on the three labelled sets, and checked by tuning on two and scoring on
// the third (tests/scale/descriptor_study.sh --tune; docs/BENCHMARKS.md "Descriptor choice");
// the graph's cords sums, which added less than 0.005 on every set, made room for the panorama
// within contrib/cube's 100 dimensions.
std::array<float, kSearchDims> search_descriptor(const ArgGraph& graph,
                                                 const Weights& weights = {});

}  // namespace arg
