#!/usr/bin/env bash
# SQL benchmark of the extension (not a test): a museum table filled through its generated
# column, then ranked by shape with ORDER BY descr <~> $1 LIMIT 10.
#
#   bench/sql_bench.sh [--existing]
#
# Without --existing it starts a throwaway cluster under $BUILD_DIR/pg-bench and stops it at the
# end; with it, it uses the server in PGHOST/PGPORT/PGUSER (database arg_bench is dropped and made
# anew there). Expects the extension installed (make install). Environment:
#   MODELS=1000      models generated (arg_generate_model, the 9 classes in turn)
#   RESOLUTION=32    their resolution (grid cells along the longest side)
#   REPEATS=21       runs of the ranking query per setting; the median is reported
# Prints inserts per second, the median execution time of the ranking query with the query
# cache on and off (arg.query_cache), one EXPLAIN ANALYZE, and per-call times used for COST.
set -euo pipefail

cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
models=${MODELS:-1000}
resolution=${RESOLUTION:-32}
repeats=${REPEATS:-21}

if [[ "${1:-}" != --existing ]]; then
  pgdir=$build/pg-bench
  trap 'tools/pg/cluster.sh stop "$pgdir" --remove >/dev/null' EXIT
  tools/pg/cluster.sh start "$pgdir" --fresh
  # shellcheck disable=SC1091
  source "$pgdir/env"
fi

PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
  -c 'DROP DATABASE IF EXISTS arg_bench' -c 'CREATE DATABASE arg_bench'
run() { psql -X -q -d arg_bench -v ON_ERROR_STOP=1 "$@"; }
# Seconds (with fractions) that one SQL script takes, measured by the server.
seconds() {
  run -tA -c "SELECT extract(epoch FROM clock_timestamp())" >/tmp/arg_bench_t0.$$
  run "$@"
  local t0 t1
  t0=$(cat /tmp/arg_bench_t0.$$)
  t1=$(run -tA -c "SELECT extract(epoch FROM clock_timestamp())")
  rm -f /tmp/arg_bench_t0.$$
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

run -c 'CREATE EXTENSION arg CASCADE' -c 'SELECT arg_version()' -tA

echo "== generating $models models (resolution $resolution)"
gen_s=$(seconds -c "
  CREATE TABLE meshes AS
  SELECT i, c.class, i / 9 AS variant, arg_generate_model(c.class, i / 9, $resolution) AS mesh
  FROM generate_series(0, $models - 1) AS i,
       LATERAL (SELECT (ARRAY['vase','cup','amphora','torus','fourleg','human','table','chair',
                              'octopus'])[i % 9 + 1] AS class) AS c")
echo "generated in ${gen_s} s"

run -c "
  CREATE TABLE objects (
    id           int PRIMARY KEY,
    inventory_no text NOT NULL,
    title        text,
    artist       text,
    period       text,
    material     text,
    mesh         bytea NOT NULL,
    descr        arg GENERATED ALWAYS AS (arg_build(mesh)) STORED
  )"

echo "== inserting $models models through the generated column"
insert_s=$(seconds -c "
  INSERT INTO objects (id, inventory_no, title, period, material, mesh)
  SELECT i + 1, 'INV-' || lpad((i + 1)::text, 5, '0'), class || ' ' || variant,
         (ARRAY['Archaic','Classical','Roman','Modern'])[i % 4 + 1], 'terracotta', mesh
  FROM meshes ORDER BY i")
run -c 'VACUUM ANALYZE objects'
awk -v n="$models" -v s="$insert_s" \
  'BEGIN { printf "inserted in %.3f s: %.1f inserts/s, %.1f ms per insert\n", s, n / s, 1000 * s / n }'

# The ranking query of the README, with the query model as a bound parameter.
rank_sql="PREPARE rank(arg) AS
  SELECT id, inventory_no, title, descr <~> \$1 AS sim FROM objects ORDER BY descr <~> \$1 LIMIT 10;"
# The ranking query's script: a generic plan, so $1 is a real parameter as from a client; one
# session runs it once to warm its caches, then $repeats times under EXPLAIN ANALYZE.
rank_script() {  # $1: on|off (arg.query_cache), $2: EXPLAIN options, $3: runs
  cat <<SQL
SET arg.query_cache = $1;
SET plan_cache_mode = force_generic_plan;
$rank_sql
SELECT descr AS q FROM objects WHERE id = 1 \gset
EXECUTE rank(:'q') \g /dev/null
SQL
  for ((i = 0; i < $3; i++)); do echo "EXPLAIN ($2) EXECUTE rank(:'q');"; done
}

time_rank() {  # $1: on|off
  rank_script "$1" "ANALYZE, FORMAT JSON" "$repeats" | run -tA -f - |
    sed -nE 's/.*"Execution Time": ([0-9.]+).*/\1/p' | median
}

echo "== ranking $models rows: ORDER BY descr <~> \$1 LIMIT 10 ($repeats runs each)"
off_ms=$(time_rank off)
on_ms=$(time_rank on)
echo "median execution time, query cache off: ${off_ms} ms"
echo "median execution time, query cache on:  ${on_ms} ms"
awk -v a="$off_ms" -v b="$on_ms" -v n="$models" \
  'BEGIN { printf "per row: %.1f us without the cache, %.1f us with it\n", 1000 * a / n, 1000 * b / n }'

echo "== one EXPLAIN ANALYZE (query cache on)"
rank_script on "ANALYZE, BUFFERS" 1 | run -f -

echo "== the same query ranked by a filtered subset and joined with metadata"
run -c "EXPLAIN (ANALYZE, COSTS OFF)
  SELECT o.inventory_no, o.title, o.descr <~> q.descr AS sim
  FROM objects o, objects q WHERE q.id = 1 AND o.period = 'Roman'
  ORDER BY o.descr <~> q.descr LIMIT 10"

echo "== per-call times for COST (ms per row, median of 5)"
percall() {  # $1: label, $2: SQL over objects (one call per row); warm-up run first
  local ms
  ms=$({ echo "$2;"; for ((i = 0; i < 5; i++)); do echo "EXPLAIN (ANALYZE, FORMAT JSON) $2;"; done; } |
    run -tA -f - | sed -nE 's/.*"Execution Time": ([0-9.]+).*/\1/p' | median)
  awk -v l="$1" -v ms="$ms" -v n="$models" \
    'BEGIN { printf "  %-34s %10.4f ms per call (%.0f x 2.5 us)\n", l, ms / n, 400 * ms / n }'
}
percall "count(*) (scan only)" "SELECT count(*) FROM objects"
percall "arg_out (text output)" "SELECT sum(length(descr::text)) FROM objects"
percall "arg_in (text input, full check)" \
  "SELECT count(arg_in(arg_out(descr)::cstring)) FROM objects"
percall "<~> (query cache on)" "SELECT sum(descr <~> (SELECT descr FROM objects WHERE id = 1)) FROM objects"
percall "arg_sim, other weights" \
  "SELECT sum(arg_sim(descr, (SELECT descr FROM objects WHERE id = 1), 'mrg')) FROM objects"
percall "arg_info" "SELECT count(arg_info(descr)) FROM objects"
percall "arg_nodes" "SELECT count(*) FROM objects, arg_nodes(descr)"
percall "arg_svg" "SELECT sum(length(arg_svg(descr))) FROM objects"
percall "arg_part_match (level 2, node 0)" \
  "SELECT count(*) FROM objects o, arg_part_match((SELECT descr FROM objects WHERE id = 2), 2, 0, o.descr)"
awk -v g="$gen_s" -v s="$insert_s" -v n="$models" 'BEGIN {
  printf "  %-34s %10.4f ms per call (%.0f x 2.5 us)\n", "arg_generate_model", 1000 * g / n, 400000 * g / n
  printf "  %-34s %10.4f ms per call (%.0f x 2.5 us)\n", "arg_build (insert)", 1000 * s / n, 400000 * s / n }'
