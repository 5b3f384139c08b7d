// A ranking's row as matching reads it: its head and keys, straight from its stored bytes.
#pragma once

#include <cstddef>
#include <string_view>

#include "graph/arg_graph.hpp"
#include "match/match_prep.hpp"
#include "match/weights.hpp"

namespace arg {

// A format-3 value without colour as matching reads it. Decoding a row into node records
// (248 bytes a node) and preparing its keys from them was half of a row's time in a ranking;
// this reads the 39-byte records straight into the keys. Reused row after row: its vectors
// keep their storage.
struct PackedGraph {
  ArgGraph head;              // all but the node records and links (graph/serialize.hpp)
  std::size_t adjacency = 0;  // what a decoded graph's adjacency.size() would be
  MatchPrep prep;             // for the weights given to read_packed_graph
};

// Reads `bytes` into `out`, checked as deserialize_arg_into(bytes, g, false) checks them, with
// the prep prepare_match(g, weights) would make of the decoded graph g (the same values bit for
// bit) but for the order of each level's nodes, left to order_packed_graph: matching reads it
// only from the graph it takes first, and sorting every row cost more than the rest of its
// prep. Returns false, out's prep left unfit, when the value is not format 3 without colour:
// read it whole then. Throws InputError.
bool read_packed_graph(std::string_view bytes, const Weights& weights, PackedGraph& out);

// Completes g's prep with each level's order (MatchPrep::Sums::order); nothing when it has it.
void order_packed_graph(PackedGraph& g);

}  // namespace arg
