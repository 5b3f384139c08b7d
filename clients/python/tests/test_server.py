"""build, info and global_vector: the server's answers, and its errors as psycopg exceptions with their SQLSTATE."""

from __future__ import annotations

from typing import Any, Dict

import numpy as np
import psycopg
import pytest

import pgarg
from pgarg import Arg


def test_build_returns_what_the_server_stores(conn: psycopg.Connection[Any], meshes: Dict[str, bytes]) -> None:
    built = pgarg.build(conn, meshes["torus_1.off"])
    assert built == conn.execute("SELECT arg_build(arg_generate_model('torus', 1, 16))").fetchone()[0]
    assert pgarg.build(conn, meshes["torus_1.off"], "levels=3") != built


def test_build_with_a_texture_samples_its_colours(conn: psycopg.Connection[Any], meshes: Dict[str, bytes]) -> None:
    # A 2 x 1 true-colour TGA: red and blue; the OBJ's texture coordinates pick the blue one.
    tga = bytes([0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 1, 0, 24, 0]) + bytes([0, 0, 255, 255, 0, 0])
    obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0.75 0.5\n" \
          b"f 1/1 3/1 2/1\nf 1/1 2/1 4/1\nf 1/1 4/1 3/1\nf 2/1 3/1 4/1\n"
    plain = pgarg.build(conn, obj)
    coloured = pgarg.build(conn, obj, texture=tga)
    assert pgarg.info(conn, plain)["has_colour"] is False
    assert pgarg.info(conn, coloured)["has_colour"] is True
    assert coloured == conn.execute("SELECT arg_build(%b, %b)", (obj, tga)).fetchone()[0]
    with pytest.raises(psycopg.errors.DataError):
        pgarg.build(conn, obj, texture=b"not an image")
    assert conn.execute("SELECT 1").fetchone()[0] == 1


@pytest.mark.parametrize("mesh, names", [(b"OFF\n3 1 0\n0 0 0\n", "OFF: line 2"),
                                         (b"solid nothing here", "STL: line 1"),
                                         (b"no mesh at all", "unrecognised mesh format")])
def test_a_bad_mesh_raises_the_servers_sqlstate(conn: psycopg.Connection[Any], mesh: bytes,
                                                 names: str) -> None:
    with pytest.raises(psycopg.errors.InvalidParameterValue) as caught:
        pgarg.build(conn, mesh)
    assert caught.value.sqlstate == "22023" and isinstance(caught.value, psycopg.DataError)
    assert caught.value.diag.message_primary.startswith("cannot build ARG: " + names)
    # The session goes on.
    assert conn.execute("SELECT 1").fetchone()[0] == 1


def test_a_mesh_over_a_cap_raises_54000(conn: psycopg.Connection[Any], meshes: Dict[str, bytes]) -> None:
    conn.execute("SET arg.max_vertices = 100")
    with pytest.raises(psycopg.errors.ProgramLimitExceeded) as caught:
        pgarg.build(conn, meshes["cup_1.off"])
    assert caught.value.sqlstate == "54000"


def test_options_the_server_refuses_raise_too(conn: psycopg.Connection[Any], meshes: Dict[str, bytes]) -> None:
    with pytest.raises(psycopg.DataError):
        pgarg.build(conn, meshes["cup_1.off"], "levels=banana")


def test_info_is_the_servers_json(conn: psycopg.Connection[Any], meshes: Dict[str, bytes]) -> None:
    value = pgarg.build(conn, meshes["cup_1.off"], "levels=4")
    described = pgarg.info(conn, value)
    assert described["levels"] == 4 and len(described["nodes_per_level"]) == 5
    assert described["bytes"] == len(value) and described["format_version"] == value.format_version


def test_global_vector_is_a_float64_array(conn: psycopg.Connection[Any], meshes: Dict[str, bytes]) -> None:
    value = pgarg.build(conn, meshes["chair_1.off"])
    vector = pgarg.global_vector(conn, value)
    assert isinstance(vector, np.ndarray) and vector.dtype == np.float64 and vector.shape == (92,)
    server = conn.execute("SELECT array_agg(x::text ORDER BY i) FROM unnest(arg_global_vector(%s)) "
                          "WITH ORDINALITY u(x, i)", (value,)).fetchone()[0]
    np.testing.assert_array_equal(vector, np.array([float(x) for x in server]))
    # The cube point the first stage of a two-stage search compares has the same coordinates.
    assert conn.execute("SELECT arg_global(%s) = cube(%s::float8[])", (value, list(vector))).fetchone()[0]
    assert np.abs(vector).sum() > 0
    other = pgarg.global_vector(conn, pgarg.build(conn, meshes["torus_1.off"]))
    assert not np.array_equal(vector, other)


def test_arg_values_need_no_server_to_compare(conn: psycopg.Connection[Any], meshes: Dict[str, bytes]) -> None:
    first, second = (pgarg.build(conn, meshes["vase_1.off"]) for _ in range(2))
    assert first == second and isinstance(first, Arg)
