// SIM over a set from its terms computed once: a weight search tries many mixes of the same
// distances, and the graph's SIM depends only on the graph's own weights.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "graph/arg_graph.hpp"
#include "match/term_weights.hpp"
#include "match/weights.hpp"

namespace arg {

// The whole-shape terms of every pair of a set, and what each model has of them.
struct TermMatrices {
  std::size_t n = 0;
  std::vector<std::uint16_t> flags;              // each model's summary flags
  std::vector<char> has_panorama, has_spectrum;  // each model's
  std::vector<double> panorama, spectrum;        // n x n distances; 0 where either lacks it
};

// The matrices of `graphs` (nullptr: a model that failed to build; its rows stay 0).
TermMatrices term_matrices(const std::vector<const ArgGraph*>& graphs);

// How SIM weighs models i and j's terms under `w` (match/term_weights.hpp).
TermWeights pair_term_weights(const TermMatrices& m, std::size_t i, std::size_t j,
                              const Weights& w);

// SIM of models i and j under `w`, given their graph SIM under w's graph weights (read only
// when the graph weighs something): arg_similarity's value, to the bit.
double mixed_similarity(const TermMatrices& m, std::size_t i, std::size_t j, const Weights& w,
                        double graph);

}  // namespace arg
