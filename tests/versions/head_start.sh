#!/usr/bin/env bash
# make test's head start: the Debian roots that the PostgreSQL 17 suites and the package tests
# need (debootstrap, then apt inside; they mostly wait on the network) are made in the
# background while this machine builds, so that they are ready when tests/run_all.sh reaches
# them; run_all waits for a root still being made (flock) rather than making it twice.
#
#   tests/versions/head_start.sh      start the three in the background and return at once
#
# Logs: $ARG_ROOTS (default build/roots)/head-start-*.log. Not on a machine where the roots
# cannot be made (no debootstrap: run_all then says why).
set -uo pipefail

cd "$(dirname "$0")/../.." || exit 1
roots=${ARG_ROOTS:-build/roots}
command -v debootstrap >/dev/null || exit 0
[[ "${ARG_SUITES:-all}" == all ]] || exit 0
mkdir -p "$roots"
start() { # NAME COMMAND...: in its own session, so that it outlives the make recipe's shell
  local name=$1
  shift
  setsid nohup "$@" >"$roots/head-start-$name.log" 2>&1 </dev/null &
}
start pg17-root tests/versions/pg17.sh root
start clean15 tests/packages/deb_install.sh prepare 15
start clean17 tests/packages/deb_install.sh prepare 17
echo "head start: making the Debian roots in the background ($roots/head-start-*.log)"
