"""The browser's reads of the demo's table objects: the grid, one object, its thumbnail and graph, rankings."""

from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional

import psycopg
from psycopg import sql
from psycopg.rows import dict_row

import pgarg

TABLE = "objects"
# The metadata a reader can filter on, each a column of the table; the only names that reach SQL.
FILTERS = ("class", "period", "material", "artist")
# What a card or a ranked row shows; the mesh, the ARG and the thumbnail stay on the server.
COLUMNS = ["id", "model_id", "inventory_no", "title", "class", "artist", "period", "material",
           "file"]


def connect() -> psycopg.Connection[Any]:
    """A connection to the catalogue (libpq's PG* variables) with the arg types registered."""
    conn = psycopg.connect(autocommit=True, application_name="arg catalogue browser")
    pgarg.register_arg(conn)
    return conn


def chosen_filters(params: Mapping[str, str]) -> Dict[str, str]:
    """The filters a request asks for: known names with a non-empty value, in FILTERS' order."""
    return {name: params[name] for name in FILTERS if params.get(name)}


def filter_choices(conn: psycopg.Connection[Any]) -> Dict[str, List[str]]:
    """Each filter's values present in the table, sorted, for the drop-down lists."""
    choices: Dict[str, List[str]] = {}
    for name in FILTERS:
        rows = conn.execute(sql.SQL("SELECT DISTINCT {0} FROM {1} WHERE {0} <> '' ORDER BY 1").format(
            sql.Identifier(name), sql.Identifier(TABLE))).fetchall()
        choices[name] = [row[0] for row in rows]
    return choices


def models(conn: psycopg.Connection[Any], filters: Mapping[str, str]) -> List[Dict[str, Any]]:
    """The grid: every model that matches the filters, in catalogue order."""
    conditions = [sql.SQL("{} = %s").format(sql.Identifier(name)) for name in filters]
    where = sql.SQL(" AND ").join(conditions) if conditions else sql.SQL("true")
    statement = sql.SQL(
        "SELECT {columns}, thumbnail IS NOT NULL AS has_thumbnail FROM {table} WHERE {where} "
        "ORDER BY id").format(columns=sql.SQL(", ").join(map(sql.Identifier, COLUMNS)),
                              table=sql.Identifier(TABLE), where=where)
    with conn.cursor(row_factory=dict_row) as cur:
        return cur.execute(statement, list(filters.values())).fetchall()


def model(conn: psycopg.Connection[Any], model_id: int) -> Optional[Dict[str, Any]]:
    """One model's metadata, its ARG (descr) and its graph's number of levels; None when there is no such id."""
    statement = sql.SQL(
        "SELECT {columns}, descr, thumbnail IS NOT NULL AS has_thumbnail, "
        "(arg_info(descr)->>'levels')::int AS levels FROM {table} WHERE id = %s").format(
            columns=sql.SQL(", ").join(map(sql.Identifier, COLUMNS)), table=sql.Identifier(TABLE))
    with conn.cursor(row_factory=dict_row) as cur:
        return cur.execute(statement, (model_id,)).fetchone()


def thumbnail(conn: psycopg.Connection[Any], model_id: int) -> Optional[bytes]:
    """The PNG rendered at load time, or None."""
    row = conn.execute(sql.SQL("SELECT thumbnail FROM {} WHERE id = %s").format(
        sql.Identifier(TABLE)), (model_id,)).fetchone()
    return bytes(row[0]) if row and row[0] is not None else None


def graph_svg(conn: psycopg.Connection[Any], model_id: int, level: int) -> Optional[str]:
    """The server's arg_svg of one level; None when there is no such id (a bad level raises 22023)."""
    row = conn.execute(sql.SQL("SELECT arg_svg(descr, %s) FROM {} WHERE id = %s").format(
        sql.Identifier(TABLE)), (level, model_id)).fetchone()
    return row[0] if row else None


def ranked(conn: psycopg.Connection[Any], query: pgarg.Arg, k: int,
           filters: Mapping[str, str]) -> List[Dict[str, Any]]:
    """The k models most like `query` among those that match the filters, best first, each with its sim."""
    return pgarg.nearest(conn, TABLE, query, k, where=dict(filters), columns=COLUMNS)


def count(conn: psycopg.Connection[Any]) -> int:
    """How many models the catalogue holds."""
    row = conn.execute(sql.SQL("SELECT count(*) FROM {}").format(sql.Identifier(TABLE))).fetchone()
    return int(row[0]) if row else 0
