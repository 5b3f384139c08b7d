#!/usr/bin/env bash
# Rebuilds the committed seed corpora (tests/fuzz/corpus/<target>/) from the project's own
# generator and writers (argtool gen/build at low resolution) plus hand-written edge cases
# (make_seeds.py). Deterministic: running it twice gives the same files.
#
#   tests/fuzz/make_corpus.sh            uses $ARGTOOL, else build-fuzz/argtool, else build/argtool
#
# The fuzzers never write into this folder: run_fuzz.sh works on a copy.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
corpus="$here/corpus"

argtool="${ARGTOOL:-}"
if [[ -z "$argtool" ]]; then
  for candidate in "$root/build-fuzz/argtool" "$root/build/argtool"; do
    if [[ -x "$candidate" ]]; then
      argtool="$candidate"
      break
    fi
  done
fi
if [[ -z "$argtool" || ! -x "$argtool" ]]; then
  echo "make_corpus.sh: no argtool found; build one (cmake --build build --target argtool)" \
       "or set ARGTOOL" >&2
  exit 1
fi
# An argtool built for fuzzing carries the sanitizers; leaks at exit are not our concern here.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=0}"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Small generated models in every format argtool writes (resolution 10: a few hundred triangles).
classes=(human fourleg octopus torus)
class_args=()
for c in "${classes[@]}"; do class_args+=(--class "$c"); done
for format in off ply stl obj; do
  "$argtool" gen --out "$work/$format" --per-class 1 --resolution 10 --format "$format" \
    "${class_args[@]}" > /dev/null
done

# ARG values of two of them, at a few levels and kinds of mu.
mkdir -p "$work/arg"
"$argtool" build --levels 2 --base-points 16 -o "$work/arg/human_l2.arg" \
  "$work/off/human_00.off" > /dev/null
"$argtool" build --levels 4 --mu height --base-points 16 -o "$work/arg/fourleg_l4_height.arg" \
  "$work/ply/fourleg_00.ply" > /dev/null
"$argtool" build --levels 3 --mu centroid --base-points 16 -o "$work/arg/torus_l3_centroid.arg" \
  "$work/stl/torus_00.stl" > /dev/null

# fuzz_arg_structure's seeds are a corpus minimised from fuzzing (committed as found, not made
# here), and fuzz_sketch's the sketches of fuzz_arg_binary's ARG seeds as the server's
# arg_sketch_send(arg_sketch(...)) wrote them (no tool here writes sketches: *.sketch in
# version 1, as arg 0.2.0 wrote them, *.sketch_v2 the same with the version-2 digest), and
# fuzz_ivf_page's three pages of an arg_ivf index the server wrote (30 scale-gen models, lists
# = 4: the metapage, a cell page, a list page; byte 0 set to the kind, 0 to 2), so only the
# other targets' folders are made afresh.
mkdir -p "$corpus"
find "$corpus" -mindepth 1 -maxdepth 1 ! -name fuzz_arg_structure ! -name fuzz_sketch \
  ! -name fuzz_ivf_page -exec rm -rf {} +
for format in off ply stl obj; do
  mkdir -p "$corpus/fuzz_read_$format"
  for c in "${classes[@]}"; do
    cp "$work/$format/${c}_00.$format" "$corpus/fuzz_read_$format/gen_${c}.$format"
  done
done
mkdir -p "$corpus/fuzz_build"
cp "$work/off/human_00.off" "$corpus/fuzz_build/gen_human.off"
cp "$work/ply/fourleg_00.ply" "$corpus/fuzz_build/gen_fourleg.ply"
cp "$work/stl/human_00.stl" "$corpus/fuzz_build/gen_human.stl"
cp "$work/obj/human_00.obj" "$corpus/fuzz_build/gen_human.obj"

# Values of earlier formats as arg 0.1.0 (format 1) and 0.2.0 (format 2) wrote them (the unit
# tests' fixtures) stay seeds of the readers; seeds are at most 64 kB.
for version in 1 2; do
  for f in "$root"/tests/unit/fixtures/format$version/*.arg; do
    [[ $(stat -c %s "$f") -le 65536 ]] && cp "$f" "$work/arg/v${version}_$(basename "$f")"
  done
done
python3 "$here/make_seeds.py" "$work" "$corpus"

# A GLB for the build target too, converted above from the generated human.
cp "$corpus/fuzz_read_glb/gen_human.glb" "$corpus/fuzz_build/gen_human.glb"

echo "corpus: $(find "$corpus" -type f | wc -l) files, $(du -sh "$corpus" | cut -f1)"
