// SIM of one query against many stored values, each read straight from its bytes: what an
// index re-ranks its candidates with, the same to the bit as the <~> operator.
#pragma once

#include <string_view>

#include "graph/arg_graph.hpp"
#include "match/match_prep.hpp"
#include "match/packed_graph.hpp"
#include "match/weights.hpp"
#include "search/shape_sketch.hpp"

namespace arg {

class QueryRanker {
 public:
  // Reads the query (checked as deserialize_arg checks a value, digest included) and prepares
  // its side of matching once. Throws InputError.
  explicit QueryRanker(std::string_view query_bytes, const Weights& weights = {});

  // SIM(row, query) of a stored value (read without the digest pass, as the operator reads
  // stored values). Throws InputError for a malformed value and Incomparable for one
  // built by another builder, as <~> does.
  double sim(std::string_view row_bytes);

  const ArgGraph& query() const { return query_; }
  const ShapeSketch& sketch() const { return sketch_; }

 private:
  Weights weights_;
  ArgGraph query_;
  MatchPrep prep_;
  ShapeSketch sketch_;
  bool packs_ = false;
  PackedGraph packed_;  // a row read straight into the matcher's keys, reused
  ArgGraph row_;        // a row read whole, reused
};

}  // namespace arg
