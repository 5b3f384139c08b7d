"""Fixtures: a connection to the test database (libpq's PG* variables) with the arg types registered."""

from __future__ import annotations

from typing import Any, Iterator

import psycopg
import pytest

import pgarg


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
