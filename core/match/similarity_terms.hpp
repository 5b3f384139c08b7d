// The graph's SIM split into the terms of sim (a, l, v, cords, curvature, colour), to explain it.
#pragma once

#include <vector>

#include "graph/arg_graph.hpp"
#include "match/similarity.hpp"
#include "match/weights.hpp"

namespace arg {

// Each term's weighted sum of minima over the matched groups, divided by SIM's denominator:
// 1 - graph_similarity = a + l + v + cords + curvature + colour (before its clamp to [0, 1]).
struct SimilarityTerms {
  double a = 0, l = 0, v = 0, cords = 0, curvature = 0, colour = 0;
  // The weights the terms were summed with: the caller's, lambda_4 0 unless both have colour.
  Weights weights;

  double total() const { return a + l + v + cords + curvature + colour; }
};

// Splits the score of `matches` (as filled by graph_similarity or arg_similarity) into its
// terms, with the same weights and the same rule that colour weighs nothing unless both
// models have colour.
SimilarityTerms similarity_terms(const ArgGraph& a, const ArgGraph& b, const Weights& weights,
                                 const std::vector<MatchPair>& matches);

}  // namespace arg
