#!/usr/bin/env bash
# Scale benchmark (not a test; run by hand, numbers go to docs/BENCHMARKS.md "Scale"): brute
# force (ORDER BY descr <~> q LIMIT 10, every row compared) against the two-stage search
# (candidates nearest by arg_global's <#>, ranked by <~>), side by side on SHREC 2007 and on
# generated catalogues of 1k, 10k and 100k models, with and without a selective filter
# (museum = 'M7', about 1/20 of the rows). The first stage either walks a GiST index on
# arg_global(descr) (with btree_gist, on (museum, arg_global(descr)) under the filter) or scans
# a stored column glob = arg_global(descr). The three-stage search orders the scan's candidates
# by arg_sketch_distance on a stored column sk = arg_sketch(descr) and ranks only a shortlist of
# them by <~>. The index search takes the shortlist straight from an arg_ivf index on sk (the
# lists of the arg.ivf_probes cells nearest to the query). Then brute force with 0, 1 and 2
# parallel workers.
#
#   tests/scale/bench_two_stage.sh [--existing]
#
# Without --existing it starts a throwaway cluster under $BUILD_DIR/pg-scale-bench (shared_buffers
# 1GB) and stops it at the end; with it, it uses the server in PGHOST/PGPORT/PGUSER. Environment:
#   SIZES="1000 10000 100000"   generated catalogue sizes (the first rows of GEN_COPY)
#   GEN_COPY=$BUILD_DIR/scale/gen100k.copy  made with `argtool scale-gen --count 100000` if missing
#   SHREC_COPY=$BUILD_DIR/scale/shrec07.copy  made from ../shared/data/shrec07 if missing (skipped
#                                             when neither exists)
#   QUERIES=20                  query models per table (spread over the ids; each is in the table)
#   CANDIDATES="100 300 1000 3000"  candidate counts of the two-stage search
#   SHORTLISTS="100 300"        shortlist counts of the three-stage search (each below a count
#                               of CANDIDATES) and of the index search
#   PROBES="8 16 32"            arg.ivf_probes of the index search (shown as its candidates;
#                               the index has the default lists, the square root of the rows)
#   PARALLEL_QUERIES=3          queries per worker count in the parallel measurement
#   REUSE=1                     keep the database arg_scale_bench and its tables between runs
#                               (and the extension as it was installed then: after changing
#                               extension/arg--*.sql, run without REUSE)
# Latencies are server-side wall times of each query (serial: max_parallel_workers_per_gather
# = 0, warm caches); recall@10 is |two-stage top 10 ∩ brute-force top 10| / 10, averaged.
set -euo pipefail

cd "$(dirname "$0")/../.."
build=${BUILD_DIR:-build}
sizes=${SIZES:-"1000 10000 100000"}
queries=${QUERIES:-20}
candidates=${CANDIDATES:-"100 300 1000 3000"}
shortlists=${SHORTLISTS:-"100 300"}
probes=${PROBES:-"8 16 32"}
par_queries=${PARALLEL_QUERIES:-3}
gen_copy=${GEN_COPY:-$build/scale/gen100k.copy}
shrec_copy=${SHREC_COPY:-$build/scale/shrec07.copy}
shrec_labels=../shared/data/shrec07/labels.csv
report=$build/scale/bench_two_stage.txt
mkdir -p "$build/scale"
max_size=$(tr ' ' '\n' <<<"$sizes" | sort -n | tail -n 1)

if [[ "${1:-}" != --existing ]]; then
  pgdir=$build/pg-scale-bench
  trap 'tools/pg/cluster.sh stop "$pgdir" >/dev/null' EXIT
  tools/pg/cluster.sh set "$pgdir" shared_buffers=1GB max_parallel_workers_per_gather=2
  # shellcheck disable=SC1091
  source "$pgdir/env"
fi

db=arg_scale_bench
if [[ "${REUSE:-0}" != 1 ]] || ! psql -X -d "$db" -c 'SELECT 1' >/dev/null 2>&1; then
  PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
    -c "DROP DATABASE IF EXISTS $db" -c "CREATE DATABASE $db"
fi
run() { PGOPTIONS='-c client_min_messages=warning' psql -X -q -d "$db" -v ON_ERROR_STOP=1 "$@"; }
now() { date +%s.%N; }
say() { echo "$*" | tee -a "$report"; }
: >"$report"

run <<'SQL'
CREATE EXTENSION IF NOT EXISTS arg CASCADE;
CREATE EXTENSION IF NOT EXISTS btree_gist;
-- Runs one ranking query (with $1 the query model) and returns its ids, in order, and its time.
CREATE OR REPLACE FUNCTION bench_ids(sql text, q arg, OUT ids int[], OUT ms float8)
LANGUAGE plpgsql AS $$
DECLARE t0 timestamptz := clock_timestamp();
BEGIN
  EXECUTE 'SELECT array_agg(id) FROM (' || sql || ') s' INTO ids USING q;
  ms := 1000 * extract(epoch FROM clock_timestamp() - t0);
END $$;
CREATE TABLE IF NOT EXISTS bench_results (
  tbl text, qid int, method text, cand int, filtered bool, ids int[], ms float8);
TRUNCATE bench_results;
SQL

say "# bench_two_stage $(date -u +%FT%TZ) on $(nproc) cores; arg $(run -tA -c 'SELECT arg_version()')"
say "load average: $(cut -d' ' -f1-3 /proc/loadavg)"

# --- data ---------------------------------------------------------------------------------------
if [[ ! -f "$gen_copy" ]]; then
  echo "== generating $max_size models into $gen_copy (argtool scale-gen)"
  "$build/argtool" scale-gen --count "$max_size" --out "$gen_copy" --threads "$(nproc)" --seed 1
fi
if [[ ! -f "$shrec_copy" && -f "$shrec_labels" ]]; then
  "$build/argtool" scale-gen --labels "$shrec_labels" --cache "$build/arg-cache" --out "$shrec_copy"
fi

create_table() {  # NAME
  run -c "CREATE TABLE $1 (id int PRIMARY KEY, museum text NOT NULL, period text, class text,
                           descr arg NOT NULL,
                           glob cube GENERATED ALWAYS AS (arg_global(descr)) STORED,
                           sk arg_sketch GENERATED ALWAYS AS (arg_sketch(descr)) STORED)"
}
table_exists() { [[ $(run -tA -c "SELECT to_regclass('$1') IS NOT NULL") == t ]]; }

tables=()
if [[ -f "$shrec_copy" ]]; then
  table_exists shrec || { create_table shrec && run -c "\\copy shrec (id, museum, period, class, descr) FROM '$shrec_copy'"; }
  tables+=(shrec)
fi
big=gen_$max_size
if ! table_exists "$big"; then
  create_table "$big"
  t0=$(now)
  run -c "\\copy $big (id, museum, period, class, descr) FROM PROGRAM 'head -n $max_size $gen_copy'"
  t1=$(now)
  say "$(awk -v n="$max_size" -v a="$t0" -v b="$t1" 'BEGIN { printf "ingest: COPY of %d prebuilt ARGs (text form, fully validated by arg_in; glob computed) in %.1f s: %.0f rows/s", n, b - a, n / (b - a) }')"
fi
for n in $sizes; do
  [[ $n == "$max_size" ]] && continue
  table_exists "gen_$n" || { create_table "gen_$n" && run -c "INSERT INTO gen_$n (id, museum, period, class, descr) SELECT id, museum, period, class, descr FROM $big WHERE id <= $n ORDER BY id"; }
done
for n in $sizes; do tables+=("gen_$n"); done

for t in "${tables[@]}"; do
  # A table kept from a run before the sketch existed gets its column (a rewrite of the table).
  if [[ $(run -tA -c "SELECT count(*) FROM pg_attribute WHERE attrelid = '$t'::regclass AND attname = 'sk'") == 0 ]]; then
    t0=$(now)
    run -c "ALTER TABLE $t ADD COLUMN sk arg_sketch GENERATED ALWAYS AS (arg_sketch(descr)) STORED" -c "VACUUM ANALYZE $t"
    say "$(awk -v t="$t" -v a="$t0" -v b="$(now)" 'BEGIN { printf "sketch column added to %s in %.1f s", t, b - a }')"
  fi
  if [[ $(run -tA -c "SELECT count(*) FROM pg_indexes WHERE tablename = '$t' AND indexname = '${t}_global'") == 0 ]]; then
    t0=$(now)
    run -c "CREATE INDEX ${t}_global ON $t USING gist (arg_global(descr))"
    t1=$(now)
    run -c "CREATE INDEX ${t}_museum_global ON $t USING gist (museum, arg_global(descr))"
    t2=$(now)
    run -c "VACUUM ANALYZE $t"
    say "$(awk -v t="$t" -v a="$t0" -v b="$t1" -v c="$t2" 'BEGIN { printf "index build on %s: GiST (arg_global) %.1f s, GiST (museum, arg_global) %.1f s", t, b - a, c - b }')"
  fi
  if [[ $(run -tA -c "SELECT count(*) FROM pg_indexes WHERE tablename = '$t' AND indexname = '${t}_sk_ivf'") == 0 ]]; then
    t0=$(now)
    run -c "SET maintenance_work_mem = '256MB'" -c "SET arg.max_build_threads = 2" \
        -c "CREATE INDEX ${t}_sk_ivf ON $t USING arg_ivf (sk)"
    say "$(awk -v t="$t" -v a="$t0" -v b="$(now)" 'BEGIN { printf "index build on %s: arg_ivf (sk), 2 threads, %.1f s", t, b - a }')"
  fi
done

say ""
say "## sizes"
run -c "SELECT t AS table, n AS rows,
          pg_size_pretty(pg_total_relation_size(t::regclass)) AS total,
          pg_size_pretty(pg_relation_size(t::regclass)) AS heap,
          pg_size_pretty(pg_total_relation_size(t::regclass) - pg_relation_size(t::regclass)
                         - pg_indexes_size(t::regclass)) AS toast,
          pg_size_pretty(pg_relation_size((t || '_global')::regclass)) AS gist_global,
          pg_size_pretty(pg_relation_size((t || '_museum_global')::regclass)) AS gist_museum_global,
          pg_size_pretty(pg_relation_size((t || '_sk_ivf')::regclass)) AS arg_ivf_sk,
          (SELECT round(avg(pg_column_size(descr))) FROM (SELECT descr FROM $big LIMIT 1000) s) AS arg_bytes_avg_gen,
          (SELECT round(avg(pg_column_size(sk))) FROM (SELECT sk FROM $big LIMIT 1000) s) AS sketch_bytes_avg_gen,
          (SELECT count(*) FILTER (WHERE museum = 'M7') FROM $big) AS m7_rows_in_biggest
        FROM unnest(ARRAY['$(IFS=,; echo "${tables[*]}" | sed "s/,/','/g")']) AS t,
             LATERAL (SELECT reltuples::bigint AS n FROM pg_class WHERE oid = t::regclass) c" | tee -a "$report"

# --- brute force vs two stage -------------------------------------------------------------------
for t in "${tables[@]}"; do
  echo "== $t: $queries queries, brute force and two-stage (candidates: $candidates)"
  run <<SQL
SET max_parallel_workers_per_gather = 0;
DO \$\$
DECLARE
  t text := '$t';
  n int := (SELECT count(*) FROM $t);
  qid int;
  q arg;
  c int;
  sl int;
  p int;
  f bool;
  w text;
  r record;
  brute text := format('SELECT id FROM %I ORDER BY descr <~> \$1, id LIMIT 10', t);
  brute_f text := format('SELECT id FROM %I WHERE museum = ''M7'' ORDER BY descr <~> \$1, id LIMIT 10', t);
BEGIN
  -- Warm-up: read the whole table once.
  PERFORM bench_ids(brute, (SELECT descr FROM $t ORDER BY id LIMIT 1));
  FOR i IN 0 .. $queries - 1 LOOP
    SELECT id, descr INTO qid, q FROM $t ORDER BY id OFFSET (i * n / $queries) LIMIT 1;
    SELECT * INTO r FROM bench_ids(brute, q);
    INSERT INTO bench_results VALUES (t, qid, 'brute', NULL, false, r.ids, r.ms);
    SELECT * INTO r FROM bench_ids(brute_f, q);
    INSERT INTO bench_results VALUES (t, qid, 'brute', NULL, true, r.ids, r.ms);
    FOREACH c IN ARRAY '{$(tr ' ' ',' <<<"$candidates")}'::int[] LOOP
      FOREACH f IN ARRAY ARRAY[false, true] LOOP
        w := CASE WHEN f THEN 'WHERE museum = ''M7''' ELSE '' END;
        -- GiST: the planner prices each probe as a random read, so keep it on the index.
        PERFORM set_config('enable_seqscan', 'off', true);
        SELECT * INTO r FROM bench_ids(format('WITH c AS MATERIALIZED (SELECT id, descr FROM %I %s
                                 ORDER BY arg_global(descr) <#> arg_global(\$1) LIMIT %s)
                               SELECT id FROM c ORDER BY descr <~> \$1, id LIMIT 10', t, w, c), q);
        INSERT INTO bench_results VALUES (t, qid, 'two-stage, GiST', c, f, r.ids, r.ms);
        PERFORM set_config('enable_seqscan', 'on', true);
        SELECT * INTO r FROM bench_ids(format('WITH c AS MATERIALIZED (SELECT id, descr FROM %I %s
                                 ORDER BY glob <#> arg_global(\$1) LIMIT %s)
                               SELECT id FROM c ORDER BY descr <~> \$1, id LIMIT 10', t, w, c), q);
        INSERT INTO bench_results VALUES (t, qid, 'two-stage, glob scan', c, f, r.ids, r.ms);
        FOREACH sl IN ARRAY '{$(tr ' ' ',' <<<"$shortlists")}'::int[] LOOP
          CONTINUE WHEN sl >= c;
          SELECT * INTO r FROM bench_ids(format('WITH c AS MATERIALIZED (SELECT id, descr, sk FROM %I %s
                                   ORDER BY glob <#> arg_global(\$1) LIMIT %s),
                                 s AS MATERIALIZED (SELECT id, descr FROM c
                                   ORDER BY arg_sketch_distance(sk, arg_sketch(\$1)) LIMIT %s)
                               SELECT id FROM s ORDER BY descr <~> \$1, id LIMIT 10', t, w, c, sl), q);
          INSERT INTO bench_results VALUES (t, qid, 'three-stage, shortlist ' || sl, c, f, r.ids, r.ms);
        END LOOP;
      END LOOP;
    END LOOP;
    FOREACH p IN ARRAY '{$(tr ' ' ',' <<<"$probes")}'::int[] LOOP
      PERFORM set_config('arg.ivf_probes', p::text, true);
      FOREACH sl IN ARRAY '{$(tr ' ' ',' <<<"$shortlists")}'::int[] LOOP
        FOREACH f IN ARRAY ARRAY[false, true] LOOP
          w := CASE WHEN f THEN 'WHERE museum = ''M7''' ELSE '' END;
          SELECT * INTO r FROM bench_ids(format('WITH s AS MATERIALIZED (SELECT id, descr FROM %I %s
                                   ORDER BY sk <~> arg_sketch(\$1) LIMIT %s)
                                 SELECT id FROM s ORDER BY descr <~> \$1, id LIMIT 10', t, w, sl), q);
          INSERT INTO bench_results VALUES (t, qid, 'arg_ivf, shortlist ' || sl, p, f, r.ids, r.ms);
        END LOOP;
      END LOOP;
    END LOOP;
    PERFORM set_config('arg.ivf_probes', '16', true);
    SELECT * INTO r FROM bench_ids(format('SELECT (o).id FROM arg_knn(NULL::%I, ''descr'', \$1, 10, sketch => ''sk'') AS k(o, sim)', t), q);
    INSERT INTO bench_results VALUES (t, qid, 'arg_knn, arg_ivf', 16, false, r.ids, r.ms);
    SELECT * INTO r FROM bench_ids(format('SELECT (o).id FROM arg_knn(NULL::%I, ''descr'', \$1, 10) AS k(o, sim)', t), q);
    INSERT INTO bench_results VALUES (t, qid, 'arg_knn, GiST', 1000, false, r.ids, r.ms);
    SELECT * INTO r FROM bench_ids(format('SELECT (o).id FROM arg_knn(NULL::%I, ''descr'', \$1, 10, filter => ''{"museum": "M7"}'') AS k(o, sim)', t), q);
    INSERT INTO bench_results VALUES (t, qid, 'arg_knn, GiST', 1000, true, r.ids, r.ms);
    SELECT * INTO r FROM bench_ids(format('SELECT (o).id FROM arg_knn(NULL::%I, ''descr'', \$1, 10, descriptor => ''glob'') AS k(o, sim)', t), q);
    INSERT INTO bench_results VALUES (t, qid, 'arg_knn, glob scan', 1000, false, r.ids, r.ms);
    SELECT * INTO r FROM bench_ids(format('SELECT (o).id FROM arg_knn(NULL::%I, ''descr'', \$1, 10, filter => ''{"museum": "M7"}'', descriptor => ''glob'') AS k(o, sim)', t), q);
    INSERT INTO bench_results VALUES (t, qid, 'arg_knn, glob scan', 1000, true, r.ids, r.ms);
    SELECT * INTO r FROM bench_ids(format('SELECT (o).id FROM arg_knn(NULL::%I, ''descr'', \$1, 10, descriptor => ''glob'', sketch => ''sk'') AS k(o, sim)', t), q);
    INSERT INTO bench_results VALUES (t, qid, 'arg_knn, glob + sketch', 3000, false, r.ids, r.ms);
    SELECT * INTO r FROM bench_ids(format('SELECT (o).id FROM arg_knn(NULL::%I, ''descr'', \$1, 10, filter => ''{"museum": "M7"}'', descriptor => ''glob'', sketch => ''sk'') AS k(o, sim)', t), q);
    INSERT INTO bench_results VALUES (t, qid, 'arg_knn, glob + sketch', 3000, true, r.ids, r.ms);
    RAISE NOTICE '% query % of %', t, i + 1, $queries;
  END LOOP;
END \$\$;
SQL
done

say ""
say "## recall@10 and latency (serial; ms: median over the queries, p90 in brackets)"
run -c "
WITH b AS (SELECT tbl, qid, filtered, ids FROM bench_results WHERE method = 'brute'),
s AS (
  SELECT r.tbl, r.method, r.cand, r.filtered,
         avg((SELECT count(*) FROM unnest(r.ids) x WHERE x = ANY (b.ids))::float8
             / greatest(cardinality(b.ids), 1)) AS recall,
         min(cardinality(r.ids)) AS min_rows, min(cardinality(b.ids)) AS brute_rows,
         percentile_cont(0.5) WITHIN GROUP (ORDER BY r.ms) AS ms,
         percentile_cont(0.9) WITHIN GROUP (ORDER BY r.ms) AS p90
  FROM bench_results r JOIN b USING (tbl, qid, filtered)
  GROUP BY 1, 2, 3, 4)
SELECT s.tbl AS table, CASE WHEN s.filtered THEN 'M7' ELSE '-' END AS filter, s.method,
       coalesce(s.cand::text, '') AS candidates, round(s.recall::numeric, 4) AS recall_at_10,
       s.min_rows || '/' || s.brute_rows AS min_rows,
       round(s.ms::numeric, 1) || ' [' || round(s.p90::numeric, 1) || ']' AS ms,
       round((bs.ms / s.ms)::numeric, 1) AS speedup_vs_brute
FROM s JOIN s bs ON bs.tbl = s.tbl AND bs.filtered = s.filtered AND bs.method = 'brute'
ORDER BY array_position(ARRAY['$(IFS=,; echo "${tables[*]}" | sed "s/,/','/g")'], s.tbl), s.filtered,
         s.method = 'brute' DESC, s.method, s.cand" | tee -a "$report"

# --- parallel brute force -----------------------------------------------------------------------
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
say ""
say "## brute force with parallel workers (median execution time of $par_queries queries, EXPLAIN ANALYZE)"
for t in "${tables[@]}"; do
  [[ $t == shrec ]] && continue
  base_ms=""
  for w in 0 1 2; do
    out=$({
      echo "SET max_parallel_workers_per_gather = $w;"
      echo "SET plan_cache_mode = force_generic_plan;"
      echo "PREPARE rank(arg) AS SELECT id FROM $t ORDER BY descr <~> \$1, id LIMIT 10;"
      for ((i = 0; i < par_queries; i++)); do
        echo "SELECT descr AS q FROM $t ORDER BY id OFFSET ($i * (SELECT count(*) FROM $t) / $par_queries) LIMIT 1 \\gset"
        echo "EXPLAIN (ANALYZE, FORMAT JSON) EXECUTE rank(:'q');"
      done
    } | run -tA -f -)
    ms=$(sed -nE 's/.*"Execution Time": ([0-9.]+).*/\1/p' <<<"$out" | median)
    launched=$(sed -nE 's/.*"Workers Launched": ([0-9]+).*/\1/p' <<<"$out" | sort -u | tr '\n' ' ')
    [[ -z "$base_ms" ]] && base_ms=$ms
    say "$(awk -v t="$t" -v w="$w" -v ms="$ms" -v b="$base_ms" -v l="${launched:-0}" \
      'BEGIN { printf "%-12s workers %d (launched: %s): %9.1f ms  speed-up %.2f\n", t, w, l, ms, b / ms }')"
  done
done
say ""
say "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "report: $report"
