"""nearest: the rows of a table whose ARG is most like a query's, with their SIM, brute force or in stages."""

from __future__ import annotations

from typing import Any, Dict, List, Mapping, Optional, Sequence

import psycopg
from psycopg import sql
from psycopg.rows import dict_row
from psycopg.types.json import Jsonb

from .names import TableName, table_identifier
from .value import Arg

# Columns left out of the rows by default: the mesh and the descriptors are large and say
# nothing to a reader of the results.
_HIDDEN_TYPES = ("bytea", "arg", "cube", "arg_sketch")


def _default_columns(conn: psycopg.Connection[Any], table: sql.Identifier) -> List[str]:
    rows = conn.execute(
        """SELECT a.attname FROM pg_attribute a JOIN pg_type t ON t.oid = a.atttypid
           WHERE a.attrelid = %s::regclass AND a.attnum > 0 AND NOT a.attisdropped
             AND t.typname <> ALL(%s)
           ORDER BY a.attnum""",
        (table.as_string(conn), list(_HIDDEN_TYPES))).fetchall()
    return [row[0] for row in rows]


def _conditions(where: Mapping[str, Any]) -> "tuple[List[sql.Composable], List[Any]]":
    # Names become quoted identifiers and values parameters: nothing the caller passes is read
    # as SQL.
    conditions: List[sql.Composable] = []
    params: List[Any] = []
    for name, value in where.items():
        if value is None:
            conditions.append(sql.SQL("{} IS NULL").format(sql.Identifier(name)))
        else:
            conditions.append(sql.SQL("{} = %s").format(sql.Identifier(name)))
            params.append(value)
    return conditions, params


def nearest(conn: psycopg.Connection[Any], table: TableName, query: Arg, k: int = 10, *,
            where: Optional[Mapping[str, Any]] = None, candidates: Optional[int] = None,
            column: str = "descr", descriptor: Optional[str] = None,
            sketch: Optional[str] = None, shortlist: Optional[int] = None,
            columns: Optional[Sequence[str]] = None) -> List[Dict[str, Any]]:
    """The `k` rows of `table` whose ARG (in `column`) is most like `query`, best first.

    Each row is a dict of `columns` (by default every column that is not bytea, arg, cube or
    arg_sketch)
    and ``sim``, the server's ``descr <~> query`` (0: the same shape). Ties are broken by the
    ARG's canonical order, as arg_knn does. `where` keeps the rows whose columns equal the
    given values (None: IS NULL); names are quoted as identifiers and values sent as
    parameters, never read as SQL.

    Without `candidates` or `sketch` it sends the plain query (``ORDER BY descr <~> query LIMIT
    k``), which the server answers through the column's arg_ivf index when it has one and by
    comparing every row otherwise. With
    `candidates`, the
    search runs in two stages through the server's arg_knn: the `candidates` rows nearest by
    the global descriptor (``arg_global``, through a GiST index on ``arg_global(descr)``, or the
    stored cube column `descriptor`), ranked exactly by ``<~>``; there `where` is arg_knn's
    filter, whose values are compared as text (so JSON-serialisable scalars). With `sketch`
    (an arg_sketch column holding ``arg_sketch(descr)``) a third stage: the candidates are
    ordered by ``arg_sketch_distance`` and only the `shortlist` nearest (the server's default
    when None) are ranked by ``<~>``; when that column has an arg_ivf index and neither `where`
    nor `descriptor` is given, the shortlist comes straight from the index (`candidates` may
    then be left out). Needs register_arg(conn) first.
    """
    if not isinstance(query, Arg):
        raise TypeError("query must be an Arg (pgarg.build makes one from mesh bytes)")
    if k < 1:
        raise ValueError("k must be at least 1")
    if where is not None and not isinstance(where, Mapping):
        raise TypeError("where must be a mapping of column names to values, not SQL text")
    target = table_identifier(table)
    names = list(columns) if columns is not None else _default_columns(conn, target)
    if "sim" in names:
        raise ValueError("a column named sim would be hidden by the result's sim")
    if shortlist is not None and shortlist < 1:
        raise ValueError("shortlist must be at least 1")
    if shortlist is not None and sketch is None:
        raise ValueError("a shortlist needs a sketch column (sketch=...)")
    if candidates is None and sketch is None:
        conditions, params = _conditions(where or {})
        conditions.insert(0, sql.SQL("{} IS NOT NULL").format(sql.Identifier(column)))
        statement = sql.SQL(
            "SELECT {columns}{sep}{arg} <~> %s AS sim FROM {table} WHERE {conditions} "
            "ORDER BY sim, {arg} LIMIT %s").format(
                columns=sql.SQL(", ").join(map(sql.Identifier, names)),
                sep=sql.SQL(", ") if names else sql.SQL(""), arg=sql.Identifier(column),
                table=target, conditions=sql.SQL(" AND ").join(conditions))
        params = [query] + params + [k]
    else:
        if candidates is not None and candidates < 1:
            raise ValueError("candidates must be at least 1")
        fields = [sql.SQL("(k.o).{0} AS {0}").format(sql.Identifier(n)) for n in names]
        statement = sql.SQL(
            "SELECT {fields}{sep}k.sim FROM arg_knn(NULL::{table}, %s::name, %s, %s::int, "
            "%s::int, %s::jsonb, %s::name, %s::name, %s::int) AS k(o, sim)").format(
                fields=sql.SQL(", ").join(fields), sep=sql.SQL(", ") if names else sql.SQL(""),
                table=target)
        params = [column, query, k, candidates, Jsonb(dict(where)) if where else None, descriptor,
                  sketch, shortlist]
    with conn.cursor(row_factory=dict_row) as cur:
        return cur.execute(statement, params).fetchall()
