"""Fixtures: a connection to the test database (libpq's PG* variables) and meshes from the server's generator."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Dict, Iterator

import psycopg
import pytest
from psycopg import sql

import pgarg

# (class, variant) of the generated models the tests load; resolution 16 keeps each build short.
MODELS = [("cup", 1), ("cup", 2), ("torus", 1), ("torus", 2), ("chair", 1), ("vase", 1)]
RESOLUTION = 16


@pytest.fixture(scope="session")
def database() -> None:
    """The database in PGDATABASE, with the extension (created if missing)."""
    with psycopg.connect(autocommit=True) as conn:
        conn.execute("SET client_min_messages = warning")
        conn.execute("CREATE EXTENSION IF NOT EXISTS arg CASCADE")


@pytest.fixture
def conn(database: None) -> Iterator[psycopg.Connection[Any]]:
    """A connection in autocommit mode with the arg types registered."""
    with psycopg.connect(autocommit=True) as connection:
        pgarg.register_arg(connection)
        yield connection


@pytest.fixture(scope="session")
def meshes(database: None) -> Dict[str, bytes]:
    """OFF bytes of each generated model, by file name (class_variant.off)."""
    with psycopg.connect(autocommit=True) as connection:
        return {f"{c}_{v}.off": connection.execute(
                    "SELECT arg_generate_model(%s, %s, %s)", (c, v, RESOLUTION)).fetchone()[0]
                for c, v in MODELS}


def off_to_obj(off: bytes) -> bytes:
    """The same mesh as a Wavefront OBJ (the generator writes plain OFF: a header line, counts, vertices, faces)."""
    lines = [line for line in off.decode("ascii").splitlines() if line.strip()]
    n_vertices, n_faces = map(int, lines[1].split()[:2])
    vertices = lines[2:2 + n_vertices]
    faces = lines[2 + n_vertices:2 + n_vertices + n_faces]
    out = ["v " + v for v in vertices]
    out += ["f " + " ".join(str(int(i) + 1) for i in f.split()[1:]) for f in faces]
    return ("\n".join(out) + "\n").encode("ascii")


@pytest.fixture
def table(conn: psycopg.Connection[Any], request: pytest.FixtureRequest) -> Iterator[str]:
    """A new catalogue table named after the test, dropped after it; the ARG is a generated column."""
    name = "t_" + request.node.name.lower().replace("[", "_").replace("]", "")[:50]
    conn.execute(sql.SQL("DROP TABLE IF EXISTS {}").format(sql.Identifier(name)))
    conn.execute(sql.SQL(
        """CREATE TABLE {} (
             id     serial PRIMARY KEY,
             title  text,
             class  text,
             sha256 text UNIQUE,
             mesh   bytea,
             descr  arg GENERATED ALWAYS AS (arg_build(mesh)) STORED)""").format(
        sql.Identifier(name)))
    yield name
    conn.execute(sql.SQL("DROP TABLE {}").format(sql.Identifier(name)))


BAD_FILE = "broken.off"  # a cut-off copy of a good file: the server refuses it


@pytest.fixture
def mesh_folder(tmp_path: Path, meshes: Dict[str, bytes]) -> Path:
    """A folder of mesh files as a museum might have: the generated models as OFF, one of them
    also as OBJ with an upper-case suffix and another as the same bytes again in a subfolder, a
    cut-off file and a file that is no mesh."""
    folder = tmp_path / "scans"
    (folder / "more").mkdir(parents=True)
    for name, data in meshes.items():
        (folder / name).write_bytes(data)
    (folder / "more" / "vase_1_copy.OBJ").write_bytes(off_to_obj(meshes["vase_1.off"]))
    (folder / "more" / "cup_1_again.off").write_bytes(meshes["cup_1.off"])
    (folder / BAD_FILE).write_bytes(meshes["cup_1.off"][:300])
    (folder / "notes.txt").write_text("not a mesh\n")
    return folder
