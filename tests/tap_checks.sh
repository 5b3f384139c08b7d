# Sourced by TAP scripts that check a running server: numbered "ok"/"not ok" lines from check
# (counting failures in $failed), psql for one value (q), and an equality that shows both sides.
# shellcheck shell=bash

n=0 failed=0
check() { # check DESCRIPTION COMMAND...: ok when the command succeeds
  local description=$1
  shift
  n=$((n + 1))
  if "$@"; then echo "ok $n - $description"; else echo "not ok $n - $description"; failed=$((failed + 1)); fi
}
q() { psql -X -q -v ON_ERROR_STOP=1 -tA "$@"; }
same() { [[ -n "$1" && "$1" == "$2" ]] || { echo "#   have: $2" >&2; echo "#   want: $1" >&2; return 1; }; }
