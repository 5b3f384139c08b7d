"""nearest: the query first with SIM 0, `where` respected and never read as SQL, the two-stage search agreeing with brute force."""

from __future__ import annotations

from typing import Any, Iterator, List

import psycopg
import pytest
from psycopg import sql

import pgarg
from pgarg import Arg

CATALOGUE = "search_catalogue"
MODELS = [(c, v) for c in ("cup", "torus", "chair", "vase") for v in (1, 2, 3)]


@pytest.fixture(scope="module")
def catalogue(database: None) -> Iterator[str]:
    """A table of generated models (one without a class); the GiST index of the two-stage search."""
    with psycopg.connect(autocommit=True) as conn:
        conn.execute(f"DROP TABLE IF EXISTS {CATALOGUE}")
        conn.execute(f"""CREATE TABLE {CATALOGUE} (
                           id    serial PRIMARY KEY,
                           title text,
                           class text,
                           mesh  bytea,
                           descr arg GENERATED ALWAYS AS (arg_build(mesh)) STORED)""")
        for c, v in MODELS:
            conn.execute(f"INSERT INTO {CATALOGUE} (title, class, mesh) "
                         "VALUES (%s, %s, arg_generate_model(%s, %s, 16))", (f"{c}_{v}", c, c, v))
        conn.execute(f"INSERT INTO {CATALOGUE} (title, mesh) VALUES ('unclassified', arg_generate_model('octopus', 1, 16))")
        conn.execute(f"CREATE INDEX ON {CATALOGUE} USING gist (arg_global(descr))")
        conn.execute(f"ANALYZE {CATALOGUE}")
        yield CATALOGUE
        conn.execute(f"DROP TABLE {CATALOGUE}")


def descr_of(conn: psycopg.Connection[Any], title: str) -> Arg:
    return conn.execute(f"SELECT descr FROM {CATALOGUE} WHERE title = %s", (title,)).fetchone()[0]


def sims(rows: List[dict]) -> List[float]:
    return [row["sim"] for row in rows]


@pytest.mark.parametrize("candidates", [None, 5])
def test_the_query_comes_first_with_sim_0(conn: psycopg.Connection[Any], catalogue: str,
                                          candidates: Any) -> None:
    rows = pgarg.nearest(conn, catalogue, descr_of(conn, "cup_2"), k=4, candidates=candidates)
    assert len(rows) == 4
    assert rows[0]["title"] == "cup_2" and rows[0]["sim"] == 0
    assert sims(rows) == sorted(sims(rows)) and all(0 < s <= 1 for s in sims(rows)[1:])
    # The mesh and the ARG stay out of the rows unless asked for.
    assert list(rows[0]) == ["id", "title", "class", "sim"]


def test_sim_is_the_servers(conn: psycopg.Connection[Any], catalogue: str) -> None:
    query = descr_of(conn, "torus_1")
    rows = pgarg.nearest(conn, catalogue, query, k=13, columns=["title", "descr"])
    assert len(rows) == 13 and list(rows[0]) == ["title", "descr", "sim"]
    for row in rows:
        assert row["sim"] == conn.execute("SELECT %s <~> %s", (row["descr"], query)).fetchone()[0]


@pytest.mark.parametrize("candidates", [None, 100])
def test_where_keeps_only_matching_rows(conn: psycopg.Connection[Any], catalogue: str, candidates: Any) -> None:
    query = descr_of(conn, "cup_1")
    rows = pgarg.nearest(conn, catalogue, query, k=10, where={"class": "torus"}, candidates=candidates)
    assert [row["class"] for row in rows] == ["torus"] * 3 and rows[0]["sim"] > 0
    rows = pgarg.nearest(conn, catalogue, query, k=10, where={"class": None}, candidates=candidates)
    assert [row["title"] for row in rows] == ["unclassified"]
    rows = pgarg.nearest(conn, catalogue, query, k=10, where={"class": "cup", "title": "cup_3"},
                         candidates=candidates)
    assert [row["title"] for row in rows] == ["cup_3"]


@pytest.mark.parametrize("candidates", [None, 100])
def test_where_is_never_read_as_sql(conn: psycopg.Connection[Any], catalogue: str, candidates: Any) -> None:
    query = descr_of(conn, "cup_1")
    assert pgarg.nearest(conn, catalogue, query, where={"class": "cup' OR '1'='1"}, candidates=candidates) == []
    with pytest.raises(psycopg.errors.UndefinedColumn):
        pgarg.nearest(conn, catalogue, query, where={f'class" IS NOT NULL; DROP TABLE {catalogue}; --': 1},
                      candidates=candidates)
    with pytest.raises(TypeError):
        pgarg.nearest(conn, catalogue, query, where="class = 'cup'", candidates=candidates)  # type: ignore[arg-type]
    assert conn.execute(f"SELECT count(*) FROM {catalogue}").fetchone()[0] == len(MODELS) + 1


def test_two_stages_with_every_row_a_candidate_equal_brute_force(conn: psycopg.Connection[Any], catalogue: str) -> None:
    query = descr_of(conn, "chair_3")
    brute = pgarg.nearest(conn, catalogue, query, k=8)
    assert pgarg.nearest(conn, catalogue, query, k=8, candidates=100) == brute


def test_a_stored_descriptor_column_serves_the_first_stage(conn: psycopg.Connection[Any], catalogue: str) -> None:
    conn.execute("DROP TABLE IF EXISTS search_stored")
    conn.execute(f"CREATE TABLE search_stored AS SELECT id, title, class, descr FROM {catalogue}")
    conn.execute("ALTER TABLE search_stored ADD COLUMN glob cube GENERATED ALWAYS AS (arg_global(descr)) STORED")
    try:
        query = descr_of(conn, "vase_2")
        brute = pgarg.nearest(conn, catalogue, query, k=5)
        staged = pgarg.nearest(conn, ("public", "search_stored"), query, k=5, candidates=50, descriptor="glob")
        assert staged == brute
        with pytest.raises(psycopg.errors.UndefinedColumn):
            pgarg.nearest(conn, "search_stored", query, candidates=50, descriptor="title")
    finally:
        conn.execute("DROP TABLE search_stored")


def test_a_sketch_column_serves_a_third_stage(conn: psycopg.Connection[Any], catalogue: str) -> None:
    conn.execute("DROP TABLE IF EXISTS search_sketched")
    conn.execute(f"CREATE TABLE search_sketched AS SELECT id, title, class, descr FROM {catalogue}")
    conn.execute("ALTER TABLE search_sketched ADD COLUMN sk arg_sketch GENERATED ALWAYS AS (arg_sketch(descr)) STORED")
    try:
        query = descr_of(conn, "torus_2")
        brute = pgarg.nearest(conn, catalogue, query, k=5)
        # Every row a candidate and on the shortlist: the three stages are brute force; the
        # sketch column is hidden like the ARG.
        staged = pgarg.nearest(conn, "search_sketched", query, k=5, candidates=50, sketch="sk", shortlist=50)
        assert staged == brute
        assert "sk" not in staged[0]
        shortlisted = pgarg.nearest(conn, "search_sketched", query, k=3, candidates=50, sketch="sk", shortlist=6)
        assert shortlisted == brute[:3]
        with pytest.raises(psycopg.errors.UndefinedColumn):
            pgarg.nearest(conn, "search_sketched", query, candidates=50, sketch="title")
        with pytest.raises(ValueError):
            pgarg.nearest(conn, "search_sketched", query, shortlist=10)
        with pytest.raises(ValueError):
            pgarg.nearest(conn, "search_sketched", query, candidates=50, sketch="sk", shortlist=0)
        # An arg_ivf index on the sketch gives the shortlist itself: no candidates needed. With
        # every cell probed and every row on the shortlist, that is brute force again.
        conn.execute("CREATE INDEX search_sketched_sk ON search_sketched USING arg_ivf (sk) WITH (lists = 4)")
        conn.execute("SET arg.ivf_probes = 4")
        indexed = pgarg.nearest(conn, "search_sketched", query, k=5, sketch="sk", shortlist=50)
        assert indexed == brute
        # One cell holds fewer rows than asked for: the server ranks every other row too.
        conn.execute("SET arg.ivf_probes = 1")
        every = pgarg.nearest(conn, "search_sketched", query, k=50, sketch="sk", shortlist=50)
        assert every == pgarg.nearest(conn, catalogue, query, k=50)
    finally:
        conn.execute("RESET arg.ivf_probes")
        conn.execute("DROP TABLE search_sketched")


def test_arguments_are_checked(conn: psycopg.Connection[Any], catalogue: str) -> None:
    query = descr_of(conn, "cup_1")
    with pytest.raises(ValueError):
        pgarg.nearest(conn, catalogue, query, k=0)
    with pytest.raises(ValueError):
        pgarg.nearest(conn, catalogue, query, candidates=0)
    with pytest.raises(ValueError):
        pgarg.nearest(conn, catalogue, query, columns=["title", "sim"])
    with pytest.raises(TypeError):
        pgarg.nearest(conn, catalogue, query.data)  # type: ignore[arg-type]
    with pytest.raises(psycopg.errors.UndefinedTable):
        pgarg.nearest(conn, sql.Identifier("no such table"), query)
