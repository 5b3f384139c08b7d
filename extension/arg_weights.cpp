// The `arg_weights` type's input and output. Text: what arg::parse_weights accepts (a preset,
// key=value pairs, or both) in, arg::format_weights (canonical, lossless) out. Binary: eleven
// float4, a byte of switches (and graph_on_proxy) and three bytes of mixing weights in network
// byte order (the three bytes may be missing, as clients of 0.1.0 send it), validated like text.
#include "arg_weights.hpp"

#include <algorithm>

extern "C" {
#include "libpq/pqformat.h"
}

namespace argpg {

namespace {

// The order of arg::format_weights.
float arg::Weights::*const kFields[11] = {
    &arg::Weights::alpha_l,  &arg::Weights::beta_l,   &arg::Weights::gamma_l,
    &arg::Weights::delta_l,  &arg::Weights::eps_l,    &arg::Weights::alpha_s,
    &arg::Weights::beta_s,   &arg::Weights::lambda_1, &arg::Weights::lambda_2,
    &arg::Weights::lambda_3, &arg::Weights::lambda_4,
};

ArgWeights* copy_out(const ArgWeights& weights) {
  auto* result = static_cast<ArgWeights*>(palloc(sizeof(ArgWeights)));
  std::memcpy(result, &weights, sizeof weights);
  return result;
}

}  // namespace

arg::Weights to_weights(const ArgWeights& stored) {
  arg::Weights w;
  for (int i = 0; i < 11; ++i) w.*kFields[i] = stored.values[i];
  w.l2 = (stored.flags & kL2) != 0;
  w.tung_rule = (stored.flags & kTungRule) != 0;
  w.groups = (stored.flags & kGroups) != 0;
  float arg::Weights::*const mixing[3] = {&arg::Weights::graph, &arg::Weights::panorama,
                                          &arg::Weights::spectrum};
  const bool legacy = stored.mixing[0] == 0 && stored.mixing[1] == 0 && stored.mixing[2] == 0;
  for (int i = 0; i < 3; ++i)
    w.*mixing[i] = legacy ? (i == 0 ? 1.0f : 0.0f) : arg::mixing_weight(stored.mixing[i]);
  w.graph_on_proxy =
      arg::mixing_weight(arg::kMaxGraphOnProxySteps - (stored.flags >> argpg::kProxyShift));
  return w;
}

ArgWeights from_weights(const arg::Weights& weights) {
  ArgWeights stored;
  std::memset(&stored, 0, sizeof stored);
  for (int i = 0; i < 11; ++i) stored.values[i] = weights.*kFields[i];
  const int proxy =
      std::clamp(arg::kMaxGraphOnProxySteps - arg::mixing_steps(weights.graph_on_proxy), 0,
                 arg::kMaxGraphOnProxySteps);
  stored.flags = uint8((weights.l2 ? kL2 : 0) | (weights.tung_rule ? kTungRule : 0) |
                       (weights.groups ? kGroups : 0) | (proxy << kProxyShift));
  stored.mixing[0] = uint8(arg::mixing_steps(weights.graph));
  stored.mixing[1] = uint8(arg::mixing_steps(weights.panorama));
  stored.mixing[2] = uint8(arg::mixing_steps(weights.spectrum));
  return stored;
}

}  // namespace argpg

extern "C" {

PG_FUNCTION_INFO_V1(arg_weights_in);
PG_FUNCTION_INFO_V1(arg_weights_out);
PG_FUNCTION_INFO_V1(arg_weights_recv);
PG_FUNCTION_INFO_V1(arg_weights_send);

// 'arg', 'mrg', 'shape lambda_4=0.1', 'alpha_l=.3 beta_l=.15 ... groups=off'
Datum arg_weights_in(PG_FUNCTION_ARGS) {
  const char* input = PG_GETARG_CSTRING(0);
  argpg::ArgWeights parsed;
  argpg::Outcome out =
      argpg::guarded([&] { parsed = argpg::from_weights(arg::parse_weights(input)); });
  argpg::raise_if_failed(out, ERRCODE_INVALID_TEXT_REPRESENTATION,
                         "invalid input syntax for type arg_weights");
  PG_RETURN_POINTER(argpg::copy_out(parsed));
}

Datum arg_weights_out(PG_FUNCTION_ARGS) {
  const argpg::ArgWeights* weights = PG_GETARG_ARG_WEIGHTS_P(0);
  char* result = nullptr;
  argpg::Outcome out = argpg::guarded(
      [&] { result = argpg::to_cstring(arg::format_weights(argpg::to_weights(*weights))); });
  argpg::raise_if_failed(out, ERRCODE_DATA_CORRUPTED, "cannot output arg_weights value");
  PG_RETURN_CSTRING(result);
}

Datum arg_weights_recv(PG_FUNCTION_ARGS) {
  StringInfo buf = (StringInfo)PG_GETARG_POINTER(0);
  argpg::ArgWeights received;
  std::memset(&received, 0, sizeof received);
  for (float4& x : received.values) x = pq_getmsgfloat4(buf);
  const int flags = pq_getmsgbyte(buf);
  if (buf->cursor < buf->len)
    for (uint8& m : received.mixing) m = uint8(pq_getmsgbyte(buf));
  if (buf->cursor != buf->len)
    ereport(ERROR, (errcode(ERRCODE_INVALID_BINARY_REPRESENTATION),
                    errmsg("invalid binary input for type arg_weights: %d bytes after the value",
                           buf->len - buf->cursor)));
  if ((flags >> argpg::kProxyShift) > arg::kMaxGraphOnProxySteps)
    ereport(ERROR, (errcode(ERRCODE_INVALID_BINARY_REPRESENTATION),
                    errmsg("invalid binary input for type arg_weights: graph_on_proxy bits "
                           "0x%02x (1 - graph_on_proxy must be 0 to 20 steps of 0.05)",
                           flags >> argpg::kProxyShift)));
  received.flags = uint8(flags);
  // The same checks as text input: the canonical text of these weights must parse back to them.
  argpg::Outcome out = argpg::guarded([&] {
    const arg::Weights w = argpg::to_weights(received);
    if (!(arg::parse_weights(arg::format_weights(w)) == w))
      throw arg::InputError("weights: value does not survive its canonical text form");
    received = argpg::from_weights(w);  // a 0.1.0 value gets its mixing bytes spelled out
  });
  argpg::raise_if_failed(out, ERRCODE_INVALID_BINARY_REPRESENTATION,
                         "invalid binary input for type arg_weights");
  PG_RETURN_POINTER(argpg::copy_out(received));
}

Datum arg_weights_send(PG_FUNCTION_ARGS) {
  const argpg::ArgWeights* weights = PG_GETARG_ARG_WEIGHTS_P(0);
  StringInfoData buf;
  pq_begintypsend(&buf);
  for (float4 x : weights->values) pq_sendfloat4(&buf, x);
  pq_sendbyte(&buf, weights->flags);
  for (uint8 m : weights->mixing) pq_sendbyte(&buf, m);
  PG_RETURN_BYTEA_P(pq_endtypsend(&buf));
}

}  // extern "C"
