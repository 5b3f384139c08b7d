#!/usr/bin/env python3
"""Mixes arg's distances with another method's (the vessel profile's, the surface detail's, ...),
(1-w) d_arg + w d_other, leave-one-set-out.

  bench/profile_mix.py [--grid W,W,...] SET LABELS ARG_MATRIX PROFILE_MATRIX [SET LABELS ARG PROFILE ...]

The matrices are `argtool eval --matrix` files. Each method's distances are divided by their
median over the training sets (so w is a share, not a unit); for each held-out set, w is the
grid value with the best mean FT on the other sets (--grid: other values than the default
0 .. 0.5). Scores as argtool eval does (every model
queries all the others, ties by index, failed models last) and prints NN, FT, DCG overall and
FT per class for the museum classes.
"""
import csv
import math
import statistics
import sys

GRID = [0.0, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5]
MUSEUM = ["Vase", "Bust", "Cup", "Hand", "hand", "Mug", "Bottle", "HumanHead"]


def read_matrix(path):
    return [[float(x) for x in line.split()] for line in open(path) if line.strip()]


def read_labels(path):
    with open(path, newline="") as f:
        return [row["class"] for row in csv.DictReader(f)]


def scores(d, labels):
    """NN, FT, DCG, FT per class and mAP, as core/eval/retrieval_metrics.cpp computes them."""
    n = len(labels)
    size = {c: labels.count(c) for c in set(labels)}
    nn = ft = dcg = ap = 0.0
    counted = 0
    per_class = {}
    for q in range(n):
        c = labels[q]
        relevant = size[c] - 1
        if relevant <= 0:
            continue
        counted += 1
        per_class.setdefault(c, []).append(0.0)
        if math.isinf(d[q][q]):
            continue  # a failed query finds nothing
        order = sorted((j for j in range(n) if j != q), key=lambda j: (d[q][j], j))
        hits = [labels[j] == c for j in order]
        nn += hits[0]
        first = sum(hits[:relevant]) / relevant
        ft += first
        per_class[c][-1] = first
        ideal = 1 + sum(1 / math.log2(k) for k in range(2, relevant + 1))
        dcg += sum((1.0 if r == 1 else 1 / math.log2(r)) for r, h in enumerate(hits, 1) if h) / ideal
        found = 0
        for r, h in enumerate(hits, 1):
            if h:
                found += 1
                ap += found / r / relevant
    return (nn / counted, ft / counted, dcg / counted,
            {c: sum(v) / len(v) for c, v in per_class.items()}, ap / counted)


def median_off_diagonal(matrices):
    return statistics.median(x for d in matrices for i, row in enumerate(d)
                             for j, x in enumerate(row) if i != j and math.isfinite(x))


def mixed(a, p, sa, sp, w):
    return [[(1 - w) * x / sa + w * y / sp for x, y in zip(ra, rp)] for ra, rp in zip(a, p)]


def main(argv):
    global GRID
    if argv[:1] == ["--grid"] and len(argv) > 1:
        GRID = sorted({0.0, *(float(w) for w in argv[1].split(","))})
        argv = argv[2:]
    if len(argv) % 4 != 0 or not argv:
        sys.exit(__doc__)
    sets = []
    for k in range(0, len(argv), 4):
        name, labels, arg_path, profile_path = argv[k:k + 4]
        sets.append((name, read_labels(labels), read_matrix(arg_path), read_matrix(profile_path)))
    for held in sets:
        train = [s for s in sets if s is not held]
        sa = median_off_diagonal([s[2] for s in train])
        sp = median_off_diagonal([s[3] for s in train])
        table = {w: [scores(mixed(s[2], s[3], sa, sp, w), s[1]) for s in train] for w in GRID}
        best = max(GRID, key=lambda w: (statistics.mean(t[1] for t in table[w]), -w))
        name, labels, a, p = held
        print(f"{name} held out: w chosen on {', '.join(s[0] for s in train)}: "
              + ", ".join(f"{w}: {statistics.mean(t[1] for t in table[w]):.3f}" for w in GRID)
              + f" -> w = {best}")
        for w in sorted({0.0, best}):
            nn, ft, dcg, per, _ = scores(mixed(a, p, sa, sp, w), labels)
            museum = " ".join(f"{c} {per[c]:.3f}" for c in MUSEUM if c in per)
            print(f"  w = {w:<4}  NN {nn:.3f}  FT {ft:.3f}  DCG {dcg:.3f}  {museum}")


if __name__ == "__main__":
    main(sys.argv[1:])
