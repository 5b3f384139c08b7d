#!/usr/bin/env bash
# How often the canonical up (argtool upright without --up: the file's +Y or +Z where the model
# stands on it, else the broadest base with the centroid highest is down) agrees with the
# labelled sets' own up, beside the longest principal axis (the pictures' up before both). The sets keep +Y or +Z up, differing from file to file (SHREC 2007's figures
# and tables +Z, its busts, cups and chairs +Y), so "agrees" is: the file axis nearest to the
# chosen up is +Y or +Z. Upside down, or any X, is wrong whatever the file's convention.
#
#   bench/upright_agreement.sh [DATA_DIR] [CLASS...]   (default ../shared/data; per class too)
#
# Needs the build; about a minute on 2 cores for the three sets' 968 files.
set -euo pipefail
cd "$(dirname "$0")/.."
ARGTOOL=${ARGTOOL:-build/argtool}
DATA=${1:-../shared/data}
shift || true
for s in shrec07 shrec11 psb_soups; do
  if [ ! -f "$DATA/$s/labels.csv" ]; then
    echo "upright_agreement: $DATA/$s/labels.csv not found (the shared data is absent): nothing to do" >&2
    exit 0
  fi
done
files=$(mktemp)
trap 'rm -f "$files"' EXIT
printf 'set\tclass\tfiles\tupright\tlongest axis\n'
for s in shrec07 shrec11 psb_soups; do
  # path,class per file; argtool prints file, up, front, longest, ... per file.
  tr -d '\r' <"$DATA/$s/labels.csv" | tail -n +2 | awk -F, -v d="$DATA/$s/" '{print d $2 "\t" $3}' >"$files"
  cut -f1 "$files" | xargs -P 2 -n 40 "$ARGTOOL" upright | grep -v '^file' |
    awk -F'\t' -v set="$s" -v classes="$*" '
      NR == FNR { cls[$1] = $2; next }
      {
        c = cls[$1]; ok_new = ($2 == "+Y" || $2 == "+Z"); ok_old = ($4 == "+Y" || $4 == "+Z")
        n++; a += ok_new; b += ok_old; cn[c]++; ca[c] += ok_new; cb[c] += ok_old
      }
      END {
        printf "%s\tall\t%d\t%.1f%%\t%.1f%%\n", set, n, 100 * a / n, 100 * b / n
        k = split(classes, want, " ")
        for (i = 1; i <= k; i++) if (want[i] in cn)
          printf "%s\t%s\t%d\t%d\t%d\n", set, want[i], cn[want[i]], ca[want[i]], cb[want[i]]
      }' "$files" -
done
