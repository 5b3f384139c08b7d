#!/usr/bin/env bash
# Sharding with postgres_fdw: one coordinator and two shards, three throwaway clusters on
# localhost (tools/pg/cluster.sh, distinct free ports, data under $BUILD_DIR/pg-shards). The
# coordinator's objects table is partitioned by hash of museum into two foreign partitions,
# one per shard; the foreign servers list the arg and cube extensions, so postgres_fdw sends
# ORDER BY descr <~> $1 (and the two-stage query's ORDER BY arg_global(descr) <#> ...) to each
# shard, and the coordinator merges the shards' ordered rows.
#
#   tests/scale/shards.sh                    MODELS=200 generated models (argtool scale-gen)
#
# Checks that the top 10 of several queries through the shards equals the answer of one server
# holding the same rows, that EXPLAIN VERBOSE shows the ordering in each shard's remote SQL,
# and that all three clusters stop. Prints TAP lines ("ok N - ...", "not ok N - ...") and exits
# non-zero when one fails; tests/run_all.sh runs it as a suite. Expects the build (argtool) and
# `make install`.
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
build=${BUILD_DIR:-build}
models=${MODELS:-200}
base=$build/pg-shards
nodes=(coord shard1 shard2)

stop_all() {
  for n in "${nodes[@]}"; do tools/pg/cluster.sh stop "$base/$n" --remove >/dev/null 2>&1; done
}
trap stop_all EXIT
trap 'exit 130' INT TERM HUP

n=0 failed=0
echo "1..11"
check() {  # check DESCRIPTION COMMAND...: ok when the command succeeds
  local description=$1
  shift
  n=$((n + 1))
  if "$@"; then echo "ok $n - $description"; else echo "not ok $n - $description"; failed=$((failed + 1)); fi
}
same() { [[ -n "$1" && "$1" == "$2" ]] || { echo "#   have: $2" >&2; echo "#   want: $1" >&2; return 1; }; }
bail() { echo "Bail out! $*"; exit 1; }

# psql on one node: on NODE [psql args...]
on() {
  local node=$1
  shift
  PGOPTIONS='-c client_min_messages=warning' psql -X -q -v ON_ERROR_STOP=1 -h localhost \
    -p "$(cat "$base/$node/port")" -U postgres -d postgres "$@"
}

# --- three clusters ---------------------------------------------------------------------------
mkdir -p "$base"
started=1
for node in "${nodes[@]}"; do
  tools/pg/cluster.sh start "$base/$node" --fresh >"$base/$node.start.log" 2>&1 || started=0
done
ports=$(cat "$base"/{coord,shard1,shard2}/port 2>/dev/null | sort -u | wc -l)
check "three clusters (coordinator, two shards) run on three distinct localhost ports" \
  test "$started" -eq 1 -a "$ports" -eq 3
[[ $started -eq 1 ]] || bail "a cluster did not start (see $base/*.start.log)"

# --- the extension everywhere, the shards' tables -----------------------------------------------
installed=1
for node in "${nodes[@]}"; do on "$node" -c 'CREATE EXTENSION arg CASCADE' || installed=0; done
for shard in shard1 shard2; do
  on "$shard" -c "CREATE TABLE objects_shard (
      id int PRIMARY KEY, museum text NOT NULL, period text, class text, descr arg)" \
    -c 'CREATE INDEX ON objects_shard USING gist (arg_global(descr))' || installed=0
done
versions=$(for node in "${nodes[@]}"; do on "$node" -tA -c 'SELECT arg_version()'; done | sort -u | wc -l)
check "the arg extension (and cube) is installed on every node, in one version" \
  test "$installed" -eq 1 -a "$versions" -eq 1

# --- the coordinator: foreign servers and the partitioned table ---------------------------------
on coord >/dev/null <<SQL || bail "could not set up the coordinator"
CREATE EXTENSION postgres_fdw;
CREATE SERVER shard1 FOREIGN DATA WRAPPER postgres_fdw
  OPTIONS (host 'localhost', port '$(cat "$base/shard1/port")', dbname 'postgres',
           extensions 'arg, cube', fetch_size '10');
CREATE SERVER shard2 FOREIGN DATA WRAPPER postgres_fdw
  OPTIONS (host 'localhost', port '$(cat "$base/shard2/port")', dbname 'postgres',
           extensions 'arg, cube', fetch_size '10');
CREATE USER MAPPING FOR CURRENT_USER SERVER shard1 OPTIONS (user 'postgres');
CREATE USER MAPPING FOR CURRENT_USER SERVER shard2 OPTIONS (user 'postgres');
CREATE TABLE objects (id int NOT NULL, museum text NOT NULL, period text, class text, descr arg)
  PARTITION BY HASH (museum);
CREATE FOREIGN TABLE objects_1 PARTITION OF objects FOR VALUES WITH (MODULUS 2, REMAINDER 0)
  SERVER shard1 OPTIONS (table_name 'objects_shard', batch_size '50');
CREATE FOREIGN TABLE objects_2 PARTITION OF objects FOR VALUES WITH (MODULUS 2, REMAINDER 1)
  SERVER shard2 OPTIONS (table_name 'objects_shard', batch_size '50');
-- The same rows on one server, for the reference answers.
CREATE TABLE objects_single (id int PRIMARY KEY, museum text NOT NULL, period text, class text,
                             descr arg);
CREATE INDEX ON objects_single USING gist (arg_global(descr));
SQL

# --- load: built outside the database, copied into the coordinator, routed to the shards ---------
copy=$base/models.copy
"$build/argtool" scale-gen --count "$models" --out "$copy" --threads 2 --seed 7 >"$base/gen.log" 2>&1 ||
  bail "argtool scale-gen failed (see $base/gen.log)"
on coord -c "\\copy objects_single FROM '$copy'" -c 'INSERT INTO objects SELECT * FROM objects_single' \
  -c 'ANALYZE objects_single' || bail "loading failed"
for shard in shard1 shard2; do on "$shard" -c 'ANALYZE objects_shard'; done
on coord -c 'ANALYZE objects_1' -c 'ANALYZE objects_2'
c1=$(on shard1 -tA -c 'SELECT count(*) FROM objects_shard')
c2=$(on shard2 -tA -c 'SELECT count(*) FROM objects_shard')
check "the $models models are spread over both shards by museum ($c1 + $c2)" \
  test "$((c1 + c2))" -eq "$models" -a "$c1" -gt 0 -a "$c2" -gt 0
fingerprint() {  # NODE SQL: md5 of arg_send of every row, in id order
  on "$1" -tA -c "SELECT md5(string_agg(id || ':' || encode(arg_send(descr), 'hex'), ',' ORDER BY id)) FROM $2"
}
check "the ARGs on the shards are byte for byte those loaded" \
  same "$(fingerprint coord objects_single)" "$(fingerprint coord objects)"

# --- the same answers ---------------------------------------------------------------------------
# Top 10 of query model Q as "id:sim" lines, through TABLE (the generic plan: $1 is a parameter
# as from a client, so the query ARG goes to the shards as a parameter too).
top10() {  # TABLE Q [WHERE]
  on coord -tA <<SQL
SET plan_cache_mode = force_generic_plan;
PREPARE rank(arg) AS SELECT id, descr <~> \$1 AS sim FROM $1 ${3:-} ORDER BY descr <~> \$1, id LIMIT 10;
SELECT descr AS q FROM objects_single WHERE id = $2 \\gset
EXECUTE rank(:'q');
SQL
}
queries=(1 17 55 123 199)
agree=1
for q in "${queries[@]}"; do
  want=$(top10 objects_single "$q") have=$(top10 objects "$q")
  same "$want" "$have" || agree=0
done
check "the top 10 of ${#queries[@]} queries through the shards equals the single-server answer" \
  test "$agree" -eq 1
agree=1
for q in 1 55; do
  want=$(top10 objects_single "$q" "WHERE museum = 'M7'")
  have=$(top10 objects "$q" "WHERE museum = 'M7'")
  same "$want" "$have" || agree=0
done
check "under a filter on the distribution column the answers agree too" test "$agree" -eq 1

# The two-stage query through the shards: each shard's GiST index gives its nearest candidates.
two_stage() {  # TABLE Q
  on coord -tA <<SQL
SET plan_cache_mode = force_generic_plan;
PREPARE knn(arg) AS
  WITH candidates AS MATERIALIZED (
    SELECT id, descr FROM $1 ORDER BY arg_global(descr) <#> arg_global(\$1) LIMIT 100)
  SELECT id, descr <~> \$1 AS sim FROM candidates ORDER BY sim, id LIMIT 10;
SELECT descr AS q FROM objects_single WHERE id = $2 \\gset
EXECUTE knn(:'q');
SQL
}
agree=1
for q in "${queries[@]}"; do same "$(two_stage objects_single "$q")" "$(two_stage objects "$q")" || agree=0; done
check "the two-stage query through the shards equals the single-server two-stage answer" \
  test "$agree" -eq 1

# --- the plan: the ordering goes to each shard --------------------------------------------------
plan=$(on coord -tA <<'SQL'
SET plan_cache_mode = force_generic_plan;
PREPARE rank(arg) AS SELECT id, descr <~> $1 AS sim FROM objects ORDER BY descr <~> $1 LIMIT 10;
EXPLAIN (VERBOSE, COSTS OFF) EXECUTE rank(NULL);
SQL
)
echo "$plan" | sed 's/^/#   /'
remote_ordered=$(grep -cE 'Remote SQL: SELECT .* FROM public\.objects_shard ORDER BY \(descr OPERATOR\(public\.<~>\) \$1::public\.arg\)' <<<"$plan")
check "EXPLAIN VERBOSE shows ORDER BY descr <~> \$1 in the remote SQL of both shards" \
  test "$remote_ordered" -eq 2
check "the coordinator merges the two ordered streams (Merge Append, no sort of its own)" \
  bash -c 'grep -q "Merge Append" <<<"$1" && ! grep -qE "^ *->  Sort" <<<"$1"' _ "$plan"
plan=$(on coord -tA <<'SQL'
SET plan_cache_mode = force_generic_plan;
PREPARE knn(arg) AS SELECT id FROM objects ORDER BY arg_global(descr) <#> arg_global($1) LIMIT 100;
EXPLAIN (VERBOSE, COSTS OFF) EXECUTE knn(NULL);
SQL
)
remote_ordered=$(grep -cE 'Remote SQL: .* ORDER BY \(public\.arg_global\(descr\) OPERATOR\(public\.<#>\) public\.arg_global\(\$1::public\.arg\)\)' <<<"$plan")
check "the two-stage candidates query sends ORDER BY arg_global(descr) <#> ... to both shards" \
  test "$remote_ordered" -eq 2

# For the record (not checks): one ranking's execution time on one server and through the shards.
for table in objects_single objects; do
  ms=$(on coord -tA <<SQL | sed -nE 's/.*"Execution Time": ([0-9.]+).*/\1/p'
SET plan_cache_mode = force_generic_plan;
PREPARE rank(arg) AS SELECT id, descr <~> \$1 AS sim FROM $table ORDER BY descr <~> \$1 LIMIT 10;
SELECT descr AS q FROM objects_single WHERE id = 17 \\gset
EXECUTE rank(:'q') \\g /dev/null
EXPLAIN (ANALYZE, FORMAT JSON) EXECUTE rank(:'q');
SQL
)
  echo "# top 10 of $models over $table: ${ms} ms"
done

# --- stop ---------------------------------------------------------------------------------------
stopped=1
for node in "${nodes[@]}"; do tools/pg/cluster.sh stop "$base/$node" --remove >/dev/null || stopped=0; done
running=0
for node in "${nodes[@]}"; do tools/pg/cluster.sh status "$base/$node" 2>/dev/null && running=1; done
check "all three clusters stop cleanly" test "$stopped" -eq 1 -a "$running" -eq 0
trap - EXIT

[[ $failed -eq 0 ]]
