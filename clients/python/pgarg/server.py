"""One-value calls of the server's functions: build an ARG, read its info, its global descriptor."""

from __future__ import annotations

from typing import Any, Dict, Union

import numpy as np
import psycopg

from .value import Arg

Mesh = Union[bytes, bytearray, memoryview]


def build(conn: psycopg.Connection[Any], mesh: Mesh, options: str = "", texture: "Mesh | None" = None) -> Arg:
    """The server's ``arg_build(mesh, options)`` of mesh bytes (OFF, OBJ, PLY, STL or GLB); with
    ``texture`` (the image an OBJ keeps outside it), ``arg_build(mesh, texture, options)``, whose
    colours are sampled from it.

    A mesh the server refuses raises the psycopg error class of its SQLSTATE (say
    psycopg.errors.InvalidTextRepresentation for 22P02); ``error.sqlstate`` and
    ``error.diag.message_primary`` say what and where. Needs register_arg(conn) first.
    """
    if texture is None:
        row = conn.execute("SELECT arg_build(%b, %s)", (bytes(mesh), options)).fetchone()
    else:
        row = conn.execute("SELECT arg_build(%b, %b, %s)", (bytes(mesh), bytes(texture), options)).fetchone()
    assert row is not None
    return row[0]


def info(conn: psycopg.Connection[Any], value: Arg) -> Dict[str, Any]:
    """The server's ``arg_info``: levels, nodes per level, genus, triangles, options, versions."""
    row = conn.execute("SELECT arg_info(%s)", (value,)).fetchone()
    assert row is not None
    return row[0]


def global_vector(conn: psycopg.Connection[Any], value: Arg) -> "np.ndarray[Any, np.dtype[np.float64]]":
    """The server's ``arg_global_vector``: the 92-value global descriptor as a float64 array.

    For a whole table, select ``arg_global_vector(descr)`` and stack the rows with
    ``numpy.array(rows, dtype=numpy.float64)``.
    """
    row = conn.execute("SELECT arg_global_vector(%s)", (value,)).fetchone()
    assert row is not None
    return np.asarray(row[0], dtype=np.float64)
