#!/usr/bin/env bash
# Regenerates docs/BENCHMARKS.md (retrieval quality section) from argtool eval and tune runs.
#
#   bench/quality_report.sh [LABELS.csv]     (default: ../shared/data/shrec07/labels.csv)
#
# Needs the build (make build or cmake) and python3 for the tables. Built ARGs are cached in
# build/arg-cache, so a second run only re-matches.
set -euo pipefail
cd "$(dirname "$0")/.."
ARGTOOL=${ARGTOOL:-build/argtool}
LABELS=${1:-../shared/data/shrec07/labels.csv}
OUT=build/quality
mkdir -p "$OUT" docs
if [ ! -f "$LABELS" ]; then
  echo "quality_report: $LABELS not found (the shared SHREC 2007 data is absent): nothing to do" >&2
  exit 0
fi
"$ARGTOOL" eval --labels "$LABELS" --method arg --method mrg --method d2 --method cords \
  --cache build/arg-cache --json "$OUT/eval.json" --plot docs/precision_recall.svg | tee "$OUT/eval.txt"
"$ARGTOOL" tune --labels "$LABELS" --folds 2 --rounds 2 --cache build/arg-cache | tee "$OUT/tune.txt"
tuned=$(tail -n 1 "$OUT/tune.txt")
"$ARGTOOL" eval --labels "$LABELS" --method arg --weights "$tuned" --cache build/arg-cache \
  --json "$OUT/eval_tuned.json" | tee "$OUT/eval_tuned.txt"
python3 bench/quality_tables.py "$OUT" "$LABELS" > "$OUT/quality.md"
echo "wrote $OUT/quality.md and docs/precision_recall.svg"
