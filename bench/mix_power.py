#!/usr/bin/env python3
"""SIM's three terms mixed by a weighted power mean instead of the weighted mean, leave-one-set-out.

  bench/mix_power.py [--argtool PATH] [--cache DIR] [--data DIR] [--fold-weights FILE] [--work DIR]

SIM is the weighted mean of the graph, PANORAMA and spectrum distances (match/term_weights.cpp).
This asks whether the weighted power mean (sum w d^p / sum w)^(1/p), p = 0 the geometric mean,
ranks better: p and a factor on each whole-shape weight are chosen, for each held-out set, by
the mean mAP of the other two sets under that set's fold weights (`argtool tune --fold-weights`,
as bench/per_class_report.sh writes them), then the held-out set is scored. Each term's matrix
comes from `argtool eval --matrix` with the other two weighed 0, and each model's proxy and
wide-open flags (which decide graph_on_proxy and whether the spectrum counts) from `argtool info
--json`: the mix of p = 1 reproduces `argtool eval`'s held-out scores to the digit. Scores as
argtool eval does (profile_mix.scores). Exits 0 with a message when the shared data is absent.
"""
import argparse
import concurrent.futures
import csv
import itertools
import json
import math
import os
import subprocess
import sys

from profile_mix import read_matrix, scores

SETS = ["shrec07", "shrec11", "psb_soups"]
MUSEUM = ["Vase", "Bust", "Cup", "Hand", "hand", "Mug", "Bottle", "HumanHead"]
POWERS = [0, 0.5, 1]
SPECTRUM = [0.25, 0.5, 1, 2]
PANORAMA = [0.5, 1, 2]


def flags_of(argtool, path):
    out = subprocess.run([argtool, "info", "--json", "--threads", "1", path], check=True,
                         capture_output=True, text=True).stdout
    d = json.loads(out)
    return bool(d["proxy"]), bool(d["wide_open"])


def lg(x):
    return math.log(max(x, 1e-9))


def mix(d, w, p):
    """The set's SIM under fold weights w and power p (term_weights.cpp's rules)."""
    G, P, S, flags = d["G"], d["P"], d["S"], d["flags"]
    wg, wp, ws = float(w["graph"]), float(w["panorama"]), float(w["spectrum"])
    gop = float(w["graph_on_proxy"])
    n = len(G)
    out = [[0.0] * n for _ in range(n)]
    for i in range(n):
        for j in range(n):
            if i == j:
                continue
            proxy = flags[i][0] or flags[j][0]
            tg = wg * gop if proxy else wg
            ts = 0.0 if (proxy or flags[i][1] or flags[j][1]) else ws
            tot = tg + wp + ts
            g, pa, s = G[i][j], P[i][j], S[i][j]
            if p == 0:  # a distance of 0 (the same spectrum) is floored: log 0 is -inf
                out[i][j] = math.exp((tg * lg(g) + wp * lg(pa) + ts * lg(s)) / tot)
            else:
                out[i][j] = ((tg * g**p + wp * pa**p + ts * s**p) / tot) ** (1 / p)
    return out


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--argtool", default=os.path.join(root, "build", "argtool"))
    ap.add_argument("--cache", default=os.path.join(root, "build", "quality", "cache"))
    ap.add_argument("--data", default=os.path.join(root, "..", "shared", "data"))
    ap.add_argument("--fold-weights",
                    default=os.path.join(root, "build", "quality", "fold_weights.txt"))
    ap.add_argument("--work", default=os.path.join(root, "build", "quality", "mix_power"))
    a = ap.parse_args()
    labels = [os.path.join(a.data, s, "labels.csv") for s in SETS]
    if not all(os.path.isfile(f) for f in labels):
        print("mix_power: skipped, the labelled sets are absent")
        return 0
    if not os.path.isfile(a.fold_weights):
        print(f"mix_power: {a.fold_weights} not found: run bench/per_class_report.sh first")
        return 1
    fold = {}
    for line in open(a.fold_weights):
        name, rest = line.split(" ", 1)
        fold[name] = dict(kv.split("=") for kv in rest.split())
    os.makedirs(a.work, exist_ok=True)
    term_weights = {"G": "arg panorama=0 spectrum=0", "P": "arg graph=0 spectrum=0",
                    "S": "arg graph=0 panorama=0"}
    for term, w in term_weights.items():
        cmd = [a.argtool, "eval", "--method", "arg", "--threads", "2", "--cache", a.cache,
               "--weights", w, "--matrix", os.path.join(a.work, term + ".txt")]
        for f in labels:
            cmd += ["--labels", f]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    data = {}
    for s, f in zip(SETS, labels):
        with open(f, newline="") as fh:
            rows = list(csv.DictReader(fh))
        paths = [os.path.join(os.path.dirname(f), r["path"]) for r in rows]
        with concurrent.futures.ThreadPoolExecutor(2) as pool:
            flags = list(pool.map(lambda p: flags_of(a.argtool, p), paths))
        data[s] = {"classes": [r["class"] for r in rows], "flags": flags}
        for term in term_weights:
            data[s][term] = read_matrix(os.path.join(a.work, f"{term}.{s}.arg.txt"))
    print("| held out | p, spectrum x, panorama x chosen | NN / FT / DCG / mAP, mean (p = 1) "
          "| power mean | museum classes' FT, p = 1 -> chosen |\n|---|---|---|---|---|")
    for held in SETS:
        train = [s for s in SETS if s != held]
        best = None
        for p, xs, xp in itertools.product(POWERS, SPECTRUM, PANORAMA):
            w = dict(fold[held])
            w["spectrum"] = str(float(w["spectrum"]) * xs)
            w["panorama"] = str(float(w["panorama"]) * xp)
            m = sum(scores(mix(data[s], w, p), data[s]["classes"])[4] for s in train) / 2
            if best is None or m > best[0] + 1e-9:
                best = (m, p, xs, xp, w)
        _, p, xs, xp, w = best
        before = scores(mix(data[held], fold[held], 1), data[held]["classes"])
        after = scores(mix(data[held], w, p), data[held]["classes"])
        fmt = lambda r: " / ".join(f"{r[k]:.3f}" for k in (0, 1, 2, 4))
        museum = ", ".join(f"{c} {before[3][c]:.3f} -> {after[3][c]:.3f}"
                           for c in MUSEUM if c in after[3])
        print(f"| {held} | {p}, {xs}, {xp} | {fmt(before)} | {fmt(after)} | {museum} |",
              flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
