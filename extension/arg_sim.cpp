// arg_sim and the <~> operator: SIM(a, b) in [0, 1], 0 for the same shape.
#include "graph/comparable.hpp"
#include "match/similarity.hpp"

#include "arg_cache.hpp"
#include "arg_weights.hpp"

namespace {

double similarity(FunctionCallInfo fcinfo, const arg::Weights& weights) {
  argpg::GraphCacheHolder* cache = argpg::graph_cache(fcinfo);
  const argpg::GraphArg args[2] = {argpg::graph_arg(fcinfo, cache, 0, 0),
                                   argpg::graph_arg(fcinfo, cache, 1, 1)};
  double sim = 0;
  argpg::Outcome out = argpg::guarded([&] {
    arg::ArgGraph scratch[2];
    const arg::ArgGraph* g[2] = {nullptr, nullptr};
    // A ranking: one argument repeats (its graph and prep kept), the other brings a row a
    // call, read straight into the matcher's keys when it can be (half of a row's time was
    // decoding it into node records and preparing it from them).
    if (const int query = argpg::repeating_slot(cache); query >= 0) {
      const int row = 1 - query;
      g[query] = &argpg::graph_of(cache, query, args[query], scratch[query]);
      const arg::MatchPrep* prep = argpg::match_prep_of(cache, query, weights);
      arg::PackedGraph* packed = arg::packs_rows(*g[query], prep, weights)
                                     ? argpg::packed_row_of(cache, row, args[row], weights)
                                     : nullptr;
      if (packed) {
        arg::require_comparable(query == 0 ? *g[0] : packed->head,
                                query == 0 ? packed->head : *g[1]);
        if (arg::packed_similarity(*g[query], prep, *packed, weights, sim)) return;
      }
    }
    for (int slot : {0, 1})
      if (!g[slot]) g[slot] = &argpg::graph_of(cache, slot, args[slot], scratch[slot]);
    // Checked on every call, on the graphs themselves: a cached query graph is no shortcut
    // around it, and a ranking stops at the first row built otherwise than the query.
    arg::require_comparable(*g[0], *g[1]);
    sim =
        arg::arg_similarity(*g[0], *g[1], weights, nullptr, argpg::match_prep_of(cache, 0, weights),
                            argpg::match_prep_of(cache, 1, weights));
  });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot compare ARGs");
  return sim;
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_sim);
PG_FUNCTION_INFO_V1(arg_distance);

// arg_sim(a arg, b arg, weights arg_weights DEFAULT 'arg')
Datum arg_sim(PG_FUNCTION_ARGS) {
  const arg::Weights weights = argpg::to_weights(*PG_GETARG_ARG_WEIGHTS_P(2));
  PG_RETURN_FLOAT8(similarity(fcinfo, weights));
}

// a <~> b: arg_sim with the default weights (the 'arg' preset), for ORDER BY.
Datum arg_distance(PG_FUNCTION_ARGS) {
  PG_RETURN_FLOAT8(similarity(fcinfo, arg::Weights{}));
}

}  // extern "C"
