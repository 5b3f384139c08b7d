#!/usr/bin/env bash
# Regenerates the per-class section of docs/BENCHMARKS.md: each class's NN and FT under weights
# learnt without its set (leave-one-set-out) beside the shipped weights, and the peers' FT.
#
#   bench/per_class_report.sh [DATA_DIR [PEERS_DIR]]   (default: ../shared/data ../shared/peers)
#
# Needs the build and python3. Shares quality_report.sh's cache (CACHE, default
# build/quality/cache): with it filled, about ten minutes on 2 cores (the leave-one-set-out
# search); from nothing, add about 20 minutes for 968 builds and 968 more on proxies.
set -euo pipefail
cd "$(dirname "$0")/.."
ARGTOOL=${ARGTOOL:-build/argtool}
THREADS=${THREADS:-2}
DATA=${1:-../shared/data}
PEERS=${2:-../shared/peers}
OUT=build/quality
CACHE=${CACHE:-$OUT/cache}
labels=()
for s in shrec07 shrec11 psb_soups; do
  if [ ! -f "$DATA/$s/labels.csv" ]; then
    echo "per_class_report: $DATA/$s/labels.csv not found (the shared data is absent): nothing to do" >&2
    exit 0
  fi
  labels+=(--labels "$DATA/$s/labels.csv")
done
mkdir -p "$OUT"
# 1. The held-out weights: what quality_report.sh's leave-one-set-out search learns.
"$ARGTOOL" tune "${labels[@]}" --mixing-only --proxy-copies --start arg --threads "$THREADS" \
  --cache "$CACHE" --fold-weights "$OUT/fold_weights.txt" > "$OUT/per_class_tune.txt"
# 2. Per class: held out, training (the shipped weights) and the peers.
"$ARGTOOL" eval "${labels[@]}" --per-class --weights-per-set "$OUT/fold_weights.txt" \
  --peers "$PEERS" --threads "$THREADS" --cache "$CACHE" --json "$OUT/eval_per_class.json" |
  tee "$OUT/per_class.txt"
python3 bench/per_class_tables.py "$OUT/eval_per_class.per_class.json" > "$OUT/per_class.md"
python3 bench/splice_section.py docs/BENCHMARKS.md per-class "$OUT/per_class.md"
echo "updated docs/BENCHMARKS.md"
