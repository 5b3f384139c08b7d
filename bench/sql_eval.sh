#!/usr/bin/env bash
# The quality harness through SQL: loads a labelled set with arg_build, then computes nearest
# neighbour and first tier with ranking queries, to compare with `argtool eval`.
#
#   bench/sql_eval.sh [LABELS.csv]        (default: ../shared/data/shrec07/labels.csv)
#
# Needs the extension installed (make build && make install). Starts its own throwaway cluster
# in build/pg-eval (stopped on exit). Paths in the CSV are relative to its folder; the client
# reads the files (\lo_import), the server never touches them.
set -euo pipefail
cd "$(dirname "$0")/.."
LABELS=${1:-../shared/data/shrec07/labels.csv}
if [ ! -f "$LABELS" ]; then
  echo "sql_eval: $LABELS not found (the shared data is absent): nothing to do" >&2
  exit 0
fi
DIR=build/pg-eval
tools/pg/cluster.sh start "$DIR" --fresh > /dev/null
trap 'tools/pg/cluster.sh stop "$DIR" --remove > /dev/null' EXIT
# shellcheck disable=SC1091
source "$DIR/env"
export PGDATABASE=postgres
base=$(cd "$(dirname "$LABELS")" && pwd)
script=$(mktemp)
{
  echo "SET client_min_messages = warning;"
  echo "CREATE EXTENSION arg CASCADE;"
  echo "CREATE TABLE shapes (id int PRIMARY KEY, class text NOT NULL, mesh bytea NOT NULL,"
  echo "                     descr arg GENERATED ALWAYS AS (arg_build(mesh)) STORED);"
  n=0
  tail -n +2 "$LABELS" | tr -d "\r" | while IFS=, read -r _ path class; do
    n=$((n + 1))
    printf "\\\\lo_import '%s'\n\\\\set lo :LASTOID\n" "$base/$path"  # an INSERT resets LASTOID
    echo "INSERT INTO shapes (id, class, mesh) VALUES ($n, '$class', lo_get(:lo));"
    echo "SELECT lo_unlink(:lo) \\g /dev/null"
  done
} > "$script"
start=$(date +%s)
psql -X -q -v ON_ERROR_STOP=1 -f "$script" > "$DIR.load.log" || { tail -5 "$DIR.load.log"; exit 1; }
rm -f "$script"
echo "loaded $(psql -X -tAc 'SELECT count(*) FROM shapes') models through arg_build in $(( $(date +%s) - start )) s"
start=$(date +%s)
psql -X -v ON_ERROR_STOP=1 <<'SQL'
-- Every model queries all the others, ties broken by id as argtool eval breaks them by index.
WITH ranked AS (
  SELECT q.id AS query, q.class = c.class AS hit,
         row_number() OVER (PARTITION BY q.id ORDER BY q.descr <~> c.descr, c.id) AS rank
  FROM shapes q JOIN shapes c ON c.id <> q.id),
sizes AS (SELECT class, count(*) - 1 AS relevant FROM shapes GROUP BY class),
per_query AS (
  SELECT r.query,
         bool_or(r.hit AND r.rank = 1)::int AS nn,
         count(*) FILTER (WHERE r.hit AND r.rank <= s.relevant)::float8 / s.relevant AS ft
  FROM ranked r JOIN shapes q ON q.id = r.query JOIN sizes s ON s.class = q.class
  GROUP BY r.query, s.relevant)
SELECT count(*) AS queries, round(avg(nn), 3) AS nn, round(avg(ft)::numeric, 3) AS ft
FROM per_query;
SQL
echo "ranked in $(( $(date +%s) - start )) s; compare with: build/argtool eval --labels $LABELS"
