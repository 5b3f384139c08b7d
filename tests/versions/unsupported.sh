#!/usr/bin/env bash
# A build against an unsupported PostgreSQL stops before compiling, naming the supported
# versions (TAP). A stand-in pg_config says it is PostgreSQL 14, then 18.
set -uo pipefail
cd "$(dirname "$0")/../.." || exit 1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
n=0
for version in 14.9 18.1; do
  cat >"$scratch/pg_config" <<CONFIG
#!/bin/sh
echo "PostgreSQL $version"
CONFIG
  chmod +x "$scratch/pg_config"
  out=$(make -n --no-print-directory PG_CONFIG="$scratch/pg_config" all 2>&1)
  status=$?
  n=$((n + 1))
  if [[ $status -ne 0 && "$out" == *"arg supports PostgreSQL 15 16 17"* &&
    "$out" == *"is PostgreSQL ${version%%.*}"* ]]; then
    echo "ok $n - PostgreSQL ${version%%.*} refused with the supported versions named"
  else
    echo "not ok $n - PostgreSQL ${version%%.*} not refused as it should be"
    printf '%s\n' "$out" | head -n 5 | sed 's/^/# /'
  fi
done
echo "1..$n"
