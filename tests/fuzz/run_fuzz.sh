#!/usr/bin/env bash
# Builds the libFuzzer targets in build-fuzz/ (clang, ASan + UBSan) and runs each for FUZZ_SECONDS.
#
#   tests/fuzz/run_fuzz.sh                          every target, 20 s each
#   FUZZ_SECONDS=1800 tests/fuzz/run_fuzz.sh        longer runs
#   FUZZ_TARGETS="fuzz_read_ply fuzz_build" ...     only these targets
#   FUZZ_SEED=1 tests/fuzz/run_fuzz.sh              the same mutations on every run (the test suite)
#   FUZZ_BUILD_DIR=... FUZZ_JOBS=... FUZZ_OPT="-O1 -g1" FUZZ_EXTRA_ARGS="-max_len=1024" ...
#
# One target at a time, one process each. Each works on build-fuzz/corpus/<target>/, seeded from
# the committed tests/fuzz/corpus/<target>/ and tests/fuzz/regressions/<target>/ (the committed
# folders are never written to), and writes what it finds to build-fuzz/artifacts/<target>/.
# Prints one line per target; exits 1 when any target crashed, leaked, timed out or ran out of
# memory (reproduce with: build-fuzz/<target> <artifact>).
set -uo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${FUZZ_SECONDS:-20}"
jobs="${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}"

if ! command -v clang++ > /dev/null; then
  echo "run_fuzz.sh: clang++ not found (apt-get install clang libclang-rt-dev)" >&2
  exit 2
fi
mkdir -p "$build"
# FUZZ_OPT: the optimisation and debug flags (make test's short run: -O1 -g1, which compiles in
# about half the time and still gives line numbers).
cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="${FUZZ_OPT:--O2 -g}" -DARG_BUILD_FUZZ=ON -DARG_BUILD_TESTS=OFF -DARG_BUILD_BENCH=OFF > "$build/configure.log" 2>&1 ||
  { cat "$build/configure.log" >&2; exit 2; }

all_targets=()
for source in "$here"/fuzz_*.cpp; do all_targets+=("$(basename "$source" .cpp)"); done
read -r -a targets <<< "${FUZZ_TARGETS:-${all_targets[*]}}"
cmake --build "$build" -j "$jobs" --target "${targets[@]}" > "$build/build.log" 2>&1 ||
  { tail -n 40 "$build/build.log" >&2; echo "run_fuzz.sh: build failed" >&2; exit 2; }

# Leaks count as findings; the sanitizers stop at the first error.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:allocator_may_return_null=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

failed=0
printf '%-20s %12s %9s  %s\n' target executions exec/s result
for target in "${targets[@]}"; do
  corpus="$build/corpus/$target"
  artifacts="$build/artifacts/$target"
  log="$build/logs/$target.log"
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  for seeds in "$here/corpus/$target" "$here/regressions/$target"; do
    [[ -d "$seeds" ]] && cp -n "$seeds"/* "$corpus"/ 2> /dev/null
  done
  start="$build/logs/$target.start"
  touch "$start"
  args=(-max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1
        -artifact_prefix="$artifacts/")
  # A fixed seed makes a short run repeatable (a test must not pass or fail by chance); without
  # one libFuzzer picks a new seed each run, which is what long runs that look for bugs want.
  [[ -n "${FUZZ_SEED:-}" ]] && args+=(-seed="$FUZZ_SEED")
  [[ -f "$here/dict/$target.dict" ]] && args+=(-dict="$here/dict/$target.dict")
  case "$target" in
    fuzz_weights | fuzz_build_options | fuzz_arg_text) args+=(-max_len=8192) ;;
    fuzz_arg_structure) args+=(-max_len=512) ;;
    *) args+=(-max_len=65536) ;;
  esac
  # shellcheck disable=SC2086
  "$build/$target" "${args[@]}" ${FUZZ_EXTRA_ARGS:-} "$corpus" > "$log" 2>&1
  status=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  found=$(find "$artifacts" -type f -newer "$start" -printf '%f ' 2> /dev/null)
  if [[ $status -ne 0 || -n "$found" ]]; then
    failed=1
    summary=$(grep -m 1 -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error|terminate called|ALARM)' \
      "$log")
    result="CRASH (exit $status) ${found:-see $log}: ${summary}"
  else
    result="ok, nothing found"
  fi
  printf '%-20s %12s %9s  %s\n' "$target" "${runs:-?}" "${speed:-?}" "$result"
done
exit $failed
