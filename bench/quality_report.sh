#!/usr/bin/env bash
# Regenerates the retrieval quality sections of docs/BENCHMARKS.md: every labelled set in one
# table, the leave-one-set-out tuning, and the robustness benchmark.
#
#   bench/quality_report.sh [DATA_DIR]      (default: ../shared/data)
#
# Needs the build (make build or cmake) and python3. The first eval builds every model on one
# thread (so build times are honest; THREADS=2 runs every step on two, faster, and the tables
# say so) into a fresh cache that the later runs reuse. About 50
# minutes on 2 cores: 968 builds and 968 more on proxies, five methods, a leave-one-set-out
# search, 11,000 perturbed builds.
set -euo pipefail
cd "$(dirname "$0")/.."
ARGTOOL=${ARGTOOL:-build/argtool}
THREADS=${THREADS:-1}
DATA=${1:-../shared/data}
OUT=build/quality
CACHE="$OUT/cache"
SETS=(shrec07 shrec11 psb_soups)
labels=()
for s in "${SETS[@]}"; do
  if [ ! -f "$DATA/$s/labels.csv" ]; then
    echo "quality_report: $DATA/$s/labels.csv not found (the shared data is absent): nothing to do" >&2
    exit 0
  fi
  labels+=(--labels "$DATA/$s/labels.csv")
done
rm -rf "$CACHE"
mkdir -p "$OUT" docs
# 1. Every set, every method: default weights (chosen by leave-one-set-out, see 2), the graph
#    alone, Hilaga's MRG, the panorama alone and D2.
"$ARGTOOL" eval "${labels[@]}" --method arg --method graph --method mrg --method panorama \
  --method d2 --threads "$THREADS" --cache "$CACHE" --json "$OUT/eval.json" --matrix "$OUT/matrix.txt" \
  --plot docs/precision_recall.svg | tee "$OUT/eval.txt"
# 2. Leave one set out: learn the mixing of SIM's terms on two sets and their proxy-built copies,
#    score on the third.
"$ARGTOOL" tune "${labels[@]}" --mixing-only --proxy-copies --start arg --threads "$THREADS" \
  --cache "$CACHE" |
  tee "$OUT/tune.txt"
# 3. Robustness: perturbed copies of two models per class query the clean set.
for s in "${SETS[@]}"; do
  "$ARGTOOL" perturb --labels "$DATA/$s/labels.csv" --out "$OUT/perturbed/$s" --per-class 2 --seed 1 \
    --threads "$THREADS"
  queries=(--queries "$OUT/perturbed/$s/clean/labels.csv")
  for q in "$OUT/perturbed/$s"/*_[1-5]/labels.csv; do queries+=(--queries "$q"); done
  "$ARGTOOL" eval --labels "$DATA/$s/labels.csv" "${queries[@]}" --method arg --threads "$THREADS" \
    --cache "$CACHE" \
    --json "$OUT/robust_$s.json" | tee "$OUT/robust_$s.txt"
done
THREADS="$THREADS" python3 bench/quality_tables.py "$OUT" > "$OUT/quality.md"
python3 bench/splice_section.py docs/BENCHMARKS.md quality "$OUT/quality.md"
echo "updated docs/BENCHMARKS.md and docs/precision_recall.svg"
