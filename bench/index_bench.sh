#!/usr/bin/env bash
# The arg_ivf index on an arg column against brute force (a benchmark, not a test; figures go to
# docs/BENCHMARKS.md "An index on the arg column"): recall@K of the plain query
# `SELECT id FROM objects [WHERE filter] ORDER BY descr <~> q LIMIT K` through the index
# against the same query over every row, and its server-side latency, for each setting of
# arg.ivf_probes and arg.ivf_candidates; unfiltered, and under filters that keep about 10% and
# 1% of the rows (museum among M1..M10, museum = 'M7': rows written with --museums 100).
#
#   bench/index_bench.sh ROWS.copy N QUERIES.copy [--existing]
#
# ROWS.copy: scale-gen rows (id, museum, period, class, arg), of which the first N are loaded
# (- reads them from standard input: a million rows are about 23 GB of text, so scale-gen
# writes them to a pipe); QUERIES.copy: rows of the same form, the query values (not in the
# table).
# Without --existing it starts a throwaway cluster under $BUILD_DIR/pg-index-bench
# (shared_buffers 4GB) and stops it at the end. Environment:
#   K=10  PROBES="8 16"  CANDIDATES="50 100 200"  FILTERS="none 10% 1%"  RUNS=2
#   REUSE=1   keep the table, the ground truth and the index between runs (same N)
#   TRUTH=FILE  the ground truth as `argtool knn` writes it (filter, query id, ids), instead
#               of brute force in SQL (one parallel scan a query: hours at a million rows)
#   DB=arg_index_bench  the database (one per table size keeps each one's table)
# Each query is run once to warm the caches, then RUNS times; latencies are the server's
# (clock_timestamp around the query in PL/pgSQL), one backend, no parallel workers.
set -euo pipefail

cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
rows_file=$1 n=$2 queries_file=$3
k=${K:-10} runs=${RUNS:-2}
probes_list=${PROBES:-"8 16"} candidates_list=${CANDIDATES:-"50 100 200"}
filters=${FILTERS:-"none 10% 1%"}
report=$build/scale/index_bench_$n.txt
mkdir -p "$build/scale"

if [[ "${4:-}" != --existing ]]; then
  pgdir=$build/pg-index-bench
  trap 'tools/pg/cluster.sh stop "$pgdir" >/dev/null' EXIT
  tools/pg/cluster.sh set "$pgdir" shared_buffers=4GB max_parallel_workers_per_gather=2 \
    maintenance_work_mem=1GB max_wal_size=8GB
  # shellcheck disable=SC1091
  source "$pgdir/env"
fi
db=${DB:-arg_index_bench}
psql -X -q -d postgres -tAc "SELECT 1 FROM pg_database WHERE datname = '$db'" | grep -q 1 ||
  psql -X -q -d postgres -c "CREATE DATABASE $db"
q() { psql -X -q -v ON_ERROR_STOP=1 -d $db "$@"; }
now_ms() { date +%s%3N; }

filter_sql() {
  case $1 in
    none) echo "true" ;;
    10%) echo "museum IN ('M1','M2','M3','M4','M5','M6','M7','M8','M9','M10')" ;;
    1%) echo "museum = 'M7'" ;;
  esac
}

loaded=$(q -tAc "SELECT CASE WHEN to_regclass('objects') IS NULL THEN 0 ELSE (SELECT count(*) FROM objects) END" 2>/dev/null || echo 0)
if [[ "${REUSE:-0}" != 1 || $loaded -ne $n ]]; then
  echo "index_bench: loading $n rows"
  q -c "DROP EXTENSION IF EXISTS arg CASCADE" -c "CREATE EXTENSION arg CASCADE" \
    -c "CREATE TABLE objects (id bigint PRIMARY KEY, museum text, period text, class text, descr arg)" \
    -c "CREATE TABLE queries (id bigint PRIMARY KEY, museum text, period text, class text, descr arg)" \
    -c "CREATE TABLE truth (filter text, qid bigint, ids bigint[], PRIMARY KEY (filter, qid))"
  t0=$(now_ms)
  if [[ $rows_file == - ]]; then head -n "$n"; else head -n "$n" "$rows_file"; fi |
    q -c "COPY objects FROM STDIN"
  echo "index_bench: COPY of $n rows in $(( $(now_ms) - t0 )) ms"
  q -c "COPY queries FROM STDIN" <"$queries_file"
  q -c "VACUUM ANALYZE objects" -c "VACUUM ANALYZE queries"
  if [[ -n ${TRUTH:-} ]]; then q -c "COPY truth FROM STDIN" <"$TRUTH"; fi
  for f in $filters; do
    [[ -n ${TRUTH:-} ]] && break
    t0=$(now_ms)
    # Brute force: every row compared (parallel workers allowed), ties by id.
    q -c "SET enable_indexscan = off" -c "
      INSERT INTO truth SELECT '$f', qq.id, (SELECT array_agg(id) FROM (
        SELECT o.id FROM objects o WHERE $(filter_sql "$f")
        ORDER BY o.descr <~> qq.descr, o.id LIMIT $k) s)
      FROM queries qq"
    echo "index_bench: brute force ($f) for every query in $(( $(now_ms) - t0 )) ms"
  done
  t0=$(now_ms)
  q -c "SET maintenance_work_mem = '1GB'" -c "SET arg.max_build_threads = 2" \
    -c "CREATE INDEX objects_descr ON objects USING arg_ivf (descr)"
  build_ms=$(( $(now_ms) - t0 ))
  q -c "CREATE TABLE build_stats AS SELECT $build_ms AS build_ms, pg_relation_size('objects_descr') AS bytes"
fi
read -r build_ms index_bytes < <(q -tA -F ' ' -c "SELECT build_ms, bytes FROM build_stats")

# One setting, one filter: every query warm once, then RUNS times, timed in the server.
q >/dev/null <<'SQL'
CREATE OR REPLACE FUNCTION bench_run(filter_sql text, k int, runs int)
RETURNS TABLE (qid bigint, run int, ms float8, ids bigint[]) LANGUAGE plpgsql AS $$
DECLARE qq record; t0 timestamptz; r int;
BEGIN
  FOR r IN 0..runs LOOP
    FOR qq IN SELECT id, descr FROM queries ORDER BY id LOOP
      t0 := clock_timestamp();
      EXECUTE format('SELECT array_agg(id) FROM (SELECT id FROM objects WHERE %s
                      ORDER BY descr <~> $1 LIMIT %s) s', filter_sql, k) INTO ids USING qq.descr;
      IF r > 0 THEN
        qid := qq.id; run := r; ms := extract(epoch FROM clock_timestamp() - t0) * 1000;
        RETURN NEXT;
      END IF;
    END LOOP;
  END LOOP;
END $$;
SQL

{
  echo "rows $n, queries $(q -tAc 'SELECT count(*) FROM queries'), K $k, index $((index_bytes / 1048576)) MB built in $((build_ms / 1000)) s"
  printf '%-6s %-7s %-10s %-10s %-10s %-10s %-8s\n' filter probes candidates recall median_ms p99_ms rows
} | tee "$report"
for f in $filters; do
  for p in $probes_list; do
    for c in $candidates_list; do
      q -tA -F ' ' -c "SET enable_seqscan = off" -c "SET max_parallel_workers_per_gather = 0" \
        -c "SET arg.ivf_probes = $p" -c "SET arg.ivf_candidates = $c" -c "
        WITH r AS (SELECT * FROM bench_run(\$\$$(filter_sql "$f")\$\$, $k, $runs))
        SELECT '$f', $p, $c,
               round(avg(cardinality(ARRAY(SELECT unnest(r.ids) INTERSECT SELECT unnest(t.ids)))::numeric
                         / greatest(cardinality(t.ids), 1)), 3),
               round(percentile_cont(0.5) WITHIN GROUP (ORDER BY ms)::numeric, 2),
               round(percentile_cont(0.99) WITHIN GROUP (ORDER BY ms)::numeric, 2),
               round(avg(coalesce(cardinality(r.ids), 0)), 1)
        FROM r JOIN truth t ON t.qid = r.qid AND t.filter = '$f'" |
        awk '{printf "%-6s %-7s %-10s %-10s %-10s %-10s %-8s\n", $1, $2, $3, $4, $5, $6, $7}' | tee -a "$report"
    done
  done
done
echo "index_bench: report in $report"
