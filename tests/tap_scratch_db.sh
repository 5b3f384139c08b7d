# Sourced by the TAP scripts that test against a running server (tests/cancel, tests/oom): set
# `db` first. Gives result() for numbered "ok"/"not ok" lines (counting failures in $failed), a
# work folder in $work, and drops the scratch database and the folder on exit.
# shellcheck shell=bash

n=0 failed=0
result() { # result OK DESCRIPTION (OK: 1 or 0)
  n=$((n + 1))
  if [[ $1 == 1 ]]; then echo "ok $n - $2"; else echo "not ok $n - $2"; failed=$((failed + 1)); fi
}

work=$(mktemp -d)
drop_scratch_db() {
  PGOPTIONS='-c client_min_messages=warning' psql -X -q -d postgres \
    -c "DROP DATABASE IF EXISTS $db WITH (FORCE)" > /dev/null 2>&1
  rm -rf "$work"
}
trap drop_scratch_db EXIT
