// How SIM mixes its three terms: which of them count for a pair of models, and how much.
#pragma once

#include <cstdint>

#include "match/weights.hpp"

namespace arg {

// The weight each term of SIM gets for one pair of models; 0 leaves the term out.
struct TermWeights {
  double graph = 0, panorama = 0, spectrum = 0;
};

// The one rule SIM, the sketch distance and the weight search all follow. `flags` is the two
// models' summary flags or-ed together; `panoramas` and `spectra` say whether both models
// carry that descriptor.
// - The graph weighs `graph`, times graph_on_proxy when either model's graph was built on a
//   proxy (a proxy's Reeb graph is a shell's: weights.hpp).
// - The panorama weighs `panorama` when both models have one.
// - The spectrum weighs `spectrum` when both have one and both were built on their own
//   surfaces, not wide open: a proxy's spectrum is its shell's, and a wide-open surface's is
//   that of its openings as much as of its shape.
// - When that leaves nothing (values without whole-shape sections, format 1), the graph
//   weighs 1.
TermWeights term_weights(const Weights& w, std::uint16_t flags, bool panoramas, bool spectra);

// Each term's share of the mix: its weight times its distance over the sum of the weights (0
// for a term of weight 0).
struct TermShares {
  double graph = 0, panorama = 0, spectrum = 0;
};
TermShares term_shares(const TermWeights& t, double graph, double panorama, double spectrum);

// The weighted mean of the three distances: the sum of term_shares, added graph, panorama,
// spectrum in that order, so that the shares shown to a reader (arg_sim_terms) add up to it
// exactly in double arithmetic (not clamped).
double mix_terms(const TermWeights& t, double graph, double panorama, double spectrum);

}  // namespace arg
