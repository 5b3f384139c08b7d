#!/usr/bin/env bash
# Runs every test suite and ends with one line "N passed, N failed" that adds them all up:
#   unit        GoogleTest, one shard a core (the CMake build in $BUILD_DIR; test_reference.cpp:
#               docs/REFERENCE.md covers every build option, weight key and preset)
#   argtool     tests/argtool/cli.sh: fast start, images loaded on demand, progress in a log file
#   stages      tests/layering/check_stages.sh: core/stages.cmake refuses includes against the
#               stage order (and passes on the tree)
#   versions    tests/versions/unsupported.sh: a build against PostgreSQL 14 or 18 stops at once,
#               naming the supported versions
#   regression  pg_regress on sql/ + expected/ (make installcheck)
#   pgtap       pg_prove on tests/pgtap/*.sql (04_reference.sql: docs/REFERENCE.md covers the SQL
#               objects, settings and SQLSTATEs)
#   reference   tests/reference/examples.sh: every example of docs/REFERENCE.md runs as it says
#   readme      tests/reference/readme_examples.sh: every example of README.md and of the Python
#               client's README runs as written against a database made as the demo makes it
#   round trips tests/sql_roundtrip.sh: pg_dump/pg_restore and COPY (FORMAT binary) of arg values
#   upgrade     tests/upgrade/upgrade.sh: a 0.1.0 database with its values, a generated column and
#               GiST indexes through ALTER EXTENSION arg UPDATE, and its dump restored at today's
#   cancel      tests/cancel/cancel.sh: statement_timeout and pg_cancel_backend stop long statements
#   memory      tests/oom/out_of_memory.sh: a backend out of address space gets 53200 and goes on
#   python      pytest on clients/python/tests: the psycopg client (Debian's python3, or $ARG_PYTHON)
#   browser     tests/browser/run_browser_tests.sh: the catalogue browser (tools/browser) on a
#               sample catalogue, driven by headless Chromium (selenium, chromium-driver)
#   server log  no backend of the throwaway cluster died ("terminated by signal") during the above,
#               read where tools/pg/cluster.sh log-path says the log is; and a test of that check
#   shards      tests/scale/shards.sh: postgres_fdw, a coordinator and two shards (its own clusters)
#   recovery    tests/recovery/index_recovery.sh: the arg_ivf index through crashes (SIGKILL,
#               immediate stop) and on a streaming standby with wal_consistency_checking
#   pg17        tests/versions/pg17.sh: the SQL suites above (regression to out of memory) against
#               PostgreSQL 17, built and run in a Debian 13 root made from Debian's archive
#   packages    make deb here and in the Debian 13 root, each package installed with apt-get into
#               a clean root that has only its PostgreSQL (tests/packages/deb_install.sh)
#   sanitizers  the unit tests again, built with ASan + UBSan in build-asan/
#   fuzz        every libFuzzer target for FUZZ_SECONDS (default 10) seconds from the fixed seed
#               FUZZ_SEED (default 1), so the run is repeatable (clang, build-fuzz/)
# ARG_QUICK=1 skips the sanitizer build and the fuzz run (the slow part: about 15 minutes).
# ARG_SUITES=sql runs only the suites on the throwaway cluster that test the extension in SQL
# (pg_regress, pgTAP, reference examples, round trips, upgrade, cancellation, out of memory,
# server log): what tests/versions/pg17.sh runs against another PostgreSQL. PG_CONFIG picks the
# server (default PostgreSQL 15's).
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
# Each suite's line says how long it took since the previous one ended (its set-up included).
last_end=$SECONDS
suite() {
  summary+=("$(printf '  %-32s %s passed, %s failed  (%d s)' "$1" "$2" "$3" $((SECONDS - last_end)))")
  last_end=$SECONDS
  total_pass=$((total_pass + $2))
  total_fail=$((total_fail + $3))
}

# Counts "N" in the first line of FILE matching the extended regex with one group (or empty).
count() { sed -nE "s/$2/\1/p" "$1" | head -n 1; }

banner() { printf '\n=== %s\n' "$*"; }

# Runs DIR/arg_unit_tests as one googletest shard a core and records the shards' summaries:
# gtest_shards NAME DIR LOG_PREFIX. One process a shard rather than CTest's process a test
# (tests/unit is still registered with CTest for `ctest -R`): the binary takes about a second
# to start, mapping and relocating some 260 shared libraries (the image and volume libraries'
# dependencies), and over 836 tests that was most of the suite's time, three times more under
# the sanitizers. Every test is listed in build/test-logs/PREFIX.N.log; failures are printed.
gtest_shards() {
  local name=$1 dir=$2 prefix=$3 shards i status shard_log passed failed skipped
  local all_pass=0 all_fail=0 all_skip=0 pids=()
  shards=$(nproc)
  for ((i = 0; i < shards; ++i)); do
    (cd "$dir" && GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i timeout 3000 ./arg_unit_tests) \
      >"$logs/$prefix.$i.log" 2>&1 &
    pids+=($!)
  done
  for ((i = 0; i < shards; ++i)); do
    wait "${pids[$i]}"
    status=$?
    shard_log=$logs/$prefix.$i.log
    passed=$(count "$shard_log" '^\[  PASSED  \] ([0-9]+) tests?\.$')
    failed=$(count "$shard_log" '^\[  FAILED  \] ([0-9]+) tests?, listed below:$')
    skipped=$(count "$shard_log" '^\[  SKIPPED \] ([0-9]+) tests?, listed below:$')
    if [[ -z "$passed" ]]; then
      # No summary: the shard died (a sanitizer report, a crash, the timeout); its log says where.
      echo "shard $i of $shards: exit status $status and no summary; the end of $shard_log:"
      tail -n 60 "$shard_log"
      all_fail=$((all_fail + 1))
      continue
    fi
    failed=${failed:-0} skipped=${skipped:-0}
    if [[ $failed -gt 0 ]]; then
      grep -E '^\[  FAILED  \]|Failure$|ERROR: |runtime error' "$shard_log"
    elif [[ $status -ne 0 ]]; then
      # Every test passed, yet the process failed: a leak report at exit, say.
      echo "shard $i of $shards: exit status $status after its tests; the end of $shard_log:"
      tail -n 40 "$shard_log"
      failed=1
    fi
    # googletest's PASSED leaves out the skipped tests (data under ../shared absent).
    echo "shard $i of $shards: $passed passed, $failed failed, $skipped skipped (exit status $status)"
    all_pass=$((all_pass + passed)) all_fail=$((all_fail + failed)) all_skip=$((all_skip + skipped))
  done
  [[ $all_skip -gt 0 ]] && name="$name ($all_skip skipped)"
  suite "$name" "$all_pass" "$all_fail"
}

# Runs a script that prints TAP lines ("ok N", "not ok N") and records them:
# tap_script NAME LOGNAME CAN_RUN COMMAND... (CAN_RUN 0: the suite counts as one failure).
tap_script() {
  local name=$1 log=$logs/$2.log can_run=$3
  shift 3
  if [[ $can_run -ne 1 ]]; then
    suite "$name" 0 1
    return
  fi
  "$@" 2>&1 | tee "$log"
  line_suite "$name" "$log" "${PIPESTATUS[0]}" '^[[:space:]]*ok [0-9]+' '^[[:space:]]*not ok [0-9]+'
}

# Records a pytest run from its closing line ("3 failed, 40 passed, 1 error in 9.1s"):
# pytest_suite NAME LOG EXIT_STATUS. Errors count as failures, skipped tests as neither (the
# suite's line says how many); a run that closed on no test or died counts as one failure.
pytest_suite() {
  local closing passed failed errors skipped name=$1
  closing=$(grep -E '^=* *[0-9]+ (passed|failed|errors?|skipped)' "$2" | tail -n 1)
  number_of() { grep -oE "[0-9]+ $1" <<<"$closing" | grep -oE '^[0-9]+' || echo 0; }
  passed=$(number_of passed) failed=$(number_of failed) errors=$(number_of 'errors?')
  skipped=$(number_of skipped)
  failed=$((failed + errors))
  [[ $3 -ne 0 && $failed -eq 0 ]] && failed=1
  [[ $((passed + failed)) -eq 0 ]] && failed=1
  [[ $skipped -gt 0 ]] && name="$1 ($skipped skipped)"
  suite "$name" "$passed" "$failed"
}

# Records a suite from the lines of its log: line_suite NAME LOG EXIT_STATUS PASS_RE FAIL_RE.
# A run that died (exit status not 0 without a failing line) or printed nothing is a failure.
line_suite() {
  local passed failed
  passed=$(grep -cE "$4" "$2")
  failed=$(grep -cE "$5" "$2")
  [[ $3 -ne 0 && $failed -eq 0 ]] && failed=1
  [[ $((passed + failed)) -eq 0 ]] && failed=1
  suite "$1" "$passed" "$failed"
}

sql_only=0
[[ "${ARG_SUITES:-all}" == sql ]] && sql_only=1

# --- unit tests -----------------------------------------------------------------------------
if [[ $sql_only -eq 0 ]]; then
banner "unit tests (googletest)"
gtest_shards "unit tests (googletest)" "$build" unit

# --- argtool as scripts run it ---------------------------------------------------------------
banner "argtool command line"
tap_script "argtool command line" argtool 1 tests/argtool/cli.sh "$build/argtool"

# --- the core's stage order ------------------------------------------------------------------
banner "core stage order"
tap_script "core stage order" layering 1 tests/layering/check_stages.sh
banner "unsupported PostgreSQL versions"
tap_script "unsupported PostgreSQL versions" unsupported 1 tests/versions/unsupported.sh
fi

# The Debian 13 root for the PostgreSQL 17 suites is made and built in the background while the
# SQL suites run (debootstrap and apt mostly wait on the network; started after the argtool
# suite, whose start-up times a busy machine would distort); its suites run after the shards.
# So are the clean roots the packages are installed into. make test starts making the roots
# before its build (tests/versions/head_start.sh): here each waits for that (flock) and finds
# its root made.
if [[ $sql_only -eq 0 ]]; then
  tests/versions/pg17.sh prepare >"$logs/pg17-prepare.log" 2>&1 &
  pg17_prepare=$!
  tests/packages/deb_install.sh prepare 15 >"$logs/clean15-prepare.log" 2>&1 &
  clean15_prepare=$!
  tests/packages/deb_install.sh prepare 17 >"$logs/clean17-prepare.log" 2>&1 &
  clean17_prepare=$!
fi

# --- the throwaway cluster ------------------------------------------------------------------
banner "throwaway cluster"
trap 'tools/pg/cluster.sh stop "$pgdir" --remove' EXIT
trap 'exit 130' INT TERM HUP
cluster_up=0
# A line this run writes into its server's log, which the server-log check looks for: proof
# that the log it reads is the running server's, not a copy an earlier run left.
run_marker="arg run_all $(date -u +%Y%m%dT%H%M%S) $$ $RANDOM"
if tools/pg/cluster.sh start "$pgdir" --fresh; then
  # shellcheck disable=SC1091
  source "$pgdir/env"
  cluster_up=1
  psql -X -q -d postgres -c "DO \$\$BEGIN RAISE LOG '%', '$run_marker'; END\$\$" ||
    echo "could not write the marker into the server log: the server-log check will fail"
fi

# --- pg_regress -----------------------------------------------------------------------------
banner "regression tests (pg_regress)"
if [[ $cluster_up -eq 1 ]]; then
  make --no-print-directory installcheck 2>&1 | tee "$logs/regress.log"
  rc=${PIPESTATUS[0]}
  # PostgreSQL 15 prints "All 3 tests passed." or "2 of 3 tests failed." (maybe with "(n failed
  # but ignored)"); PostgreSQL 17 the same after "# ".
  all=$(count "$logs/regress.log" '^#? *All ([0-9]+) tests passed.*')
  if [[ -n "$all" ]]; then
    failed=0
  else
    failed=$(count "$logs/regress.log" '^#? *([0-9]+) of [0-9]+ tests failed.*')
    all=$(count "$logs/regress.log" '^#? *[0-9]+ of ([0-9]+) tests failed.*')
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
can_prove=0
if [[ $cluster_up -eq 1 && ${#tap_files[@]} -gt 0 ]] &&
  PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
    -c 'DROP DATABASE IF EXISTS arg_tap' \
    -c 'CREATE DATABASE arg_tap' && psql -X -q -d arg_tap -c 'CREATE EXTENSION pgtap'; then
  can_prove=1
fi
tap_script "pgTAP tests (pg_prove)" pgtap "$can_prove" pg_prove --verbose -d arg_tap "${tap_files[@]}"

# --- scripts that print TAP lines on the throwaway cluster -----------------------------------
banner "reference examples (docs/REFERENCE.md)"
tap_script "reference examples" reference "$cluster_up" tests/reference/examples.sh

if [[ $sql_only -eq 0 ]]; then
  banner "README examples (README.md, clients/python/README.md)"
  tap_script "README examples" readme "$cluster_up" tests/reference/readme_examples.sh
fi

banner "round trips (pg_dump, COPY)"
tap_script "round trips (pg_dump, COPY)" roundtrip "$cluster_up" tests/sql_roundtrip.sh

banner "upgrade from 0.1.0 (ALTER EXTENSION, pg_dump)"
tap_script "upgrade from 0.1.0" upgrade "$cluster_up" tests/upgrade/upgrade.sh

banner "cancellation (statement_timeout, pg_cancel_backend)"
tap_script "cancellation" cancel "$cluster_up" tests/cancel/cancel.sh

banner "out of memory (prlimit on one backend)"
tap_script "out of memory" oom "$cluster_up" tests/oom/out_of_memory.sh

# --- the Python client, on the same cluster ---------------------------------------------------
if [[ $sql_only -eq 0 ]]; then
banner "python client (pytest)"
# Debian's interpreter, which sees the python3-psycopg, -numpy and -pytest packages (another
# python3 may come first on PATH).
python=${ARG_PYTHON:-/usr/bin/python3}
can_pytest=0
if [[ $cluster_up -eq 1 ]] && "$python" -c 'import psycopg, numpy, pytest' &&
  PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres -v ON_ERROR_STOP=1 \
    -c 'DROP DATABASE IF EXISTS arg_python' -c 'CREATE DATABASE arg_python'; then
  can_pytest=1
fi
if [[ $can_pytest -eq 1 ]]; then
  (cd clients/python && PGDATABASE=arg_python PYTHONDONTWRITEBYTECODE=1 \
    timeout 900 "$python" -m pytest -p no:cacheprovider -q -rfE) 2>&1 | tee "$logs/pytest.log"
  pytest_suite "python client (pytest)" "$logs/pytest.log" "${PIPESTATUS[0]}"
else
  suite "python client (pytest)" 0 1
fi

# --- the catalogue browser in headless Chromium, on the same cluster ------------------------
banner "catalogue browser (chromium)"
tap_script "catalogue browser (chromium)" browser "$cluster_up" tests/browser/run_browser_tests.sh
fi

# --- the server survived everything above ---------------------------------------------------
banner "server log"
# The log is where the cluster keeps it: in DIR, or in /tmp beside a data directory the
# postgres user can reach (a checkout under a 0700 home); cluster.sh says which, or why none.
if [[ $cluster_up -eq 1 ]]; then
  server_log=$(tools/pg/cluster.sh log-path "$pgdir")
  if tests/server_log/check.sh "$server_log" "$run_marker"; then
    suite "server log: no crash" 1 0
  else
    suite "server log: no crash" 0 1
  fi
else
  echo "server log: the cluster did not start, so there is no log to check"
  suite "server log: no crash" 0 1
fi
[[ $sql_only -eq 0 ]] &&
  tap_script "server log check (self-test)" server_log_check 1 tests/server_log/check_test.sh

# Stop the cluster before the summary so that the summary stays the last line.
tools/pg/cluster.sh stop "$pgdir" --remove || suite "cluster shutdown" 0 1
trap - EXIT

if [[ $sql_only -eq 1 ]]; then
  banner "summary"
  printf '%s\n' "${summary[@]}"
  echo "$total_pass passed, $total_fail failed"
  [[ $total_fail -eq 0 ]]
  exit
fi

# --- sharding with postgres_fdw (three clusters of its own) ---------------------------------
banner "shards (postgres_fdw)"
tap_script "shards (postgres_fdw)" shards 1 tests/scale/shards.sh

banner "index through crashes and on a standby"
tap_script "index: crashes and a standby" recovery 1 tests/recovery/index_recovery.sh

# --- the SQL suites against PostgreSQL 17, in a Debian 13 root --------------------------------
banner "PostgreSQL 17 (Debian 13 root)"
wait "$pg17_prepare" || echo "pg17: the root or its build failed in the background ($logs/pg17-prepare.log); trying again"
tests/versions/pg17.sh 2>&1 | tee "$logs/pg17.log"
pg17_status=${PIPESTATUS[0]}
pg17_pass=$(count "$logs/pg17.log" '^([0-9]+) passed, [0-9]+ failed$')
pg17_fail=$(count "$logs/pg17.log" '^[0-9]+ passed, ([0-9]+) failed$')
if [[ -z "$pg17_pass" ]]; then
  suite "PostgreSQL 17: SQL suites" 0 1
else
  [[ $pg17_status -ne 0 && $pg17_fail -eq 0 ]] && pg17_fail=1
  suite "PostgreSQL 17: SQL suites" "$pg17_pass" "$pg17_fail"
fi

# --- Debian packages, installed into clean roots --------------------------------------------
banner "Debian packages for PostgreSQL 15 (Debian 12)"
wait "$clean15_prepare"
if make --no-print-directory deb >"$logs/deb15.log" 2>&1; then
  tap_script "package on PostgreSQL 15, clean Debian 12" deb15-install 1 \
    tests/packages/deb_install.sh 15 "$build/deb"
else
  tail -n 20 "$logs/deb15.log"
  suite "package on PostgreSQL 15, clean Debian 12" 0 1
fi
banner "Debian packages for PostgreSQL 17 (Debian 13)"
wait "$clean17_prepare"
if tests/versions/pg17.sh deb >"$logs/deb17.log" 2>&1; then
  tap_script "package on PostgreSQL 17, clean Debian 13" deb17-install 1 \
    tests/packages/deb_install.sh 17 "$(dirname "$(grep -m1 'postgresql-17-arg_' "$logs/deb17.log")")"
else
  tail -n 20 "$logs/deb17.log"
  suite "package on PostgreSQL 17, clean Debian 13" 0 1
fi

# --- sanitizers and fuzz smoke (skipped with ARG_QUICK=1) -------------------------------------
if [[ "${ARG_QUICK:-0}" == 1 ]]; then
  echo "ARG_QUICK=1: skipping the sanitizer build and the fuzz smoke run"
else
  # The unit tests again, built with AddressSanitizer and UndefinedBehaviorSanitizer.
  banner "unit tests under ASan + UBSan"
  asan=${ASAN_BUILD_DIR:-build-asan}
  # -O1 -g1 (line tables for the reports), as the sanitizers' documentation suggests: it
  # compiles in about half the time of -O2 -g and still finds what -O2 finds. Only the unit
  # tests' target: argtool's 28 files would add a minute to CI's hour and run nothing here.
  if cmake -S . -B "$asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARG_SANITIZE=ON \
       -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
       -DARG_BUILD_BENCH=OFF -DARG_WERROR=OFF >"$logs/asan-configure.log" 2>&1 &&
     cmake --build "$asan" -j "$(nproc)" --target arg_unit_tests \
       >"$logs/asan-build.log" 2>&1; then
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      gtest_shards "unit tests under ASan + UBSan" "$asan" asan
  else
    tail -n 30 "$logs/asan-configure.log" "$logs/asan-build.log"
    suite "unit tests under ASan + UBSan" 0 1
  fi

  # Every libFuzzer target for FUZZ_SECONDS (10 s) from its committed corpus, built at -O1 like
  # the sanitizer build: a smoke run inside make test's hour; `make fuzz` runs longer.
  banner "fuzz smoke run (${FUZZ_SECONDS:-10} s per target)"
  FUZZ_SEED=${FUZZ_SEED:-1} FUZZ_SECONDS=${FUZZ_SECONDS:-10} FUZZ_OPT=${FUZZ_OPT:--O1 -g1} \
    tests/fuzz/run_fuzz.sh 2>&1 | tee "$logs/fuzz.log"
  line_suite "fuzz smoke run" "$logs/fuzz.log" "${PIPESTATUS[0]}" \
    '^fuzz_[a-z_]+ .* ok, nothing found$' '^fuzz_[a-z_]+ .* CRASH'
fi

banner "summary"
printf '%s\n' "${summary[@]}"
echo "(run_all took $((SECONDS / 60)) min $((SECONDS % 60)) s)"
echo "$total_pass passed, $total_fail failed"
[[ $total_fail -eq 0 ]]
