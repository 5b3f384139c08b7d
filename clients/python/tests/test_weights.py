"""ArgWeights without a server: float4 rounding, the canonical text and the 48- or 49-byte binary form."""

from __future__ import annotations

import struct

import pytest

from pgarg import ArgWeights
from pgarg.weights_binary import pack_weights, unpack_weights

ODD = ArgWeights(alpha_l=0.1, beta_l=1e6, gamma_l=0, delta_l=1 / 3, eps_l=123.456,
                 lambda_2=2.5e-7, graph=0.05, panorama=12.75, spectrum=0,
                 graph_on_proxy=0, norm="l2", tung=False, groups=True)


def test_weights_are_kept_as_float4() -> None:
    w = ArgWeights(alpha_l=0.1)
    assert w.alpha_l == struct.unpack("<f", struct.pack("<f", 0.1))[0]
    assert w.alpha_l != 0.1
    assert w == ArgWeights(alpha_l=w.alpha_l)


def test_canonical_text_uses_the_shortest_exact_digits() -> None:
    text = str(ArgWeights())
    assert text.startswith("alpha_l=0.3 beta_l=0.15 ")
    assert text.endswith(" graph=1 panorama=2.5 spectrum=0.75 graph_on_proxy=0.75 level_ratio=1 norm=l1 tung=on groups=off")
    assert "delta_l=0.33333334" in str(ODD)  # 1/3 needs eight digits as a float4
    assert "beta_l=1e+06" in str(ODD)


@pytest.mark.parametrize("weights", [ArgWeights(), ODD, ArgWeights(lambda_4=0, graph_on_proxy=1),
                                     ArgWeights(level_ratio=0.65), ArgWeights(level_ratio=0)])
def test_text_and_binary_read_back(weights: ArgWeights) -> None:
    assert ArgWeights.parse(str(weights)) == weights
    data = pack_weights(weights)
    assert len(data) == (48 if weights.level_ratio == 1 else 49)
    assert unpack_weights(data) == weights


def test_level_ratio_is_a_byte_of_its_own_sent_only_when_not_1() -> None:
    assert pack_weights(ArgWeights(level_ratio=0.65))[48] == 7  # 1 - 0.65 = 7 steps of 0.05
    assert pack_weights(ArgWeights(level_ratio=0.65))[:48] == pack_weights(ArgWeights())
    with pytest.raises(ValueError):
        ArgWeights(level_ratio=1.05)


def test_text_of_a_server_before_level_ratio_reads_as_ratio_1() -> None:
    old = str(ArgWeights()).replace(" level_ratio=1", "")
    assert ArgWeights.parse(old) == ArgWeights()


def test_binary_layout() -> None:
    data = pack_weights(ODD)
    assert struct.unpack(">f", data[:4])[0] == ODD.alpha_l  # network byte order
    # switches: l2 (1), no Tung rule (2), groups (4); 1 - graph_on_proxy = 20 steps in bits 3..7
    assert data[44] == 1 | 4 | 20 << 3
    assert list(data[45:]) == [1, 255, 0]
    assert pack_weights(ArgWeights())[44] == 2 | 5 << 3


def test_zero_mixing_bytes_read_as_the_graph_alone() -> None:
    old = pack_weights(ArgWeights())[:45] + bytes(3)
    w = unpack_weights(old)
    assert (w.graph, w.panorama, w.spectrum) == (1, 0, 0)


@pytest.mark.parametrize("data", [bytes(47), bytes(50), pack_weights(ArgWeights()) + bytes([21]),
                                  pack_weights(ArgWeights())[:44] + bytes([21 << 3]) + bytes(3)])
def test_binary_the_server_never_sends_is_refused(data: bytes) -> None:
    with pytest.raises(ValueError):
        unpack_weights(data)


@pytest.mark.parametrize("change", [{"graph": 0.07}, {"panorama": 12.8}, {"graph_on_proxy": 1.05},
                                    {"spectrum": -0.05}, {"alpha_l": -1}, {"lambda_1": float("nan")},
                                    {"norm": "l3"}])
def test_values_the_type_cannot_hold_are_refused(change: dict) -> None:
    with pytest.raises(ValueError):
        ArgWeights(**change)


@pytest.mark.parametrize("text", ["mrg", "shape lambda_4=0.1", str(ArgWeights()).replace(" groups=off", ""),
                                  str(ArgWeights()) + " extra=1", str(ArgWeights()).replace("tung=on", "tung=yes"),
                                  str(ArgWeights()) + " alpha_l=0.3"])
def test_only_the_canonical_text_parses(text: str) -> None:
    with pytest.raises(ValueError):
        ArgWeights.parse(text)


def test_replace_checks_the_new_value() -> None:
    assert ArgWeights().replace(lambda_4=0).lambda_4 == 0
    with pytest.raises(ValueError):
        ArgWeights().replace(graph=0.01)
