#!/usr/bin/env bash
# Sustained load (run by hand, not part of make test): pgbench with 8 clients for 10 minutes,
# mixing inserts (the ARG built by a generated column from a generated mesh) with top-10 ranking
# queries against a catalogue of 5,000 models. Checks afterwards that no transaction failed, that
# every committed row is there with a valid arg (its text form read back equals it), that no
# backend died, and that backend memory stayed flat after warm-up (the first half of the run).
#
#   tests/load/run_load.sh
#
# Environment: LOAD_SECONDS=600, LOAD_CLIENTS=8, LOAD_ROWS=5000 (the catalogue), LOAD_RESOLUTION=16
# (mesh resolution of generated models; 16 gives about 2,000 triangles), RANK_WEIGHT=4 and
# INSERT_WEIGHT=1 (pgbench script weights). Starts a throwaway cluster under
# $BUILD_DIR/pg-load and removes it at the end. Prints TAP lines and a report in
# $BUILD_DIR/load/report.txt: throughput, latency median and p99 per script, backend RSS over time.
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
build=${BUILD_DIR:-build}
seconds=${LOAD_SECONDS:-600}
clients=${LOAD_CLIENTS:-8}
rows=${LOAD_ROWS:-5000}
resolution=${LOAD_RESOLUTION:-16}
rank_weight=${RANK_WEIGHT:-4}
insert_weight=${INSERT_WEIGHT:-1}
out=$build/load
pgdir=$build/pg-load
mkdir -p "$out"
rm -f "$out"/pgbench_log.* "$out/rss.txt"
report=$out/report.txt
: >"$report"
say() { echo "$*" | tee -a "$report"; }

n=0 failed=0
result() {  # result OK DESCRIPTION (OK: 1 or anything else)
  n=$((n + 1))
  if [[ $1 == 1 ]]; then echo "ok $n - $2"; else echo "not ok $n - $2"; failed=$((failed + 1)); fi
}

trap 'tools/pg/cluster.sh stop "$pgdir" --remove >/dev/null' EXIT
tools/pg/cluster.sh start "$pgdir" --fresh || exit 1
# shellcheck disable=SC1091
source "$pgdir/env"
db=arg_load
q() { PGOPTIONS='-c client_min_messages=warning' psql -X -q -v ON_ERROR_STOP=1 -tA "$@"; }
q -d postgres -c "ALTER SYSTEM SET max_connections = 40" -c "ALTER SYSTEM SET shared_buffers = '512MB'" >/dev/null
tools/pg/cluster.sh stop "$pgdir" >/dev/null && tools/pg/cluster.sh start "$pgdir" >/dev/null || exit 1
# shellcheck disable=SC1091
source "$pgdir/env"
q -d postgres -c "CREATE DATABASE $db" >/dev/null || exit 1

say "# load test $(date -u +%FT%TZ) on $(nproc) cores: $clients clients, ${seconds} s, $rows rows, resolution $resolution"
say "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"

# The catalogue, loaded by two sessions at once (each model built by the generated column).
q -d "$db" >/dev/null <<SQL || exit 1
CREATE EXTENSION arg CASCADE;
CREATE TABLE objects (
  id     bigserial PRIMARY KEY,
  museum text NOT NULL,
  class  text NOT NULL,
  mesh   bytea NOT NULL,
  descr  arg GENERATED ALWAYS AS (arg_build(mesh)) STORED);
CREATE TABLE classes (i int PRIMARY KEY, name text NOT NULL);
INSERT INTO classes VALUES (0, 'vase'), (1, 'cup'), (2, 'amphora'), (3, 'torus'), (4, 'fourleg'),
                           (5, 'human'), (6, 'table'), (7, 'chair');
SQL
t0=$(date +%s.%N)
for part in 0 1; do
  q -d "$db" -c "INSERT INTO objects (museum, class, mesh)
                 SELECT 'M' || (g % 20), c.name, arg_generate_model(c.name, g / 8, $resolution)
                 FROM generate_series($part, $rows - 1, 2) g JOIN classes c ON c.i = g % 8" &
done
wait
t1=$(date +%s.%N)
q -d "$db" -c "VACUUM ANALYZE objects" >/dev/null
initial=$(q -d "$db" -c "SELECT count(*) FROM objects")
say "$(awk -v n="$initial" -v a="$t0" -v b="$t1" 'BEGIN { printf "catalogue: %d rows built by INSERT (generated column, 2 sessions) in %.1f s: %.1f rows/s", n, b - a, n / (b - a) }')"

# The two transactions pgbench mixes.
cat >"$out/insert.sql" <<SQL
\set c random(0, 7)
\set v random(0, 100000)
\set m random(0, 19)
INSERT INTO objects (museum, class, mesh)
SELECT 'M' || :m, name, arg_generate_model(name, :v, $resolution) FROM classes WHERE i = :c;
SQL
cat >"$out/rank.sql" <<SQL
\set q random(1, $rows)
SELECT id, class, museum, descr <~> (SELECT descr FROM objects WHERE id = :q) AS sim
FROM objects ORDER BY sim LIMIT 10;
SQL

# Private memory (RssAnon) of every pgbench backend, sampled every 10 s while pgbench runs:
# shared buffers a backend touches count in its RSS but are not its own, so they are left out.
sample_rss() {
  local start=$SECONDS
  while sleep 10; do
    local pids kb=() pid
    pids=$(q -d postgres -c "SELECT pid FROM pg_stat_activity WHERE application_name = 'pgbench'")
    for pid in $pids; do
      kb+=("$(awk '/^RssAnon:/ { print $2 }' "/proc/$pid/status" 2>/dev/null)")
    done
    [[ ${#kb[@]} -gt 0 ]] && echo "$((SECONDS - start)) ${kb[*]}" >>"$out/rss.txt"
  done
}
sample_rss &
sampler=$!

say "pgbench: insert.sql@$insert_weight, rank.sql@$rank_weight"
(cd "$out" && PGAPPNAME=pgbench pgbench -n -c "$clients" -j 2 -T "$seconds" -P 60 -l \
  --log-prefix=pgbench_log -f "insert.sql@$insert_weight" -f "rank.sql@$rank_weight" "$db") \
  >"$out/pgbench.txt" 2>&1
bench_rc=$?
kill "$sampler" 2>/dev/null
wait "$sampler" 2>/dev/null
cat "$out/pgbench.txt"

# Per-transaction log lines: client transaction latency_us script epoch_s epoch_us.
stats() {  # stats SCRIPT_NO
  cat "$out"/pgbench_log.* | awk -v s="$1" '$4 == s && $3 ~ /^[0-9]+$/ { print $3 / 1000 }' | sort -g |
    awk '{ v[NR] = $1 } END { if (NR == 0) { print "0 0 0"; exit }
           m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
           p = v[int(NR * 0.99 + 0.999)]; printf "%d %.1f %.1f\n", NR, m, p }'
}
read -r inserts insert_med insert_p99 <<<"$(stats 0)"
read -r ranks rank_med rank_p99 <<<"$(stats 1)"
errors=$(cat "$out"/pgbench_log.* | awk '$3 !~ /^[0-9]+$/' | wc -l)
reported_failed=$(sed -nE 's/^number of failed transactions: ([0-9]+).*/\1/p' "$out/pgbench.txt")
tps=$(sed -nE 's/^tps = ([0-9.]+) .*/\1/p' "$out/pgbench.txt")
say ""
say "throughput: ${tps:-?} transactions/s over $seconds s with $clients clients"
say "insert (generated column builds the ARG): $inserts committed, latency median $insert_med ms, p99 $insert_p99 ms"
say "top-10 ranking over the table:           $ranks done, latency median $rank_med ms, p99 $rank_p99 ms"

result "$([[ $bench_rc -eq 0 && $errors -eq 0 && ${reported_failed:-0} -eq 0 ]] && echo 1)" \
  "pgbench finished with 0 failed transactions (exit $bench_rc, ${reported_failed:-?} reported failed, $errors failed in the log)"

final=$(q -d "$db" -c "SELECT count(*) FROM objects")
result "$([[ $final -eq $((initial + inserts)) ]] && echo 1)" \
  "every committed insert is in the table: $initial + $inserts = $final rows"

invalid=$(q -d "$db" -c "SELECT count(*) FROM objects
                         WHERE descr IS NULL OR descr::text::arg <> descr OR arg_info(descr) IS NULL
                            OR descr <> arg_build(mesh)" 2>&1)
result "$([[ $invalid == 0 ]] && echo 1)" \
  "every row holds a valid arg equal to a fresh build of its mesh ($invalid bad rows)"

# The log is where cluster.sh keeps it (in /tmp when the checkout is under a 0700 home).
server_log=$(tools/pg/cluster.sh log-path "$pgdir")
log_check=$(tests/server_log/check.sh "$server_log" 2>&1)
log_rc=$?
result "$([[ $log_rc -eq 0 ]] && echo 1)" "the server log shows no crashed backend: ${log_check%%$'\n'*}"

# Memory: RssAnon per backend at each minute. Eight backends sharing two cores run only a few
# hundred transactions each in ten minutes, so their caches (catalogue, plans, allocator arenas)
# fill for minutes: warm-up is the first half of the run, and the check compares the mean over
# the backends at mid-run with the mean at the end. (tests/pgtap/03_memory.sql checks one
# backend over 1,300 calls in make test.)
say ""
say "backend private memory (RssAnon, MB; median and max over the $clients backends) at each minute:"
while read -r at kbs; do
  (( at % 60 < 10 )) || continue
  tr ' ' '\n' <<<"$kbs" | sort -n | awk -v at="$at" '{ v[NR] = $1 }
    END { med = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
          printf "  %4d s: median %.1f, max %.1f\n", at, med / 1024, v[NR] / 1024 }'
done <"$out/rss.txt" | tee -a "$report"
growth=$(awk -v half=$((seconds / 2)) '
           NF > 1 { s = 0; for (i = 2; i <= NF; i++) s += $i; m = s / (NF - 1)
                    if ($1 >= half && first == "") first = m; last = m }
           END { if (first == "" || first == 0) print "?"; else printf "%.1f", 100 * (last - first) / first }' \
         "$out/rss.txt")
result "$([[ $growth != "?" ]] && awk -v g="$growth" 'BEGIN { exit !(g < 5) }' && echo 1)" \
  "backend memory is flat after warm-up: mean RssAnon changed by $growth% from mid-run to the end (limit 5%)"
say "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "report: $report"
[[ $failed -eq 0 ]]
