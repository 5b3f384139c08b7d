"""The adapters against the server: arg and arg_weights in text and binary, compared with the server's own forms."""

from __future__ import annotations

import struct
from typing import Any

import psycopg
import pytest
from psycopg.adapt import Dumper
from psycopg.pq import Format

import pgarg
from pgarg import Arg, ArgWeights
from pgarg.weights_binary import pack_weights, unpack_weights

BUILD = "SELECT arg_build(arg_generate_model('cup', 1, 16))"
PRESETS = ["arg", "mrg", "graph", "shape", "colour",
           "shape lambda_3=2.125 alpha_l=0.1 graph_on_proxy=0.35 panorama=12.75 norm=l2 groups=on"]


@pytest.fixture
def value(conn: psycopg.Connection[Any]) -> Arg:
    return conn.execute(BUILD).fetchone()[0]


@pytest.mark.parametrize("binary", [False, True])
def test_arg_results_load_as_the_servers_bytes(conn: psycopg.Connection[Any], binary: bool) -> None:
    loaded = conn.execute(BUILD, binary=binary).fetchone()[0]
    assert isinstance(loaded, Arg)
    send, text = conn.execute(f"SELECT arg_send(a), a::text FROM ({BUILD}) v(a)").fetchone()
    assert loaded.data == send
    assert loaded.to_text() == text
    assert loaded.format_version == 3


@pytest.mark.parametrize("placeholder", ["%t", "%b", "%s"])
def test_arg_parameters_reach_the_server_unchanged(conn: psycopg.Connection[Any], value: Arg,
                                                    placeholder: str) -> None:
    same, send, type_name = conn.execute(
        f"SELECT a = ({BUILD}), arg_send(a), pg_typeof(a)::text FROM (SELECT {placeholder}) v(a)",
        (value,)).fetchone()
    assert same and send == value.data and type_name == "arg"


def test_arg_arrays_load_element_by_element(conn: psycopg.Connection[Any], value: Arg) -> None:
    for binary in (False, True):
        assert conn.execute(f"SELECT ARRAY[({BUILD}), NULL, ({BUILD})]", binary=binary).fetchone()[0] == [value, None, value]


def test_a_damaged_arg_is_refused_by_the_server(conn: psycopg.Connection[Any], value: Arg) -> None:
    damaged = bytearray(value.data)
    damaged[-1] ^= 1
    with pytest.raises(psycopg.errors.InvalidBinaryRepresentation):
        conn.execute("SELECT %b::text", (Arg(damaged),))


@pytest.mark.parametrize("preset", PRESETS)
@pytest.mark.parametrize("binary", [False, True])
def test_weights_results_load_as_the_server_prints_them(conn: psycopg.Connection[Any], preset: str,
                                                          binary: bool) -> None:
    loaded, text, send = conn.execute(
        "SELECT w, w::text, arg_weights_send(w) FROM (SELECT %s::arg_weights) v(w)", (preset,),
        binary=binary).fetchone()
    assert isinstance(loaded, ArgWeights)
    assert str(loaded) == text
    assert pack_weights(loaded) == send


@pytest.mark.parametrize("preset", PRESETS)
@pytest.mark.parametrize("placeholder", ["%t", "%b"])
def test_weights_parameters_reach_the_server_unchanged(conn: psycopg.Connection[Any], preset: str,
                                                        placeholder: str) -> None:
    weights = conn.execute("SELECT %s::arg_weights", (preset,)).fetchone()[0]
    same, type_name = conn.execute(
        f"SELECT arg_weights_send(w) = arg_weights_send(%s::arg_weights), pg_typeof(w)::text "
        f"FROM (SELECT {placeholder}) v(w)", (preset, weights)).fetchone()
    assert same and type_name == "arg_weights"


def test_client_defaults_are_the_servers_arg_preset(conn: psycopg.Connection[Any]) -> None:
    assert conn.execute("SELECT 'arg'::arg_weights").fetchone()[0] == ArgWeights()


def test_client_made_weights_equal_the_servers_reading(conn: psycopg.Connection[Any]) -> None:
    weights = ArgWeights(alpha_l=0.1, delta_l=1 / 3, lambda_4=0, graph=2, spectrum=0.05,
                         graph_on_proxy=0.4, tung=False)
    assert conn.execute("SELECT %s::arg_weights", (str(weights),)).fetchone()[0] == weights
    assert conn.execute("SELECT %t::text, %b::text", (weights, weights)).fetchone() == (str(weights),) * 2


class _RawWeights:
    """Bytes sent as the binary form of arg_weights exactly as given."""

    def __init__(self, data: bytes) -> None:
        self.data = data


def _send_raw(conn: psycopg.Connection[Any]) -> None:
    oid = psycopg.types.TypeInfo.fetch(conn, "arg_weights").oid
    dumper = type("RawDumper", (Dumper,), {"format": Format.BINARY, "oid": oid,
                                           "dump": lambda self, obj: obj.data})
    conn.adapters.register_dumper(_RawWeights, dumper)


@pytest.mark.parametrize("mixing", [bytes(3), bytes([20, 0, 0]), bytes([0, 50, 3])])
@pytest.mark.parametrize("proxy_steps", [0, 7, 20])
def test_binary_decoding_matches_the_servers(conn: psycopg.Connection[Any], mixing: bytes,
                                              proxy_steps: int) -> None:
    # Forms the client itself never writes (all mixing bytes zero, as stored before they
    # existed) read the same here and in the server.
    _send_raw(conn)
    data = pack_weights(ArgWeights())[:44] + bytes([2 | proxy_steps << 3]) + mixing
    server = conn.execute("SELECT %b::arg_weights::text", (_RawWeights(data),)).fetchone()[0]
    assert str(unpack_weights(data)) == server


@pytest.mark.parametrize("ratio", [1, 0.65, 0])
def test_level_ratio_reaches_the_server_and_back_in_both_forms(conn: psycopg.Connection[Any],
                                                                ratio: float) -> None:
    weights = ArgWeights(level_ratio=ratio)
    text, back = conn.execute("SELECT %s::arg_weights::text, %s::arg_weights",
                              (str(weights), str(weights))).fetchone()
    assert text == str(weights) and back == weights
    _send_raw(conn)
    assert conn.execute("SELECT %b::arg_weights::text", (_RawWeights(pack_weights(weights)),)).fetchone()[0] == text


def test_a_negative_weight_or_a_level_ratio_byte_out_of_range_is_refused(conn: psycopg.Connection[Any]) -> None:
    _send_raw(conn)
    negative = struct.pack(">f", -0.0) + pack_weights(ArgWeights())[4:]
    for data in (negative, pack_weights(ArgWeights()) + bytes([21])):
        with pytest.raises(psycopg.errors.InvalidBinaryRepresentation):
            conn.execute("SELECT %b::arg_weights", (_RawWeights(data),))


def test_graph_on_proxy_bits_out_of_range_are_refused_by_both(conn: psycopg.Connection[Any]) -> None:
    _send_raw(conn)
    data = pack_weights(ArgWeights())[:44] + bytes([21 << 3]) + bytes([20, 0, 0])
    with pytest.raises(psycopg.errors.InvalidBinaryRepresentation):
        conn.execute("SELECT %b::arg_weights", (_RawWeights(data),))
    with pytest.raises(ValueError):
        unpack_weights(data)


def test_register_without_the_extension_says_so(database: None) -> None:
    with psycopg.connect(autocommit=True) as conn:
        with pytest.raises(psycopg.ProgrammingError, match="CREATE EXTENSION arg"):
            pgarg.register_arg(conn, schema="pg_catalog")
