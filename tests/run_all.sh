#!/usr/bin/env bash
# Runs every test suite and ends with one line "N passed, N failed" that adds them all up:
#   unit        GoogleTest through CTest (the CMake build in $BUILD_DIR)
#   regression  pg_regress on sql/ + expected/ (make installcheck)
#   pgtap       pg_prove on tests/pgtap/*.sql
#   round trips tests/sql_roundtrip.sh: pg_dump/pg_restore and COPY (FORMAT binary) of arg values
#   shards      tests/scale/shards.sh: postgres_fdw, a coordinator and two shards (its own clusters)
# The SQL suites run on a throwaway cluster that this script starts and always stops. A suite that
# cannot run at all counts as one failure, never as zero tests. Exits non-zero on any failure.
# Expects the build and `make install` done (make test does both first).
set -uo pipefail

cd "$(dirname "$0")/.." || exit 1
build=${BUILD_DIR:-build}
logs=$build/test-logs
pgdir=$build/pg-test
mkdir -p "$logs"

total_pass=0 total_fail=0
summary=()

# Records one suite's counts: suite NAME PASSED FAILED.
suite() {
  summary+=("$(printf '  %-32s %s passed, %s failed' "$1" "$2" "$3")")
  total_pass=$((total_pass + $2))
  total_fail=$((total_fail + $3))
}

# Counts "N" in the first line of FILE matching the extended regex with one group (or empty).
count() { sed -nE "s/$2/\1/p" "$1" | head -n 1; }

banner() { printf '\n=== %s\n' "$*"; }

# --- unit tests -----------------------------------------------------------------------------
banner "unit tests (ctest)"
ctest --test-dir "$build" --output-on-failure --no-tests=error --timeout 900 -j "$(nproc)" \
  2>&1 | tee "$logs/ctest.log"
rc=${PIPESTATUS[0]}
# "100% tests passed, 0 tests failed out of 12"
failed=$(count "$logs/ctest.log" '^[0-9]+% tests passed, ([0-9]+) tests? failed out of [0-9]+.*')
all=$(count "$logs/ctest.log" '^[0-9]+% tests passed, [0-9]+ tests? failed out of ([0-9]+).*')
if [[ -z "$failed" || -z "$all" ]]; then
  suite "unit tests (ctest)" 0 1
else
  [[ $rc -ne 0 && $failed -eq 0 ]] && failed=1 all=$((all + 1))
  suite "unit tests (ctest)" $((all - failed)) "$failed"
fi

# --- the throwaway cluster ------------------------------------------------------------------
banner "throwaway cluster"
trap 'tools/pg/cluster.sh stop "$pgdir" --remove' EXIT
trap 'exit 130' INT TERM HUP
cluster_up=0
if tools/pg/cluster.sh start "$pgdir" --fresh; then
  # shellcheck disable=SC1091
  source "$pgdir/env"
  cluster_up=1
fi

# --- pg_regress -----------------------------------------------------------------------------
banner "regression tests (pg_regress)"
if [[ $cluster_up -eq 1 ]]; then
  make --no-print-directory installcheck 2>&1 | tee "$logs/regress.log"
  rc=${PIPESTATUS[0]}
  # PostgreSQL 15 prints "All 3 tests passed." or "2 of 3 tests failed." (maybe with "(n failed but ignored)").
  all=$(count "$logs/regress.log" '^ *All ([0-9]+) tests passed.*')
  if [[ -n "$all" ]]; then
    failed=0
  else
    failed=$(count "$logs/regress.log" '^ *([0-9]+) of [0-9]+ tests failed.*')
    all=$(count "$logs/regress.log" '^ *[0-9]+ of ([0-9]+) tests failed.*')
  fi
  if [[ -z "$all" || -z "$failed" ]]; then
    suite "regression tests (pg_regress)" 0 1
  else
    [[ $rc -ne 0 && $failed -eq 0 ]] && failed=1 all=$((all + 1))
    [[ -f "$build/regress/regression.diffs" ]] && echo "diffs: $build/regress/regression.diffs"
    suite "regression tests (pg_regress)" $((all - failed)) "$failed"
  fi
else
  suite "regression tests (pg_regress)" 0 1
fi

# --- pgTAP ----------------------------------------------------------------------------------
banner "pgTAP tests (pg_prove)"
shopt -s nullglob
tap_files=(tests/pgtap/*.sql)
if [[ $cluster_up -eq 1 && ${#tap_files[@]} -gt 0 ]] &&
  PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
    -c 'DROP DATABASE IF EXISTS arg_tap' \
    -c 'CREATE DATABASE arg_tap' && psql -X -q -d arg_tap -c 'CREATE EXTENSION pgtap'; then
  pg_prove --verbose -d arg_tap "${tap_files[@]}" 2>&1 | tee "$logs/pgtap.log"
  rc=${PIPESTATUS[0]}
  passed=$(grep -cE '^[[:space:]]*ok [0-9]+' "$logs/pgtap.log")
  failed=$(grep -cE '^[[:space:]]*not ok [0-9]+' "$logs/pgtap.log")
  # A file that died or broke its plan has rc != 0 without a "not ok" line.
  [[ $rc -ne 0 && $failed -eq 0 ]] && failed=1
  [[ $((passed + failed)) -eq 0 ]] && failed=1
  suite "pgTAP tests (pg_prove)" "$passed" "$failed"
else
  suite "pgTAP tests (pg_prove)" 0 1
fi

# --- dump/restore and binary COPY round trips -----------------------------------------------
banner "round trips (pg_dump, COPY)"
if [[ $cluster_up -eq 1 ]]; then
  tests/sql_roundtrip.sh 2>&1 | tee "$logs/roundtrip.log"
  rc=${PIPESTATUS[0]}
  passed=$(grep -cE '^ok [0-9]+' "$logs/roundtrip.log")
  failed=$(grep -cE '^not ok [0-9]+' "$logs/roundtrip.log")
  [[ $rc -ne 0 && $failed -eq 0 ]] && failed=1
  [[ $((passed + failed)) -eq 0 ]] && failed=1
  suite "round trips (pg_dump, COPY)" "$passed" "$failed"
else
  suite "round trips (pg_dump, COPY)" 0 1
fi

# Stop the cluster before the summary so that the summary stays the last line.
tools/pg/cluster.sh stop "$pgdir" --remove || suite "cluster shutdown" 0 1
trap - EXIT

# --- sharding with postgres_fdw (three clusters of its own) ---------------------------------
banner "shards (postgres_fdw)"
tests/scale/shards.sh 2>&1 | tee "$logs/shards.log"
rc=${PIPESTATUS[0]}
passed=$(grep -cE '^ok [0-9]+' "$logs/shards.log")
failed=$(grep -cE '^not ok [0-9]+' "$logs/shards.log")
[[ $rc -ne 0 && $failed -eq 0 ]] && failed=1
[[ $((passed + failed)) -eq 0 ]] && failed=1
suite "shards (postgres_fdw)" "$passed" "$failed"

banner "summary"
printf '%s\n' "${summary[@]}"
echo "$total_pass passed, $total_fail failed"
[[ $total_fail -eq 0 ]]
