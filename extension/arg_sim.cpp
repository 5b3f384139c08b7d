// arg_sim and the <~> operator: SIM(a, b) in [0, 1], 0 for the same shape.
#include "graph/comparable.hpp"
#include "match/similarity.hpp"

#include "arg_cache.hpp"
#include "arg_weights.hpp"

namespace {

double similarity(FunctionCallInfo fcinfo, const arg::Weights& weights) {
  argpg::GraphCacheHolder* cache = argpg::graph_cache(fcinfo);
  const argpg::GraphArg a = argpg::graph_arg(fcinfo, cache, 0, 0);
  const argpg::GraphArg b = argpg::graph_arg(fcinfo, cache, 1, 1);
  double sim = 0;
  argpg::Outcome out = argpg::guarded([&] {
    arg::ArgGraph scratch_a, scratch_b;
    const arg::ArgGraph& ga = argpg::graph_of(cache, 0, a, scratch_a);
    const arg::ArgGraph& gb = argpg::graph_of(cache, 1, b, scratch_b);
    // Checked on every call, on the graphs themselves: a cached query graph is no shortcut
    // around it, and a ranking stops at the first row built otherwise than the query.
    arg::require_comparable(ga, gb);
    sim = arg::arg_similarity(ga, gb, weights, nullptr, argpg::match_prep_of(cache, 0, weights),
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
