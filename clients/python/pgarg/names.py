"""SQL names given by the caller (tables, columns), composed as quoted identifiers, never as SQL text."""

from __future__ import annotations

from typing import Tuple, Union

from psycopg import sql

# "objects", ("museum", "objects") for a schema-qualified table, or an Identifier already made.
TableName = Union[str, Tuple[str, str], sql.Identifier]


def table_identifier(table: TableName) -> sql.Identifier:
    """The table as a quoted identifier; a dot in a plain string is part of the name."""
    if isinstance(table, sql.Identifier):
        return table
    if isinstance(table, str):
        return sql.Identifier(table)
    if isinstance(table, tuple) and len(table) == 2 and all(isinstance(p, str) for p in table):
        return sql.Identifier(*table)
    raise TypeError(f"table must be a name, a (schema, name) pair or a psycopg.sql.Identifier, "
                    f"not {table!r}")
