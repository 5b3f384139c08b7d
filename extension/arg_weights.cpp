// The `arg_weights` type's input and output. Text: what arg::parse_weights accepts (a preset,
// key=value pairs, or both) in, arg::format_weights (canonical, lossless) out. Binary: eleven
// float4, a byte of switches (and graph_on_proxy), three bytes of mixing weights and a byte of
// 1 - level_ratio in steps of 0.05 in network byte order, validated like text. The last byte is
// sent only when level_ratio is not 1, and may be missing (clients of 0.2.0 send 48 bytes),
// as may the three before it (clients of 0.1.0 send 45).
#include "arg_weights.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

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

constexpr uint32 kSign = 0x80000000u;

uint32 bits_of(float4 x) {
  uint32 b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

float4 float_of(uint32 b) {
  float4 x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

}  // namespace

int level_ratio_count(const ArgWeights& stored) {
  int count = 0;
  for (int k = 0; k < kLevelRatioBits; ++k)
    count |= (bits_of(stored.values[k]) & kSign) != 0 ? 1 << k : 0;
  return count;
}

ArgWeights without_level_ratio(const ArgWeights& stored) {
  ArgWeights plain = stored;
  for (int k = 0; k < kLevelRatioBits; ++k)
    plain.values[k] = float_of(bits_of(stored.values[k]) & ~kSign);
  return plain;
}

arg::Weights to_weights(const ArgWeights& stored) {
  arg::Weights w;
  const ArgWeights plain = without_level_ratio(stored);
  for (int i = 0; i < 11; ++i) w.*kFields[i] = plain.values[i];
  w.level_ratio = arg::mixing_weight(arg::kMaxLevelRatioSteps - level_ratio_count(stored));
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
  // Weights are at least 0; -0 is stored as 0, so that no sign bit is set but level_ratio's.
  for (int i = 0; i < 11; ++i) stored.values[i] = float_of(bits_of(weights.*kFields[i]) & ~kSign);
  const int proxy =
      std::clamp(arg::kMaxGraphOnProxySteps - arg::mixing_steps(weights.graph_on_proxy), 0,
                 arg::kMaxGraphOnProxySteps);
  stored.flags = uint8((weights.l2 ? kL2 : 0) | (weights.tung_rule ? kTungRule : 0) |
                       (weights.groups ? kGroups : 0) | (proxy << kProxyShift));
  stored.mixing[0] = uint8(arg::mixing_steps(weights.graph));
  stored.mixing[1] = uint8(arg::mixing_steps(weights.panorama));
  stored.mixing[2] = uint8(arg::mixing_steps(weights.spectrum));
  const int count = std::clamp(arg::kMaxLevelRatioSteps - arg::mixing_steps(weights.level_ratio), 0,
                               arg::kMaxLevelRatioSteps);
  for (int k = 0; k < kLevelRatioBits; ++k)
    if ((count >> k) & 1) stored.values[k] = float_of(bits_of(stored.values[k]) | kSign);
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
  int level_ratio = 0;  // 1 - level_ratio in steps; 0 when the byte is missing
  if (buf->cursor < buf->len) {
    for (uint8& m : received.mixing) m = uint8(pq_getmsgbyte(buf));
    if (buf->cursor < buf->len) level_ratio = pq_getmsgbyte(buf);
  }
  if (buf->cursor != buf->len)
    ereport(ERROR, (errcode(ERRCODE_INVALID_BINARY_REPRESENTATION),
                    errmsg("invalid binary input for type arg_weights: %d bytes after the value",
                           buf->len - buf->cursor)));
  if ((flags >> argpg::kProxyShift) > arg::kMaxGraphOnProxySteps)
    ereport(ERROR, (errcode(ERRCODE_INVALID_BINARY_REPRESENTATION),
                    errmsg("invalid binary input for type arg_weights: graph_on_proxy bits "
                           "0x%02x (1 - graph_on_proxy must be 0 to 20 steps of 0.05)",
                           flags >> argpg::kProxyShift)));
  if (level_ratio > arg::kMaxLevelRatioSteps)
    ereport(ERROR, (errcode(ERRCODE_INVALID_BINARY_REPRESENTATION),
                    errmsg("invalid binary input for type arg_weights: level_ratio byte %d "
                           "(1 - level_ratio must be 0 to 20 steps of 0.05)",
                           level_ratio)));
  received.flags = uint8(flags);
  // The same checks as text input: the canonical text of these weights must parse back to them.
  for (float4 x : received.values)
    if (std::signbit(x))
      ereport(ERROR, (errcode(ERRCODE_INVALID_BINARY_REPRESENTATION),
                      errmsg("invalid binary input for type arg_weights: a negative weight (%g)",
                             double(x))));
  argpg::Outcome out = argpg::guarded([&] {
    arg::Weights w = argpg::to_weights(received);
    w.level_ratio = arg::mixing_weight(arg::kMaxLevelRatioSteps - level_ratio);
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
  const argpg::ArgWeights plain = argpg::without_level_ratio(*weights);
  for (float4 x : plain.values) pq_sendfloat4(&buf, x);
  pq_sendbyte(&buf, weights->flags);
  for (uint8 m : weights->mixing) pq_sendbyte(&buf, m);
  if (const int count = argpg::level_ratio_count(*weights)) pq_sendbyte(&buf, count);
  PG_RETURN_BYTEA_P(pq_endtypsend(&buf));
}

}  // extern "C"
