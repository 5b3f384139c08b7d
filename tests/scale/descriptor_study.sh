#!/usr/bin/env bash
# Builds and runs the first stage's studies against the core library of the CMake build (not
# tests; the numbers go to docs/BENCHMARKS.md "Descriptor choice"):
#   tests/scale/descriptor_study.sh SET [MAX_MODELS [QUERIES]]
#       recall@10 of two-stage search per descriptor variant and candidate count, and the
#       tightness of the level-sum lower bound of SIM (tests/scale/descriptor_study.cpp)
#   tests/scale/descriptor_study.sh --tune SET SET [SET ...]
#       leave-one-set-out choice of the descriptor's block scales (descriptor_tuning.cpp)
#   tests/scale/descriptor_study.sh --ivf SET [QUERIES]
#       recall@10 of an arg_ivf search by cells and probes (ivf_study.cpp)
#   tests/scale/descriptor_study.sh --hnsw ROWS.copy N QUERIES.copy [POOL]
#       the inverted file against a navigable graph, recall by distances computed (hnsw_study.cpp)
# SET is a COPY file from `argtool scale-gen`, or a labelled set's labels.csv (model_id,path,
# class), built once into $BUILD_DIR/scale/NAME.copy (cached ARGs in $BUILD_DIR/arg-cache).
set -euo pipefail
shopt -s inherit_errexit  # a failed compile or build inside $(...) stops the script
usage() {
  echo "usage: $0 SET [MAX_MODELS [QUERIES]] | $0 --tune SET SET [SET ...] | $0 --ivf SET [QUERIES]" >&2
  echo "       $0 --hnsw ROWS.copy N QUERIES.copy [POOL]" >&2
  exit 2
}
[[ $# -ge 1 ]] || usage
# Paths as given, before the cd below.
args=()
for a in "$@"; do
  if [[ -e "$a" ]]; then args+=("$(realpath "$a")"); else args+=("$a"); fi
done
set -- "${args[@]}"
cd "$(dirname "$0")/../.."
build=${BUILD_DIR:-build}
[[ -f "$build/libargmethod.a" ]] || { echo "build the core first (make build)" >&2; exit 1; }
mkdir -p "$build/scale"

compile() {  # NAME
  local exe=$build/scale/$1
  if [[ ! -x "$exe" || tests/scale/$1.cpp -nt "$exe" || "$build/libargmethod.a" -nt "$exe" ]]; then
    g++ -std=c++17 -O2 -pthread -Icore -I/usr/include/eigen3 -D_USE_MATH_DEFINES \
      "tests/scale/$1.cpp" "$build/libargmethod.a" -lOpenMeshCore -o "$exe" >&2
  fi
  echo "$exe"
}

# A labels CSV becomes COPY rows; scale-gen wants integer ids, so rows are numbered in order.
copy_of() {  # SET
  if [[ "$1" != *.csv ]]; then echo "$1"; return; fi
  local dir name out labels
  dir=$(cd "$(dirname "$1")" && pwd)
  name=$(basename "$dir")
  out=$build/scale/$name.copy
  # Made again when argtool is newer (another builder); written whole or not at all (scale-gen
  # fails when a model does not build).
  if [[ ! -s "$out" || "$build/argtool" -nt "$out" ]]; then
    labels=$build/scale/$name.numbered.csv
    awk -F, -v d="$dir" 'NR == 1 { print; next } { print NR - 1 "," d "/" $2 "," $3 }' "$1" >"$labels"
    "$build/argtool" scale-gen --labels "$labels" --cache "$build/arg-cache" --out "$out.tmp" >&2
    mv "$out.tmp" "$out"
  fi
  echo "$out"
}

if [[ "$1" == --tune ]]; then
  shift
  [[ $# -ge 2 ]] || usage
  exe=$(compile descriptor_tuning)
  files=()
  for s in "$@"; do files+=("$(copy_of "$s")"); done
  "$exe" "${files[@]}"
elif [[ "$1" == --ivf ]]; then
  [[ $# -ge 2 ]] || usage
  exe=$(compile ivf_study)
  file=$(copy_of "$2")
  shift 2
  "$exe" "$file" "$@"
elif [[ "$1" == --hnsw ]]; then
  [[ $# -ge 4 ]] || usage
  exe=$(compile hnsw_study)
  shift
  "$exe" "$@"
else
  exe=$(compile descriptor_study)
  file=$(copy_of "$1")
  shift
  "$exe" "$file" "$@"
fi
