#!/usr/bin/env bash
# Per-row SQL cost of ARG values, two sets side by side (formats or builders): COPY ingest rate,
# value size, and the brute-force ranking ORDER BY arg <~> query LIMIT 10 over every row.
#
#   bench/sql_rows_ab.sh NAME_A ROWS_A NAME_B ROWS_B [COPIES]
#
# ROWS_x are COPY text files of `argtool scale-gen` (id, museum, period, class, arg); each is
# loaded COPIES times (default 25, ids renumbered) into its own table, so 400 models make 10,000
# rows. Against the server in PGHOST/PGPORT/PGUSER with the extension installed; database
# arg_rows_ab is made anew. Rounds alternate A and B; medians of 2 x REPEATS (default 9)
# rankings in warm backends and of 3 loads. The query is row 1 of each table, so each set is
# ranked against its own kind.
set -euo pipefail
[[ $# -ge 4 ]] || { sed -n 2,11p "$0"; exit 2; }
name_a=$1 rows_a=$2 name_b=$3 rows_b=$4 copies=${5:-25} repeats=${REPEATS:-9}
db=arg_rows_ab
PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
  -c "DROP DATABASE IF EXISTS $db" -c "CREATE DATABASE $db"
run() { psql -X -q -d $db -v ON_ERROR_STOP=1 "$@"; }
run -c 'CREATE EXTENSION arg CASCADE'
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# COPIES copies of a file with ids renumbered 1..N.
for side in a b; do
  src=$([[ $side == a ]] && echo "$rows_a" || echo "$rows_b")
  awk -F'\t' -v copies="$copies" 'BEGIN { OFS = "\t" } { line[NR] = $0 }
    END { id = 0; for (c = 0; c < copies; ++c) for (i = 1; i <= NR; ++i) {
      split(line[i], f, "\t"); f[1] = ++id; out = f[1];
      for (k = 2; k <= length(f); ++k) out = out "\t" f[k]; print out } }' "$src" >"$work/$side.txt"
done
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
ms_of() { grep -o 'Execution Time: [0-9.]*' | awk '{ print $3 }'; }
: >"$work/load_a" ; : >"$work/load_b"; : >"$work/rank_a"; : >"$work/rank_b"
for _ in 1 2 3; do
  for side in a b; do
    run -c "DROP TABLE IF EXISTS rows_$side" \
      -c "CREATE TABLE rows_$side (id int PRIMARY KEY, museum text, period text, class text, descr arg)"
    t0=$(date +%s.%N)
    run -c "\\copy rows_$side FROM '$work/$side.txt'"
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" -v n="$(wc -l <"$work/$side.txt")" 'BEGIN { printf "%.0f\n", n / (b - a) }' >>"$work/load_$side"
  done
done
run -c 'VACUUM ANALYZE rows_a' -c 'VACUUM ANALYZE rows_b'
# Three rankings a backend, the first dropped: a new backend's first ranking also maps every
# shared buffer it reads into its address space (a minor page fault per 4 kB page without huge
# pages), which cost 70% more here (473 against 280 ms for 10,000 rows); a
# pooled connection pays it once.
for ((r = 0; r < repeats; ++r)); do
  for side in a b; do
    rank="EXPLAIN (ANALYZE, TIMING OFF) SELECT id FROM rows_$side
      ORDER BY descr <~> (SELECT descr FROM rows_$side WHERE id = 1) LIMIT 10;"
    printf '%s\n' "$rank" "$rank" "$rank" | run -tA | ms_of | tail -n +2 >>"$work/rank_$side"
  done
done
rows=$(run -tA -c 'SELECT count(*) FROM rows_a')
printf '| set | rows | size median (B) | size max (B) | COPY rows/s | ranking ms | us a row |\n|---|---|---|---|---|---|---|\n'
for side in a b; do
  name=$([[ $side == a ]] && echo "$name_a" || echo "$name_b")
  sizes=$(run -tA -c "SELECT percentile_disc(0.5) WITHIN GROUP (ORDER BY octet_length(arg_send(descr))),
                             max(octet_length(arg_send(descr))) FROM rows_$side" | tr '|' ' ')
  load=$(median <"$work/load_$side")
  rank=$(median <"$work/rank_$side")
  awk -v n="$name" -v rows="$rows" -v s="$sizes" -v l="$load" -v r="$rank" 'BEGIN {
    split(s, z, " "); printf "| %s | %d | %d | %d | %d | %.1f | %.1f |\n", n, rows, z[1], z[2], l, r, 1000 * r / rows }'
done
