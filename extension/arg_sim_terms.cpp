// arg_sim_terms: SIM(a, b) broken into its terms and the graph's share per feature, to explain it.
#include "graph/comparable.hpp"
#include "match/similarity.hpp"
#include "match/similarity_terms.hpp"

#include "arg_cache.hpp"
#include "arg_weights.hpp"

// funcapi.h reaches PostgreSQL's spinlock headers, which use `register` (not C++17).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wregister"
extern "C" {
#include "funcapi.h"
#include "utils/builtins.h"
#include "utils/tuplestore.h"
}
#pragma GCC diagnostic pop

namespace {

constexpr int kRows = 9;

// Plain data, filled inside guarded() and emitted after it (no C++ object crosses a longjmp).
struct TermRow {
  const char* term;
  float8 weight, value, contribution;
  bool has_contribution;
};

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_sim_terms);

// arg_sim_terms(a arg, b arg, weights arg_weights DEFAULT 'arg')
//   RETURNS TABLE (term text, weight float8, value float8, contribution float8)
// The rows graph, panorama, spectrum first: their contributions, added in that order, are
// arg_sim(a, b, weights) to the bit (core's one mixing rule, match/term_weights.hpp). Then the
// graph's features, whose values add up to 1 - the graph's SIM (before its clamp); they have no
// contribution of their own.
Datum arg_sim_terms(PG_FUNCTION_ARGS) {
  const arg::Weights weights = argpg::to_weights(*PG_GETARG_ARG_WEIGHTS_P(2));
  argpg::GraphCacheHolder* cache = argpg::graph_cache(fcinfo);
  const argpg::GraphArg a = argpg::graph_arg(fcinfo, cache, 0, 0);
  const argpg::GraphArg b = argpg::graph_arg(fcinfo, cache, 1, 1);
  TermRow rows[kRows];
  argpg::Outcome out = argpg::guarded([&] {
    arg::ArgGraph scratch_a, scratch_b;
    const arg::ArgGraph& ga = argpg::graph_of(cache, 0, a, scratch_a);
    const arg::ArgGraph& gb = argpg::graph_of(cache, 1, b, scratch_b);
    arg::require_comparable(ga, gb);
    std::vector<arg::MatchPair> pairs;
    const arg::SimilarityParts p = arg::similarity_parts(ga, gb, weights, &pairs);
    const arg::SimilarityTerms t = arg::similarity_terms(ga, gb, weights, pairs);
    const arg::Weights& w = t.weights;
    rows[0] = {"graph", p.w_graph, p.graph, p.share_graph, true};
    rows[1] = {"panorama", p.w_panorama, p.panorama, p.share_panorama, true};
    rows[2] = {"spectrum", p.w_spectrum, p.spectrum, p.share_spectrum, true};
    rows[3] = {"graph.area", w.alpha_s, t.a, 0, false};
    rows[4] = {"graph.length", w.beta_s, t.l, 0, false};
    rows[5] = {"graph.volume", w.lambda_1, t.v, 0, false};
    rows[6] = {"graph.cords", w.lambda_2, t.cords, 0, false};
    rows[7] = {"graph.curvature", w.lambda_3, t.curvature, 0, false};
    rows[8] = {"graph.colour", w.lambda_4, t.colour, 0, false};
  });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot compare ARGs");

  InitMaterializedSRF(fcinfo, 0);
  ReturnSetInfo* rsinfo = reinterpret_cast<ReturnSetInfo*>(fcinfo->resultinfo);
  for (const TermRow& row : rows) {
    Datum values[4] = {CStringGetTextDatum(row.term), Float8GetDatum(row.weight),
                       Float8GetDatum(row.value), Float8GetDatum(row.contribution)};
    bool nulls[4] = {false, false, false, !row.has_contribution};
    tuplestore_putvalues(rsinfo->setResult, rsinfo->setDesc, values, nulls);
  }
  return (Datum)0;
}

}  // extern "C"
