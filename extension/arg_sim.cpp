// arg_sim and the <~> operator: SIM(a, b) in [0, 1], 0 for the same shape.
#include "graph/serialize.hpp"
#include "match/similarity.hpp"
#include "match/weights.hpp"

#include "arg_bridge.hpp"

namespace {

double similarity(varlena* a, varlena* b, std::string_view weights) {
  double sim = 0;
  argpg::Outcome out = argpg::guarded([&] {
    const arg::Weights parsed = arg::parse_weights(weights);
    sim = arg::arg_similarity(arg::deserialize_arg(argpg::view(a)),
                              arg::deserialize_arg(argpg::view(b)), parsed);
  });
  argpg::raise_if_failed(out, ERRCODE_INVALID_PARAMETER_VALUE, "cannot compare ARGs");
  return sim;
}

}  // namespace

extern "C" {

PG_FUNCTION_INFO_V1(arg_sim);
PG_FUNCTION_INFO_V1(arg_distance);

// arg_sim(a arg, b arg, weights text DEFAULT 'arg')
Datum arg_sim(PG_FUNCTION_ARGS) {
  PG_RETURN_FLOAT8(
      similarity(PG_GETARG_ARG_PP(0), PG_GETARG_ARG_PP(1), argpg::view(PG_GETARG_TEXT_PP(2))));
}

// a <~> b: arg_sim with the default weights, for ORDER BY.
Datum arg_distance(PG_FUNCTION_ARGS) {
  PG_RETURN_FLOAT8(similarity(PG_GETARG_ARG_PP(0), PG_GETARG_ARG_PP(1), "arg"));
}

}  // extern "C"
