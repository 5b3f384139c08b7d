// The `arg_weights` type: the matching weights as a fixed-length value (48 bytes, by reference).
#pragma once

#include "match/weights.hpp"

#include "arg_bridge.hpp"

namespace argpg {

// The stored form: the eleven weights of matching and sim in the order of arg::format_weights,
// the switches, then graph, panorama and spectrum as multiples of arg::kMixingStep. Unused bits
// are always zero, so equal weights are equal bytes. The three mixing bytes all zero is how
// values stored before they existed read: the graph alone (graph=1 panorama=0 spectrum=0),
// which a new value cannot be confused with (at least one of them must be positive). The top
// five bits of the switch byte hold 1 - graph_on_proxy in steps of arg::kMixingStep (0..20), so
// that a value stored before it existed (bits zero) reads as graph_on_proxy=1, as it meant. The
// sign bits of the first five floats (weights are never negative) hold 1 - level_ratio in the
// same steps, bit k of the count in values[k]: zero, as every value stored before level_ratio
// existed has them, reads as level_ratio=1. to_weights and from_weights are the only readers
// and writers of those bits; the binary form sends the count as a byte of its own.
struct ArgWeights {
  float4 values[11];
  uint8 flags;  // kL2, kTungRule, kGroups, and (1 - graph_on_proxy) << kProxyShift
  uint8 mixing[3];
};
static_assert(sizeof(ArgWeights) == 48, "arg_weights has INTERNALLENGTH = 48");

inline constexpr uint8 kL2 = 1, kTungRule = 2, kGroups = 4;
inline constexpr int kProxyShift = 3;      // bits 3..7 of the switch byte: graph_on_proxy
inline constexpr int kLevelRatioBits = 5;  // sign bits of values[0..4]: 1 - level_ratio

// 1 - level_ratio in steps of arg::kMixingStep (0..20), as the value holds it, and the value
// with those bits cleared (its floats as they read).
int level_ratio_count(const ArgWeights& stored);
ArgWeights without_level_ratio(const ArgWeights& stored);

// Plain conversions (no allocation, no exception): safe anywhere.
arg::Weights to_weights(const ArgWeights& stored);
ArgWeights from_weights(const arg::Weights& weights);

}  // namespace argpg

#define PG_GETARG_ARG_WEIGHTS_P(n) ((const argpg::ArgWeights*)PG_GETARG_POINTER(n))
