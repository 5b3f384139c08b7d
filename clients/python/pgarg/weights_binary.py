"""The binary form of `arg_weights` (what arg_weights_send sends and arg_weights_recv reads)."""

from __future__ import annotations

import struct

from .weights import (MATCH_FIELDS, MAX_GRAPH_ON_PROXY_STEPS, MIXING_STEP, ArgWeights,
                      mixing_steps, mixing_weight)

# Eleven float4 in network byte order, a byte of switches, then graph, panorama and spectrum in
# steps of 0.05, one byte each (extension/arg_weights.cpp).
_LAYOUT = struct.Struct(">11fB3B")
SIZE = _LAYOUT.size  # 48
_L2, _TUNG, _GROUPS = 1, 2, 4
# The top five bits of the switch byte hold 1 - graph_on_proxy in steps of 0.05: zero bits (a
# value stored before graph_on_proxy existed) mean graph_on_proxy = 1.
_PROXY_SHIFT = 3


def pack_weights(weights: ArgWeights) -> bytes:
    """The 48 bytes of the binary form."""
    proxy = MAX_GRAPH_ON_PROXY_STEPS - mixing_steps("graph_on_proxy", weights.graph_on_proxy)
    flags = ((_L2 if weights.norm == "l2" else 0) | (_TUNG if weights.tung else 0) |
             (_GROUPS if weights.groups else 0) | proxy << _PROXY_SHIFT)
    mixing = [mixing_steps(name, getattr(weights, name)) for name in ("graph", "panorama", "spectrum")]
    return _LAYOUT.pack(*(getattr(weights, name) for name in MATCH_FIELDS), flags, *mixing)


def unpack_weights(data: bytes) -> ArgWeights:
    """Reads the binary form; ValueError for a length or switch byte the server never sends."""
    if len(data) != SIZE:
        raise ValueError(f"arg_weights: binary form of {len(data)} bytes (expected {SIZE})")
    *values, flags, graph, panorama, spectrum = _LAYOUT.unpack(data)
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
                      norm="l2" if flags & _L2 else "l1", tung=bool(flags & _TUNG),
                      groups=bool(flags & _GROUPS))
