// Node-level results of matching: arg_matches (the pairs behind SIM) and arg_part_match (the
// parts of a candidate that match one node of a query, paper section 5).
#include "graph/comparable.hpp"
#include "match/similarity.hpp"

#include "arg_cache.hpp"
#include "arg_weights.hpp"

// funcapi.h reaches PostgreSQL's spinlock headers, which use `register` (not C++17).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wregister"
extern "C" {
#include "funcapi.h"
#include "utils/tuplestore.h"
}
#pragma GCC diagnostic pop

namespace {

// Rows are plain data, filled inside guarded() and emitted after it.
struct PartRow {
  int32 level, node;
  float8 score;
};

struct PairRow {
  int32 level, a_node, b_node, group;
  float8 loss, sim;
};

template <typename Row, typename Source>
Row* copy_rows(const std::vector<Source>& source, Row (*convert)(const Source&)) {
  Row* rows = static_cast<Row*>(argpg::alloc_records(source.size(), sizeof(Row)));
  for (std::size_t i = 0; i < source.size(); ++i) rows[i] = convert(source[i]);
  return rows;
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_part_match);
PG_FUNCTION_INFO_V1(arg_matches);

// arg_part_match(query arg, level int, node int, candidate arg, weights arg_weights DEFAULT 'arg')
//   RETURNS TABLE (candidate_level int, candidate_node int, score float8), best (lowest) first.
Datum arg_part_match(PG_FUNCTION_ARGS) {
  const int32 level = PG_GETARG_INT32(1);
  const int32 node = PG_GETARG_INT32(2);
  const arg::Weights weights = argpg::to_weights(*PG_GETARG_ARG_WEIGHTS_P(4));
  argpg::GraphCacheHolder* cache = argpg::graph_cache(fcinfo);
  const argpg::GraphArg query = argpg::graph_arg(fcinfo, cache, 0, 0);
  const argpg::GraphArg candidate = argpg::graph_arg(fcinfo, cache, 1, 3);
  PartRow* rows = nullptr;
  std::size_t count = 0;
  argpg::Outcome out = argpg::guarded([&] {
    arg::ArgGraph scratch_q, scratch_c;
    const arg::ArgGraph& q = argpg::graph_of(cache, 0, query, scratch_q);
    const arg::ArgGraph& c = argpg::graph_of(cache, 1, candidate, scratch_c);
    arg::require_comparable(q, c);
    const std::vector<arg::PartMatch> parts =
        arg::part_match(q, level, node, c, weights, 0.5, argpg::stop_requested);
    rows = copy_rows<PartRow, arg::PartMatch>(parts, [](const arg::PartMatch& p) {
      return PartRow{p.level, p.node, p.score};
    });
    count = parts.size();
  });
  argpg::raise_if_failed(out, ERRCODE_INVALID_PARAMETER_VALUE, "cannot match parts");

  InitMaterializedSRF(fcinfo, 0);
  ReturnSetInfo* rsinfo = reinterpret_cast<ReturnSetInfo*>(fcinfo->resultinfo);
  for (std::size_t i = 0; i < count; ++i) {
    Datum values[3] = {Int32GetDatum(rows[i].level), Int32GetDatum(rows[i].node),
                       Float8GetDatum(rows[i].score)};
    bool nulls[3] = {false, false, false};
    tuplestore_putvalues(rsinfo->setResult, rsinfo->setDesc, values, nulls);
  }
  return (Datum)0;
}

// arg_matches(a arg, b arg, weights arg_weights DEFAULT 'arg')
//   RETURNS TABLE (level int, a_node int, b_node int, match_group int, loss float8, sim float8)
Datum arg_matches(PG_FUNCTION_ARGS) {
  const arg::Weights weights = argpg::to_weights(*PG_GETARG_ARG_WEIGHTS_P(2));
  argpg::GraphCacheHolder* cache = argpg::graph_cache(fcinfo);
  const argpg::GraphArg a = argpg::graph_arg(fcinfo, cache, 0, 0);
  const argpg::GraphArg b = argpg::graph_arg(fcinfo, cache, 1, 1);
  PairRow* rows = nullptr;
  std::size_t count = 0;
  argpg::Outcome out = argpg::guarded([&] {
    arg::ArgGraph scratch_a, scratch_b;
    const arg::ArgGraph& ga = argpg::graph_of(cache, 0, a, scratch_a);
    const arg::ArgGraph& gb = argpg::graph_of(cache, 1, b, scratch_b);
    arg::require_comparable(ga, gb);
    std::vector<arg::MatchPair> pairs;
    arg::arg_similarity(ga, gb, weights, &pairs);
    rows = copy_rows<PairRow, arg::MatchPair>(pairs, [](const arg::MatchPair& p) {
      return PairRow{p.level, p.a_node, p.b_node, p.group, p.loss, p.sim};
    });
    count = pairs.size();
  });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot match ARGs");

  InitMaterializedSRF(fcinfo, 0);
  ReturnSetInfo* rsinfo = reinterpret_cast<ReturnSetInfo*>(fcinfo->resultinfo);
  for (std::size_t i = 0; i < count; ++i) {
    const PairRow& row = rows[i];
    Datum values[6] = {Int32GetDatum(row.level),  Int32GetDatum(row.a_node),
                       Int32GetDatum(row.b_node), Int32GetDatum(row.group),
                       Float8GetDatum(row.loss),  Float8GetDatum(row.sim)};
    bool nulls[6] = {false, false, false, false, false, false};
    tuplestore_putvalues(rsinfo->setResult, rsinfo->setDesc, values, nulls);
  }
  return (Datum)0;
}

}  // extern "C"
