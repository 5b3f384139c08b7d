#!/usr/bin/env bash
# Regenerates docs/BENCHMARKS.md (retrieval quality section) from argtool eval and tune runs.
#
#   bench/quality_report.sh [LABELS.csv]     (default: ../shared/data/shrec07/labels.csv)
#
# Needs the build (make build or cmake) and python3 for the tables. The first eval builds every
# model (so build times are measured) into a fresh cache that the tuning runs then reuse.
set -euo pipefail
cd "$(dirname "$0")/.."
ARGTOOL=${ARGTOOL:-build/argtool}
LABELS=${1:-../shared/data/shrec07/labels.csv}
OUT=build/quality
CACHE="$OUT/cache"
rm -rf "$CACHE"
mkdir -p "$OUT" docs
if [ ! -f "$LABELS" ]; then
  echo "quality_report: $LABELS not found (the shared SHREC 2007 data is absent): nothing to do" >&2
  exit 0
fi
"$ARGTOOL" eval --labels "$LABELS" --method arg --method mrg --method d2 --method cords \
  --cache "$CACHE" --json "$OUT/eval.json" --plot docs/precision_recall.svg | tee "$OUT/eval.txt"
"$ARGTOOL" tune --labels "$LABELS" --folds 2 --rounds 2 --cache "$CACHE" | tee "$OUT/tune.txt"
tuned=$(tail -n 1 "$OUT/tune.txt")
"$ARGTOOL" eval --labels "$LABELS" --method arg --weights "$tuned" --cache "$CACHE" \
  --json "$OUT/eval_tuned.json" | tee "$OUT/eval_tuned.txt"
python3 bench/quality_tables.py "$OUT" "$LABELS" > "$OUT/quality.md"
python3 bench/splice_section.py docs/BENCHMARKS.md quality "$OUT/quality.md"
echo "updated docs/BENCHMARKS.md and docs/precision_recall.svg"
