#!/usr/bin/env bash
# Regenerates the pictures in docs/pictures from the project's own model generator.
#
# Run from the repository root after the build:  docs/pictures/make_pictures.sh
# ARGTOOL overrides the argtool binary (default build/argtool). The models come from
# `argtool gen` (deterministic, no third-party data), so the pictures are the same bytes on
# every run of the same build.
set -euo pipefail

argtool=${ARGTOOL:-build/argtool}
out=docs/pictures
if [[ ! -x $argtool ]]; then
  echo "make_pictures.sh: no argtool at $argtool (build first, or set ARGTOOL)" >&2
  exit 1
fi
if [[ ! -d $out ]]; then
  echo "make_pictures.sh: run from the repository root ($out not found)" >&2
  exit 1
fi

models=$(mktemp -d)
trap 'rm -rf "$models"' EXIT
"$argtool" gen --out "$models" --per-class 3 >/dev/null

# Times one picture and prints what argtool said about it.
picture() {
  local start end
  start=$(date +%s%N)
  "$argtool" "$@" | tail -n 1
  end=$(date +%s%N)
  echo "    ($(((end - start) / 1000000)) ms: argtool $*)" | sed "s|$models/||g; s|$models|MODELS|g"
}

# Humans are aligned with the head towards -x, so roll the front view by 180 degrees to stand
# them upright.
picture render "$models/human_00.off" --level 2 --view 0,0,180 -o "$out/human_level2.png"
picture render "$models/human_00.off" --level 3 --view 0,0,180 -o "$out/human_level3.png"
picture render "$models/cup_00.off" --level 2 -o "$out/cup_level2.png"
picture render "$models/octopus_00.off" --level 3 -o "$out/octopus_level3.png"
picture render-match "$models/human_00.off" "$models/human_01.off" --level 2 --view 0,0,180 \
  --size 400 -o "$out/match_human_poses.png"
picture sheet "$models/cup_00.off" --folder "$models" --top 7 --columns 4 --thumb 150 \
  -o "$out/sheet_cup.png"
picture render "$models/human_00.off" --level 3 -o "$out/human_graph_level3.svg"

too_big=0
for f in "$out"/*.png "$out"/*.svg; do
  size=$(wc -c <"$f")
  printf '%8d  %s\n' "$size" "$f"
  if ((size > 150 * 1024)); then too_big=1; fi
done
if ((too_big)); then echo "make_pictures.sh: a picture is over 150 KB" >&2; exit 1; fi
