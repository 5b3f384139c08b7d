#!/usr/bin/env bash
# Bulk ingest end to end: a folder of meshes to an indexed table (docs/BENCHMARKS.md, "Bulk
# ingest"), against the server in PGHOST/PGPORT/PGUSER (a throwaway cluster:
# tools/pg/cluster.sh start build/pg-ingest; source build/pg-ingest/env).
#   bench/ingest_bench.sh DIR [CATALOGUE]
# For each thread count (THREADS, default "1 2") and round (ROUNDS, default 3): `argtool ingest`
# into a file (the builds), COPY of that file into an empty table, CREATE INDEX ... USING
# arg_ivf; then once per thread count the documented pipe, `argtool ingest --table | psql`,
# into an empty table. Prints each time and the medians; the builds' CPU time (user + system,
# which a busy machine inflates far less than wall time) beside their wall time. The table (database DB, default
# arg_ingest_bench, made anew) has a text column for each of the catalogue's header names
# (plain names, no quoted commas) and `descr arg`. ARGTOOL: default build/argtool.
set -euo pipefail
[[ $# -ge 1 ]] || { sed -n 2,11p "$0"; exit 2; }
dir=$1 catalogue=${2:-}
argtool=$(realpath "${ARGTOOL:-build/argtool}")
db=${DB:-arg_ingest_bench}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { PGOPTIONS='-c client_min_messages=warning' psql -X -q -d "$db" -v ON_ERROR_STOP=1 "$@"; }
# Seconds of wall time of a psql command, from \timing.
timed() { run -c '\timing on' "$@" | awk '/^Time:/ { s += $2 / 1000 } END { printf "%.2f\n", s }'; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

columns="file text"
catalogue_flag=()
if [[ -n "$catalogue" ]]; then
  columns=$(head -n 1 "$catalogue" | tr -d '\r' | awk -F, '{ for (i = 1; i <= NF; ++i)
    printf "%s%s text", (i > 1 ? ", " : ""), tolower($i) }')
  catalogue_flag=(--catalogue "$catalogue")
fi
PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
  -c "DROP DATABASE IF EXISTS $db" -c "CREATE DATABASE $db"
run -c 'CREATE EXTENSION arg CASCADE' -c "CREATE TABLE t ($columns, descr arg)"
models=$(find "$dir" -type f \( -iname '*.off' -o -iname '*.obj' -o -iname '*.ply' -o \
  -iname '*.stl' -o -iname '*.glb' \) | wc -l)
echo "ingest bench: $models mesh files under $dir; table t ($columns, descr arg)"

for threads in ${THREADS:-1 2}; do
  : >"$work/build" && : >"$work/cpu" && : >"$work/copy" && : >"$work/index"
  for ((round = 1; round <= ${ROUNDS:-3}; ++round)); do
    TIMEFORMAT='%R %U %S'
    { time "$argtool" ingest "$dir" "${catalogue_flag[@]}" --threads "$threads" \
      -o "$work/rows.copy" 2>"$work/ingest.log"; } 2>"$work/time"
    build=$(awk '{ printf "%.2f\n", $1 }' "$work/time")
    cpu=$(awk '{ printf "%.2f\n", $2 + $3 }' "$work/time")
    run -c 'TRUNCATE t'
    copy=$(timed -c "\\copy t FROM '$work/rows.copy'")
    index=$(timed -c 'CREATE INDEX t_descr ON t USING arg_ivf (descr)')
    run -c 'DROP INDEX t_descr'
    echo "$build" >>"$work/build" && echo "$cpu" >>"$work/cpu"
    echo "$copy" >>"$work/copy" && echo "$index" >>"$work/index"
    echo "threads $threads round $round: build $build s ($cpu s CPU), COPY $copy s," \
      "CREATE INDEX $index s;" \
      "$(tail -n 1 "$work/ingest.log")"
  done
  run -c 'TRUNCATE t'
  start=$(date +%s%N)
  "$argtool" ingest "$dir" "${catalogue_flag[@]}" --threads "$threads" --table t 2>"$work/pipe.log" |
    run
  pipe=$(awk -v ns=$(($(date +%s%N) - start)) 'BEGIN { printf "%.2f\n", ns / 1e9 }')
  rows=$(run -tA -c 'SELECT count(*) FROM t')
  b=$(median <"$work/build") u=$(median <"$work/cpu")
  c=$(median <"$work/copy") i=$(median <"$work/index")
  echo "threads $threads: medians of ${ROUNDS:-3}: build $b s ($(awk -v n="$models" -v s="$b" \
    'BEGIN { printf "%.2f", n / s }') models/s; $u s CPU), COPY $c s, CREATE INDEX $i s;" \
    "pipe (ingest --table | psql) $pipe s for $rows rows"
done
PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -c "DROP DATABASE IF EXISTS $db"
