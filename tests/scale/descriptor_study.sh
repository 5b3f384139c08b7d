#!/usr/bin/env bash
# Builds and runs tests/scale/descriptor_study.cpp against the core library of the CMake build:
# recall@10 of two-stage search per descriptor variant and candidate count, and the tightness
# of the level-sum lower bound of SIM. Not a test; the numbers go to docs/BENCHMARKS.md "Scale".
#
#   tests/scale/descriptor_study.sh FILE.copy [MAX_MODELS]    (FILE from argtool scale-gen)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${BUILD_DIR:-build}
[[ -f "$build/libargmethod.a" ]] || { echo "build the core first (make build)" >&2; exit 1; }
exe=$build/scale/descriptor_study
mkdir -p "$build/scale"
if [[ ! -x "$exe" || tests/scale/descriptor_study.cpp -nt "$exe" || "$build/libargmethod.a" -nt "$exe" ]]; then
  g++ -std=c++17 -O2 -pthread -Icore -I/usr/include/eigen3 -D_USE_MATH_DEFINES \
    tests/scale/descriptor_study.cpp "$build/libargmethod.a" -lOpenMeshCore -o "$exe"
fi
"$exe" "$@"
