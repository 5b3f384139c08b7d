#!/usr/bin/env bash
# Checks a PostgreSQL server log for backends that died: "terminated by signal", any other
# "server process ... was terminated" (an exit the postmaster did not expect), or a PANIC.
#
#   tests/server_log/check.sh LOG [MARKER]
#
# LOG comes from `tools/pg/cluster.sh log-path DIR` (the log is not always in DIR). With MARKER,
# a line the run wrote into its server's log when it started (RAISE LOG), the log must contain
# it: that shows the file read is the running server's own, not a copy an earlier run left.
# Prints what it read and the first crash lines. Exit 0: no crash; 1: a crash; 2: no log to
# read, or not this run's (the message says which).
set -uo pipefail

log=${1:-} marker=${2:-}
if [[ -z "$log" ]]; then
  echo "server log: no log to read (no path given: cluster.sh log-path found none?)" >&2
  exit 2
fi
if [[ ! -f "$log" || ! -r "$log" ]]; then
  echo "server log: cannot read $log" >&2
  exit 2
fi
if [[ -n "$marker" ]] && ! grep -qF -- "$marker" "$log"; then
  echo "server log: $log is not this run's server log (it lacks the line '$marker' written at the start)" >&2
  exit 2
fi

pattern='terminated by signal|server process .* was terminated|PANIC:'
crashes=$(grep -cE "$pattern" "$log")
found=""
[[ -n "$marker" ]] && found=", this run's marker found"
echo "server log: $crashes backend crashes in $log ($(wc -l <"$log") lines$found)"
grep -E "$pattern" "$log" | head -n 5
[[ $crashes -eq 0 ]] || exit 1
