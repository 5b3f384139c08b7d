"""load_models on a folder of good meshes and one bad file: the bad one reported with its SQLSTATE, the rest loaded, a rerun loads nothing new."""

from __future__ import annotations

import hashlib
from pathlib import Path
from typing import Any, Dict

import psycopg
import pytest
from psycopg import sql

import pgarg

GOOD = ["chair_1.off", "cup_1.off", "cup_2.off", "more/vase_1_copy.OBJ", "torus_1.off",
        "torus_2.off", "vase_1.off"]


def rows(conn: psycopg.Connection[Any], table: str) -> Dict[str, str]:
    """sha256 -> title of every row that has an ARG."""
    return dict(conn.execute(sql.SQL("SELECT sha256, title FROM {} WHERE descr IS NOT NULL")
                             .format(sql.Identifier(table))).fetchall())


def title(path: Path) -> Dict[str, Any]:
    return {"title": path.stem, "class": path.stem.split("_")[0]}


def test_files_are_found_by_suffix_in_any_case(mesh_folder: Path) -> None:
    found = [p.relative_to(mesh_folder).as_posix() for p in pgarg.mesh_files(mesh_folder)]
    assert found == ["broken.off", "chair_1.off", "cup_1.off", "cup_2.off", "more/cup_1_again.off",
                     "more/vase_1_copy.OBJ", "torus_1.off", "torus_2.off", "vase_1.off"]
    assert pgarg.mesh_files([mesh_folder / "notes.txt"]) == [mesh_folder / "notes.txt"]
    with pytest.raises(FileNotFoundError):
        pgarg.mesh_files(mesh_folder / "missing")


def test_folder_loads_and_the_bad_file_is_reported(conn: psycopg.Connection[Any], table: str,
                                                   mesh_folder: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    report = pgarg.load_models(conn, table, mesh_folder, metadata=title, batch_size=4)
    assert sorted(p.relative_to(mesh_folder).as_posix() for p in report.loaded) == GOOD
    # The same bytes under another name are the same model.
    assert report.skipped == [mesh_folder / "more" / "cup_1_again.off"]
    assert [f.path for f in report.failed] == [mesh_folder / "broken.off"]
    failure = report.failed[0]
    with pytest.raises(psycopg.Error) as direct:
        pgarg.build(conn, (mesh_folder / "broken.off").read_bytes())
    assert failure.sqlstate == direct.value.sqlstate == "22023"
    assert failure.message == direct.value.diag.message_primary
    assert "OFF" in failure.message and isinstance(failure.error, psycopg.errors.InvalidParameterValue)
    # Nothing half-loaded: one row per good file, each with its ARG, its hash and its metadata.
    loaded = rows(conn, table)
    assert sorted(loaded.values()) == sorted(Path(name).stem for name in GOOD)
    assert loaded[hashlib.sha256((mesh_folder / "cup_2.off").read_bytes()).hexdigest()] == "cup_2"
    assert conn.execute(sql.SQL("SELECT count(*) FROM {} WHERE class = 'cup'")
                        .format(sql.Identifier(table))).fetchone()[0] == 2
    err = capsys.readouterr().err
    assert f"FAILED {mesh_folder / 'broken.off'}: SQLSTATE 22023: cannot build ARG" in err
    assert "9/9 files: 7 loaded, 1 already there, 1 failed" in err


def test_a_rerun_loads_nothing_new(conn: psycopg.Connection[Any], table: str, mesh_folder: Path) -> None:
    pgarg.load_models(conn, table, mesh_folder, metadata=title, progress=False)
    before = rows(conn, table)
    (mesh_folder / "cup_2.off").rename(mesh_folder / "renamed.off")
    again = pgarg.load_models(conn, table, [mesh_folder], metadata=title, progress=False)
    assert again.loaded == []
    assert len(again.skipped) == 8 and mesh_folder / "renamed.off" in again.skipped
    assert [f.sqlstate for f in again.failed] == ["22023"]
    assert rows(conn, table) == before


def test_an_error_that_is_not_the_files_stops_the_load(conn: psycopg.Connection[Any], table: str,
                                                        mesh_folder: Path) -> None:
    with pytest.raises(psycopg.errors.UndefinedColumn):
        pgarg.load_models(conn, table, mesh_folder, metadata=lambda p: {"no_such_column": 1},
                          progress=False)
    assert rows(conn, table) == {}


def test_each_batch_is_committed(conn: psycopg.Connection[Any], table: str, mesh_folder: Path) -> None:
    # A connection outside autocommit: the loaded batches are there for another session.
    with psycopg.connect() as other:
        pgarg.load_models(other, table, [mesh_folder / "cup_1.off", mesh_folder / "torus_1.off"],
                          batch_size=1, progress=False)
        assert other.info.transaction_status == psycopg.pq.TransactionStatus.IDLE
    assert len(rows(conn, table)) == 2


def test_a_cap_is_reported_per_file(conn: psycopg.Connection[Any], table: str, mesh_folder: Path) -> None:
    conn.execute("SET arg.max_vertices = 1000")
    small = conn.execute("SELECT arg_generate_model('torus', 3, 8)").fetchone()[0]
    (mesh_folder / "small.off").write_bytes(small)
    report = pgarg.load_models(conn, table, [mesh_folder / "small.off", mesh_folder / "cup_1.off"],
                               progress=False)
    assert report.loaded == [mesh_folder / "small.off"]
    assert [(f.path.name, f.sqlstate) for f in report.failed] == [("cup_1.off", "54000")]
