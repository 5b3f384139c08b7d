#!/usr/bin/env bash
# Two builds of arg.so on the same SQL brute-force ranking, installed in turn:
#   bench/sql_build_ab.sh COPY_FILE SO_A SO_B [ROUNDS]
# COPY_FILE (rows of `argtool scale-gen`) is loaded 25 times over (ids renumbered) into table r
# of database arg_build_ab, made anew on the server in PGHOST/PGPORT/PGUSER. Each round
# installs each build (copied over arg.so in pg_config's pkglibdir, by rename: a running
# backend keeps the library it loaded) and runs, in a new backend, one ranking then four timed
# ones (EXPLAIN ANALYZE of ORDER BY descr <~> (row 1) LIMIT 10): a new backend's first
# ranking also maps every shared buffer it reads. Prints each build's median and the
# ratio; the arg.so found at the start is put back at the end. Needs write access to pkglibdir.
# MEASURE=copy times the text form's way in and out instead: each round and build, TRUNCATE
# and COPY the rows in (every value checked by arg_in), then COPY them out (arg_out).
set -euo pipefail
[[ $# -ge 3 ]] || { sed -n 2,10p "$0"; exit 2; }
file=$(realpath "$1") so_a=$(realpath "$2") so_b=$(realpath "$3") rounds=${4:-6}
lib=$(pg_config --pkglibdir)/arg.so
db=arg_build_ab
work=$(mktemp -d)
cp "$lib" "$work/installed.so"
install_so() { cp "$1" "$lib.ab" && mv "$lib.ab" "$lib"; }
trap 'install_so "$work/installed.so"; rm -rf "$work"' EXIT
PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
  -c "DROP DATABASE IF EXISTS $db" -c "CREATE DATABASE $db"
run() { psql -X -q -d $db -v ON_ERROR_STOP=1 "$@"; }
run -c 'CREATE EXTENSION arg CASCADE' \
  -c 'CREATE TABLE r (id int PRIMARY KEY, museum text, period text, class text, descr arg)'
awk -F'\t' 'BEGIN { OFS = "\t" } { line[NR] = $0 }
  END { id = 0; for (c = 0; c < 25; ++c) for (i = 1; i <= NR; ++i) {
    split(line[i], f, "\t"); f[1] = ++id; out = f[1];
    for (k = 2; k <= length(f); ++k) out = out "\t" f[k]; print out } }' "$file" >"$work/rows.txt"
run -c "\\copy r FROM '$work/rows.txt'" -c 'VACUUM ANALYZE r'
median() { sort -g "$1" | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
rows=$(run -tA -c 'SELECT count(*) FROM r')
if [[ "${MEASURE:-rank}" == copy ]]; then
  timed() { run -c '\timing on' "$@" | grep -o 'Time: [0-9.]*' | awk '{ print $2 }'; }
  for side in a b; do : >"$work/$side.in" && : >"$work/$side.out"; done
  for ((round = 0; round < rounds; ++round)); do
    for side in a b; do
      install_so "$([[ $side == a ]] && echo "$so_a" || echo "$so_b")"
      run -c 'TRUNCATE r'
      timed -c "\\copy r FROM '$work/rows.txt'" >>"$work/$side.in"
      timed -c "\\copy r TO '/dev/null'" >>"$work/$side.out"
    done
  done
  awk -v n="$rows" -v ai="$(median "$work/a.in")" -v bi="$(median "$work/b.in")" \
    -v ao="$(median "$work/a.out")" -v bo="$(median "$work/b.out")" -v k="$rounds" 'BEGIN {
    printf "| build | rounds | COPY in, median ms | rows/s | COPY out, median ms | rows/s |\n";
    printf "|---|---|---|---|---|---|\n";
    printf "| A | %d | %.1f | %.0f | %.1f | %.0f |\n", k, ai, 1000 * n / ai, ao, 1000 * n / ao;
    printf "| B | %d | %.1f | %.0f | %.1f | %.0f |\n", k, bi, 1000 * n / bi, bo, 1000 * n / bo;
    printf "ratio B / A: in %.3f, out %.3f\n", bi / ai, bo / ao }'
  exit 0
fi
rank="EXPLAIN (ANALYZE, TIMING OFF) SELECT id FROM r
  ORDER BY descr <~> (SELECT descr FROM r WHERE id = 1) LIMIT 10;"
: >"$work/a"
: >"$work/b"
for ((round = 0; round < rounds; ++round)); do
  for side in a b; do
    install_so "$([[ $side == a ]] && echo "$so_a" || echo "$so_b")"
    printf '%s\n' "$rank" "$rank" "$rank" "$rank" "$rank" | run -tA |
      grep -o 'Execution Time: [0-9.]*' | awk '{ print $3 }' | tail -n +2 >>"$work/$side"
  done
done
ma=$(median "$work/a") mb=$(median "$work/b")
awk -v a="$ma" -v b="$mb" -v n="$rows" -v ka="$(wc -l <"$work/a")" 'BEGIN {
  printf "| build | rankings | median ms | us a row |\n|---|---|---|---|\n";
  printf "| A | %d | %.1f | %.1f |\n| B | %d | %.1f | %.1f |\nratio B / A: %.3f\n",
    ka, a, 1000 * a / n, ka, b, 1000 * b / n, b / a }'
