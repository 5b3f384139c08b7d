"""load_models: mesh files into a table, batched and resumable; a file the server refuses is reported and the rest loads."""

from __future__ import annotations

import dataclasses
import hashlib
import os
import sys
from pathlib import Path
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Set, Tuple, Union

import psycopg
from psycopg import sql
from psycopg.adapt import PyFormat

from .names import TableName, table_identifier

MESH_SUFFIXES = (".off", ".obj", ".ply", ".stl", ".glb")
PathLike = Union[str, "os.PathLike[str]"]

# SQLSTATEs that say something about one file and leave the session usable: bad data (class
# 22: 22P02, 22023 for a bad mesh), a constraint the row breaks (23, say a duplicate inventory
# number from the metadata), a cap of arg_build (54000), one build out of memory (53200), an
# internal error of the build (XX). Anything else (an unknown column, a lost connection, a
# cancel) stops the load: it would fail every file the same way.
_PER_FILE_CLASSES = ("22", "23", "54", "XX")
_PER_FILE_STATES = ("53200",)


@dataclasses.dataclass(frozen=True)
class LoadFailure:
    """A file that was not loaded: the server's SQLSTATE and message, or None and why it could not be read."""

    path: Path
    sqlstate: Optional[str]
    message: str
    error: BaseException


@dataclasses.dataclass
class LoadReport:
    """What load_models did with each file, in the order the files were taken."""

    loaded: List[Path] = dataclasses.field(default_factory=list)
    skipped: List[Path] = dataclasses.field(default_factory=list)  # content already in the table
    failed: List[LoadFailure] = dataclasses.field(default_factory=list)


def mesh_files(paths_or_dir: Union[PathLike, Iterable[PathLike]]) -> List[Path]:
    """The files to load: the mesh files (by suffix, any case) under each folder, sorted, and
    each file given by name as it is. FileNotFoundError for a path that is neither."""
    items = [paths_or_dir] if isinstance(paths_or_dir, (str, os.PathLike)) else list(paths_or_dir)
    files: List[Path] = []
    for item in map(Path, items):
        if item.is_dir():
            files.extend(sorted(p for p in item.rglob("*")
                                if p.suffix.lower() in MESH_SUFFIXES and p.is_file()))
        elif item.is_file():
            files.append(item)
        else:
            raise FileNotFoundError(f"load_models: {item} is neither a file nor a folder")
    return files


def content_key(data: bytes) -> str:
    """How a file is identified: the SHA-256 of its bytes, in hex."""
    return hashlib.sha256(data).hexdigest()


def _is_per_file(error: psycopg.Error) -> bool:
    state = error.sqlstate or ""
    return state.startswith(_PER_FILE_CLASSES) or state in _PER_FILE_STATES


def _insert_statement(table: sql.Identifier, columns: List[str], mesh_column: str) -> sql.Composed:
    # The mesh goes as a binary bytea parameter: no hex escaping, half the bytes on the wire.
    values = [sql.Placeholder(format=PyFormat.BINARY if c == mesh_column else PyFormat.AUTO)
              for c in columns]
    return sql.SQL("INSERT INTO {} ({}) VALUES ({})").format(
        table, sql.SQL(", ").join(map(sql.Identifier, columns)), sql.SQL(", ").join(values))


def _read(path: Path, report: LoadReport, say: Callable[[str], None]) -> Optional[bytes]:
    try:
        return path.read_bytes()
    except OSError as error:
        report.failed.append(LoadFailure(path, None, str(error), error))
        say(f"load_models: FAILED {path}: cannot read: {error}")
        return None


def load_models(conn: psycopg.Connection[Any], table: TableName,
                paths_or_dir: Union[PathLike, Iterable[PathLike]], *,
                metadata: Optional[Callable[[Path], Mapping[str, Any]]] = None,
                mesh_column: str = "mesh", key_column: str = "sha256",
                batch_size: int = 20, progress: bool = True) -> LoadReport:
    """Loads mesh files (.off .obj .ply .stl .glb) into `table`, one row per file.

    The table builds the ARG itself (a generated column or arg_index_trigger, as the README
    shows); this sends each file's bytes as a bytea parameter into `mesh_column`, the SHA-256
    of the bytes in hex into `key_column` (text, best UNIQUE) and the columns `metadata(path)`
    returns (say ``{"title": path.stem}``).

    A file is identified by its content: one whose SHA-256 is already in `key_column` is
    skipped, so a second run loads only what the first did not (renamed or moved files are not
    loaded twice; an edited file is a new model, and its old row stays). Each batch of files is
    one transaction (committed at its end, unless `conn` is already inside a transaction, whose
    owner commits) and each file a savepoint in it: a file the server refuses (a bad mesh: its
    SQLSTATE's class is 22, 23, 54 or XX, or 53200) leaves no row and is reported with the
    server's SQLSTATE and message, and the rest loads; any other error stops the load and
    rolls back the batch under way. With `progress`, a line per batch and per failure goes to
    standard error.
    """
    if batch_size < 1:
        raise ValueError("batch_size must be at least 1")
    say = (lambda line: print(line, file=sys.stderr, flush=True)) if progress else (lambda line: None)
    target = table_identifier(table)
    files = mesh_files(paths_or_dir)
    report = LoadReport()
    known: Set[str] = set()
    for start in range(0, len(files), batch_size):
        batch: List[Tuple[Path, bytes, str]] = []
        for path in files[start:start + batch_size]:
            data = _read(path, report, say)
            if data is not None:
                batch.append((path, data, content_key(data)))
        with conn.transaction():
            found = conn.execute(
                sql.SQL("SELECT {key} FROM {table} WHERE {key} = ANY(%s)").format(
                    key=sql.Identifier(key_column), table=target),
                ([key for _, _, key in batch],)).fetchall()
            known.update(row[0] for row in found)
            for path, data, key in batch:
                if key in known:
                    report.skipped.append(path)
                    continue
                row: Dict[str, Any] = dict(metadata(path)) if metadata else {}
                row[mesh_column], row[key_column] = data, key
                try:
                    with conn.transaction():
                        conn.execute(_insert_statement(target, list(row), mesh_column), list(row.values()))
                except psycopg.Error as error:
                    if not _is_per_file(error):
                        raise
                    message = error.diag.message_primary or str(error)
                    report.failed.append(LoadFailure(path, error.sqlstate, message, error))
                    say(f"load_models: FAILED {path}: SQLSTATE {error.sqlstate}: {message}")
                    continue
                report.loaded.append(path)
                known.add(key)
        say(f"load_models: {min(start + batch_size, len(files))}/{len(files)} files: "
            f"{len(report.loaded)} loaded, {len(report.skipped)} already there, "
            f"{len(report.failed)} failed")
    return report
