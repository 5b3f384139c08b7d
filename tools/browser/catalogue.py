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


def thumbnail(conn: psycopg.Connection[Any], model_id: int, mu: bool = False) -> Optional[bytes]:
    """A PNG rendered at load time, in the object's own colours or (mu) coloured by mu; or None."""
    row = conn.execute(sql.SQL("SELECT {} FROM {} WHERE id = %s").format(
        sql.Identifier("thumbnail_mu" if mu else "thumbnail"), sql.Identifier(TABLE)), (model_id,)).fetchone()
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


# The "more like this" choices of appearance: the reader's word, the arg_weights preset it stands
# for. Shape and colour is the default preset, whose ranking goes through <~> (and its index).
APPEARANCE = {"shape": "shape", "shape-colour": "arg", "colour": "colour"}
APPEARANCE_LABELS = {"shape": "shape only", "shape-colour": "shape and colour", "colour": "colour first"}
DEFAULT_APPEARANCE = "shape-colour"


def appearance(value: Optional[str]) -> str:
    """The appearance a request asks for; anything unknown is the default."""
    return value if value in APPEARANCE else DEFAULT_APPEARANCE


def ranked_with(conn: psycopg.Connection[Any], query: pgarg.Arg, k: int, filters: Mapping[str, str],
                look: str) -> List[Dict[str, Any]]:
    """`ranked` with the weights of an appearance: the server's arg_sim under that preset, best first."""
    weights = APPEARANCE[look]
    if weights == "arg":
        return ranked(conn, query, k, filters)
    conditions = [sql.SQL("{} = %s").format(sql.Identifier(name)) for name in filters]
    where = sql.SQL(" AND ").join(conditions) if conditions else sql.SQL("true")
    # Ties broken by the ARG's canonical order, as the default ranking breaks them.
    statement = sql.SQL(
        "SELECT {columns}, arg_sim(descr, %s, %s::arg_weights) AS sim FROM {table} "
        "WHERE descr IS NOT NULL AND {where} ORDER BY sim, descr LIMIT %s").format(
            columns=sql.SQL(", ").join(map(sql.Identifier, COLUMNS)), table=sql.Identifier(TABLE),
            where=where)
    with conn.cursor(row_factory=dict_row) as cur:
        return cur.execute(statement, [query, weights, *filters.values(), k]).fetchall()


def has_up(conn: psycopg.Connection[Any]) -> bool:
    """Whether the table keeps each file's up axis (tools/demo/load.sql makes the column `up`; a
    table made otherwise may not have it, and its pictures then find up from the shape)."""
    return conn.execute("SELECT EXISTS (SELECT FROM information_schema.columns WHERE table_name = %s "
                        "AND column_name = 'up' AND table_schema = ANY (current_schemas(false)))",
                        (TABLE,)).fetchone()[0]


def material_textures(conn: psycopg.Connection[Any], model_id: int) -> Dict[str, bytes]:
    """Each material's texture image of an object (an OBJ's, by usemtl name) from the table
    object_textures that tools/demo/load.sql makes; none when the database has no such table."""
    if conn.execute("SELECT to_regclass('object_textures') IS NULL").fetchone()[0]:
        return {}
    rows = conn.execute("SELECT material, image FROM object_textures WHERE object_id = %s",
                        (model_id,)).fetchall()
    return {material: bytes(image) for material, image in rows}


def stored_mesh(conn: psycopg.Connection[Any], model_id: int) -> Optional[Dict[str, Any]]:
    """The mesh as stored, its file name, its number of triangles, the texture stored beside it
    (an OBJ's) and each of its materials' (`materials`), the build options of its stored ARG (a picture's graph must be that one) and the
    file's up axis from the catalogue ('' when none); None when there is no such id."""
    statement = sql.SQL(
        "SELECT file, mesh, texture, (arg_info(descr)->>'triangles')::bigint AS triangles, "
        "coalesce(arg_info(descr)->>'options', '') AS options, {} AS up "
        "FROM {} WHERE id = %s").format(sql.SQL("coalesce(up, '')" if has_up(conn) else "''"),
                                        sql.Identifier(TABLE))
    with conn.cursor(row_factory=dict_row) as cur:
        row = cur.execute(statement, (model_id,)).fetchone()
    for column in ("mesh", "texture"):
        if row is not None and row[column] is not None:
            row[column] = bytes(row[column])
    if row is not None:
        row["materials"] = material_textures(conn, model_id)
    return row


def sim_terms(conn: psycopg.Connection[Any], a: pgarg.Arg, b: pgarg.Arg,
              weights: str) -> "tuple[float, List[Dict[str, Any]]]":
    """arg_sim(a, b) and arg_sim_terms(a, b) under a preset, in one statement (one snapshot)."""
    with conn.cursor(row_factory=dict_row) as cur:
        rows = cur.execute(
            "SELECT s.sim, t.term, t.weight, t.value, t.contribution "
            "FROM (SELECT arg_sim(%(a)s, %(b)s, %(w)s::arg_weights) AS sim) s, "
            "arg_sim_terms(%(a)s, %(b)s, %(w)s::arg_weights) WITH ORDINALITY AS t "
            "ORDER BY t.ordinality", {"a": a, "b": b, "w": weights}).fetchall()
    return (rows[0]["sim"] if rows else 0.0), rows


def best_matches(conn: psycopg.Connection[Any], a: pgarg.Arg, b: pgarg.Arg, weights: str,
                 level: int) -> List[Dict[str, Any]]:
    """The matched groups at one level (arg_matches), best (largest share of sim) first."""
    with conn.cursor(row_factory=dict_row) as cur:
        return cur.execute(
            "SELECT match_group, array_agg(DISTINCT a_node ORDER BY a_node) AS a_nodes, "
            "array_agg(DISTINCT b_node ORDER BY b_node) AS b_nodes, max(sim) AS sim "
            "FROM arg_matches(%s, %s, %s::arg_weights) WHERE level = %s "
            "GROUP BY match_group ORDER BY max(sim) DESC, match_group",
            (a, b, weights, level)).fetchall()


def node_count(conn: psycopg.Connection[Any], model_id: int, level: int) -> Optional[int]:
    """How many nodes a model's graph has at a level (0 for a level it lacks); None when there is no such id."""
    row = conn.execute(sql.SQL(
        "SELECT (SELECT count(*) FROM arg_nodes(descr) n WHERE n.level = %s) FROM {} WHERE id = %s").format(
            sql.Identifier(TABLE)), (level, model_id)).fetchone()
    return None if row is None else int(row[0])


def part_matches(conn: psycopg.Connection[Any], query_id: int, level: int, node: int,
                 k: int) -> List[Dict[str, Any]]:
    """The other models with a part like node `node` of `level` of model `query_id`: each with its
    best part (arg_part_match, lowest score first), best first; models without one are left out."""
    statement = sql.SQL(
        "SELECT {columns}, p.candidate_level AS part_level, p.candidate_node AS part_node, p.score "
        "FROM {table} q, {table} o CROSS JOIN LATERAL ("
        "  SELECT * FROM arg_part_match(q.descr, %s, %s, o.descr) ORDER BY score LIMIT 1) p "
        "WHERE q.id = %s AND o.id <> q.id ORDER BY p.score, o.id LIMIT %s").format(
            columns=sql.SQL(", ").join(sql.Identifier("o", c) for c in COLUMNS), table=sql.Identifier(TABLE))
    with conn.cursor(row_factory=dict_row) as cur:
        return cur.execute(statement, (level, node, query_id, k)).fetchall()
