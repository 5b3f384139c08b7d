#!/usr/bin/env bash
# The stage check of core/stages.cmake (TAP): passes on the tree, and refuses a copy of it with
# an include against the stage order or an unplaced folder, naming the file.
set -uo pipefail
cd "$(dirname "$0")/../.." || exit 1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
n=0
check() {  # check DESCRIPTION EXPECTED_STATUS(0|1) PATTERN CORE_DIR
  local out status
  out=$(cmake -DARG_CORE_DIR="$4" -P core/stages.cmake 2>&1)
  status=$?
  n=$((n + 1))
  if [[ $2 -eq 0 && $status -eq 0 ]] || [[ $2 -ne 0 && $status -ne 0 && "$out" == *"$3"* ]]; then
    echo "ok $n - $1"
  else
    echo "not ok $n - $1"
    printf '%s\n' "$out" | sed 's/^/# /'
  fi
}
check "the tree follows the stage order" 0 "" core
cp -r core "$scratch/up"
echo '#include "pipeline/build_arg.hpp"' >>"$scratch/up/mu/dijkstra.hpp"
check "mu including pipeline is refused, naming the file" 1 \
  "core/mu/dijkstra.hpp includes pipeline/" "$scratch/up"
cp -r core "$scratch/gen"
echo '#include "gen/generate_models.hpp"' >>"$scratch/gen/mesh/mesh.hpp"
check "mesh including the generator is refused" 1 "core/mesh/mesh.hpp includes gen/" "$scratch/gen"
cp -r core "$scratch/new"
mkdir "$scratch/new/extra"
check "a folder not placed in the stages is refused" 1 "place core/extra" "$scratch/new"
echo "1..$n"
