"""The binary form of `arg_weights` (what arg_weights_send sends and arg_weights_recv reads)."""

from __future__ import annotations

import struct

from .weights import (MATCH_FIELDS, MAX_GRAPH_ON_PROXY_STEPS, MAX_LEVEL_RATIO_STEPS, MIXING_STEP,
                      ArgWeights, mixing_steps, mixing_weight)

# Eleven float4 in network byte order, a byte of switches, then graph, panorama and spectrum in
# steps of 0.05, one byte each (extension/arg_weights.cpp); then, only when level_ratio is not
# 1, a byte of 1 - level_ratio in steps of 0.05.
_LAYOUT = struct.Struct(">11fB3B")
SIZE = _LAYOUT.size  # 48
_L2, _TUNG, _GROUPS = 1, 2, 4
# The top five bits of the switch byte hold 1 - graph_on_proxy in steps of 0.05: zero bits (a
# value stored before graph_on_proxy existed) mean graph_on_proxy = 1.
_PROXY_SHIFT = 3


def pack_weights(weights: ArgWeights) -> bytes:
    """The binary form: 48 bytes, 49 when level_ratio is not 1."""
    proxy = MAX_GRAPH_ON_PROXY_STEPS - mixing_steps("graph_on_proxy", weights.graph_on_proxy)
    flags = ((_L2 if weights.norm == "l2" else 0) | (_TUNG if weights.tung else 0) |
             (_GROUPS if weights.groups else 0) | proxy << _PROXY_SHIFT)
    mixing = [mixing_steps(name, getattr(weights, name)) for name in ("graph", "panorama", "spectrum")]
    level = MAX_LEVEL_RATIO_STEPS - mixing_steps("level_ratio", weights.level_ratio)
    data = _LAYOUT.pack(*(getattr(weights, name) for name in MATCH_FIELDS), flags, *mixing)
    return data + bytes([level]) if level else data


def unpack_weights(data: bytes) -> ArgWeights:
    """Reads the binary form; ValueError for a length or switch byte the server never sends."""
    if len(data) not in (SIZE, SIZE + 1):
        raise ValueError(f"arg_weights: binary form of {len(data)} bytes (expected {SIZE} or {SIZE + 1})")
    level = data[SIZE] if len(data) > SIZE else 0
    if level > MAX_LEVEL_RATIO_STEPS:
        raise ValueError(f"arg_weights: level_ratio byte {level} (at most {MAX_LEVEL_RATIO_STEPS})")
    *values, flags, graph, panorama, spectrum = _LAYOUT.unpack(data[:SIZE])
    proxy = flags >> _PROXY_SHIFT
    if proxy > MAX_GRAPH_ON_PROXY_STEPS:
        raise ValueError(f"arg_weights: graph_on_proxy bits {proxy} (at most {MAX_GRAPH_ON_PROXY_STEPS})")
    # All three mixing bytes zero is how a value stored before they existed reads: the graph alone.
    if graph == panorama == spectrum == 0:
        graph = round(1.0 / MIXING_STEP)
    return ArgWeights(**dict(zip(MATCH_FIELDS, values)),
                      graph=mixing_weight(graph), panorama=mixing_weight(panorama),
                      spectrum=mixing_weight(spectrum),
                      graph_on_proxy=mixing_weight(MAX_GRAPH_ON_PROXY_STEPS - proxy),
                      level_ratio=mixing_weight(MAX_LEVEL_RATIO_STEPS - level),
                      norm="l2" if flags & _L2 else "l1", tung=bool(flags & _TUNG),
                      groups=bool(flags & _GROUPS))
