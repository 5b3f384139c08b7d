// Jittered copies of a built ARG: a million rows for the index benchmarks from a few thousand
// builds, each copy a plausible value near its original.
#pragma once

#include <cstdint>

#include "graph/arg_graph.hpp"

namespace arg {

// A copy of `g` whose every stored number is moved by a relative amount drawn uniformly in
// [-amount, amount] from a stream seeded by `seed`: each node's area, length, volume and
// radius, its angles (by amount times their range), each histogram bin (the bins then scaled
// back to sum to the node's area), every panorama value (kept in [0, 1]) and eigenvalue (kept
// in the formats' range), and the global descriptor. Links, levels, flags and options are kept,
// so the copy is a valid value of the same builder that reads and compares like any other. The
// same graph, seed and amount give the same copy.
ArgGraph jittered_copy(const ArgGraph& g, std::uint64_t seed, double amount);

}  // namespace arg
