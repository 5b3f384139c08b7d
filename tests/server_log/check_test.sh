#!/usr/bin/env bash
# The server-log check itself (tests/server_log/check.sh) and cluster.sh log-path, on made-up
# logs and folders, no server needed: a crash line fails the check, a clean log passes, a log
# that is missing or not this run's fails with a message, and log-path finds the log beside a
# data directory kept elsewhere (as in /tmp when the checkout is under a 0700 home).
# Prints TAP lines; exits non-zero when one fails.
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0 failed=0
result() { # result OK DESCRIPTION (OK: 1 or anything else)
  n=$((n + 1))
  if [[ $1 == 1 ]]; then echo "ok $n - $2"; else echo "not ok $n - $2"; failed=$((failed + 1)); fi
}
# Runs the check on LOG [MARKER]: sets rc and out (its stdout and stderr).
check() { out=$(tests/server_log/check.sh "$@" 2>&1); rc=$?; }

marker="arg run_all 20260101T000000 4242 17"
clean=$work/clean.log
cat >"$clean" <<LOG
2026-01-01 00:00:00.000 UTC [100] LOG:  starting PostgreSQL 15.8 on x86_64-pc-linux-gnu
2026-01-01 00:00:00.010 UTC [100] LOG:  database system is ready to accept connections
2026-01-01 00:00:00.100 UTC [101] LOG:  $marker
2026-01-01 00:00:01.000 UTC [102] ERROR:  canceling statement due to user request
2026-01-01 00:00:02.000 UTC [103] ERROR:  out of memory
LOG
echo "1..8"

check "$clean" "$marker"
result "$([[ $rc -eq 0 ]] && echo 1)" "a clean log with the run's marker passes (exit $rc)"

sed '$a 2026-01-01 00:00:03.000 UTC [100] LOG:  server process (PID 123) was terminated by signal 11: Segmentation fault' \
  "$clean" >"$work/segv.log"
check "$work/segv.log" "$marker"
result "$([[ $rc -eq 1 && $out == *"PID 123) was terminated by signal 11"* ]] && echo 1)" \
  "a log with a backend terminated by signal 11 fails and shows the line (exit $rc)"

sed '$a 2026-01-01 00:00:03.000 UTC [100] LOG:  server process (PID 124) was terminated by exception 0xC0000005' \
  "$clean" >"$work/other.log"
sed '$a 2026-01-01 00:00:03.000 UTC [105] PANIC:  could not write to file "pg_wal/xlogtemp.105"' \
  "$clean" >"$work/panic.log"
check "$work/other.log" "$marker"
rc_other=$rc
check "$work/panic.log" "$marker"
result "$([[ $rc_other -eq 1 && $rc -eq 1 ]] && echo 1)" \
  "another unexpected backend exit and a PANIC fail too (exit $rc_other, $rc)"

check "$work/absent.log" "$marker"
result "$([[ $rc -eq 2 && $out == *"cannot read $work/absent.log"* ]] && echo 1)" \
  "a missing log fails with a message naming it (exit $rc: $out)"

check "" "$marker"
result "$([[ $rc -eq 2 && $out == *"no log to read"* ]] && echo 1)" \
  "no log path at all fails with a message (exit $rc: $out)"

grep -vF "$marker" "$clean" >"$work/stale.log"
check "$work/stale.log" "$marker"
result "$([[ $rc -eq 2 && $out == *"not this run's server log"* ]] && echo 1)" \
  "a clean log without this run's marker (an earlier run's copy) fails with a message (exit $rc)"

# cluster.sh log-path: the log is beside the data directory, which DIR/data may link to.
mkdir -p "$work/kept/data" "$work/cluster"
: >"$work/kept/postgres.log"
: >"$work/cluster/postgres.log" # a stale copy, as stop --remove leaves
ln -s "$work/kept/data" "$work/cluster/data"
path=$(tools/pg/cluster.sh log-path "$work/cluster" 2>&1)
result "$([[ $path == "$work/kept/postgres.log" ]] && echo 1)" \
  "log-path names the log beside a data directory kept elsewhere, not the copy in DIR ($path)"

mkdir -p "$work/empty"
msg=$(tools/pg/cluster.sh log-path "$work/empty" 2>&1)
rc=$?
result "$([[ $rc -ne 0 && $msg == *"no server log at $work/empty/postgres.log"* ]] && echo 1)" \
  "log-path fails with a message where no cluster ever ran (exit $rc: $msg)"

[[ $failed -eq 0 ]]
