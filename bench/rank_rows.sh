#!/usr/bin/env bash
# A brute-force ranking in process (bench/standalone/rank_rows.cpp), built against the core
# library of a CMake build ($BUILD_DIR, default build):
#   bench/rank_rows.sh COPY_FILE [QUERIES [ROUNDS [DUMP]]]
# COPY_FILE is a COPY file of `argtool scale-gen` (tests/scale/descriptor_study.sh makes one
# from a labelled set into build/scale/NAME.copy). Two builds compare by running it with each
# BUILD_DIR (time a row), and by cmp of their DUMP files (every SIM, byte for byte).
set -euo pipefail
[[ $# -ge 1 ]] || { sed -n 2,7p "$0"; exit 2; }
file=$(realpath "$1")
shift
cd "$(dirname "$0")/.."
build=$(realpath "${BUILD_DIR:-build}")
[[ -f "$build/libargmethod.a" ]] || { echo "build the core first (make build)" >&2; exit 1; }
exe=$build/bench/rank_rows
mkdir -p "$build/bench"
if [[ ! -x "$exe" || bench/standalone/rank_rows.cpp -nt "$exe" || "$build/libargmethod.a" -nt "$exe" ]]; then
  g++ -std=c++17 -O2 -pthread -Icore -I/usr/include/eigen3 -D_USE_MATH_DEFINES \
    bench/standalone/rank_rows.cpp "$build/libargmethod.a" -lOpenMeshCore -o "$exe"
fi
"$exe" "$file" "$@"
