// SIM of one query against many stored values.
#include "search/query_ranker.hpp"

#include "graph/comparable.hpp"
#include "graph/serialize.hpp"
#include "match/similarity.hpp"

namespace arg {

QueryRanker::QueryRanker(std::string_view query_bytes, const Weights& weights)
    : weights_(weights), query_(deserialize_arg(query_bytes)) {
  prepare_match(query_, weights_, prep_);
  sketch_ = shape_sketch(query_);
  packs_ = packs_rows(query_, &prep_, weights_);
}

double QueryRanker::sim(std::string_view row_bytes) {
  // As the operator ranks a row against a repeated query: straight from the bytes when the
  // value allows it, whole otherwise; the two give the same bits.
  if (packs_ && read_packed_graph(row_bytes, weights_, packed_)) {
    require_comparable(packed_.head, query_);
    double sim = 0;
    if (packed_similarity(query_, &prep_, packed_, weights_, sim)) return sim;
  }
  deserialize_arg_into(row_bytes, row_, /*check_digest=*/false);
  require_comparable(row_, query_);
  return arg_similarity(row_, query_, weights_, nullptr, nullptr, &prep_);
}

}  // namespace arg
