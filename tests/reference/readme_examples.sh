#!/usr/bin/env bash
# Every example of README.md and clients/python/README.md runs as written against the demo's
# database (TAP): the database `museum` made as `make demo` makes it (the sample catalogue of
# `argtool gen` in build/demo/models, loaded by tools/demo/load.sql into `objects`), then each
# ```sql block of the README in a psql session of its own, from the top of the tree, and each
# ```python block of both READMEs with Debian's python3, the client on the path, in a scratch
# folder that holds what the client README's session expects (scans/: a generated catalogue
# and a file that is not a mesh). A block that needs other servers says so in its first line
# and is skipped.
#
# Needs PGHOST/PGPORT/PGUSER of a running cluster with the extension installed (run by
# tests/run_all.sh on its throwaway cluster) and the build (BUILD_DIR, default build: argtool).
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
build=${BUILD_DIR:-build}
python=${ARG_PYTHON:-/usr/bin/python3}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
n=0 failed=0
result() {  # result DESCRIPTION STATUS OUTPUT
  n=$((n + 1))
  if [[ $2 -eq 0 ]]; then
    echo "ok $n - $1"
  else
    failed=$((failed + 1))
    echo "not ok $n - $1"
    printf '%s\n' "$3" | tail -n 15 | sed 's/^/#   /'
  fi
}

# The demo's database, as tools/demo/run.sh makes it.
out=$({ PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
          -c 'DROP DATABASE IF EXISTS museum' -c 'CREATE DATABASE museum' &&
        "$build/argtool" gen --out "$build/demo/models" --per-class 5 &&
        psql -X -q -d museum -v ON_ERROR_STOP=1 -v mode=sample -v dir="$(pwd -P)/$build/demo/models" \
          -v script="$scratch/import.sql" -v every=1000 -f tools/demo/load.sql \
          <"$build/demo/models/catalogue.csv"; } 2>&1)
result "the demo's database museum with its objects" $? "$out"

# The fenced blocks of language LANG in FILE, one a file in DIR (NNN.LANG), in order.
blocks() {
  awk -v lang="$2" -v dir="$3" '
    $0 == "```" lang { inside = 1; k++; file = sprintf("%s/%03d.%s", dir, k, lang); next }
    inside && $0 == "```" { inside = 0; close(file); next }
    inside { print > file }' "$1"
}
mkdir -p "$scratch/readme" "$scratch/client"
blocks README.md sql "$scratch/readme"
blocks README.md python "$scratch/readme"
blocks clients/python/README.md python "$scratch/client"

for f in "$scratch"/readme/*.sql; do
  first=$(head -n 3 "$f" | grep -m1 -o 'needs the shard servers' || true)
  what="README.md sql block $(basename "$f" .sql): $(grep -m1 -v '^ *--' "$f" | cut -c1-60)"
  if [[ -n "$first" ]]; then
    n=$((n + 1))
    echo "ok $n - $what # SKIP it needs the shard servers (tests/scale/shards.sh runs it)"
    continue
  fi
  out=$(psql -X -q -d museum -v ON_ERROR_STOP=1 -f "$f" 2>&1)
  result "$what" $? "$out"
done

# What the client README's session expects beside it: scans/ with a generated catalogue (two
# models a class) and a file that is not a mesh.
"$build/argtool" gen --out "$scratch/demo/scans" --per-class 2 >/dev/null
printf 'OFF\nthis is not a mesh\n' >"$scratch/demo/scans/notes.off"
# A block that imports is an example; the others show signatures.
for f in "$scratch"/readme/*.python "$scratch"/client/*.python; do
  [[ -e "$f" ]] && grep -qE '^(import|from) ' "$f" || continue
  where=$([[ $f == */client/* ]] && echo clients/python/README.md || echo README.md)
  what="$where python block $(basename "$f" .python): $(grep -m1 -vE '^(import|from|$)' "$f" | cut -c1-50)"
  out=$(cd "$scratch/demo" && PGDATABASE=museum PYTHONPATH="$OLDPWD/clients/python" \
          PYTHONDONTWRITEBYTECODE=1 timeout 300 "$python" "$f" 2>&1)
  result "$what" $? "$out"
done
PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -c 'DROP DATABASE IF EXISTS museum' >/dev/null 2>&1
echo "1..$n"
[[ $failed -eq 0 ]]
