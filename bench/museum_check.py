#!/usr/bin/env python3
"""The museum check: nearest neighbour by category and the spread of SIM on a catalogue folder.

  bench/museum_check.py [--data DIR] [--argtool PATH] [--threads N] [--cache DIR] [--weights W]
                        [--method M]

DIR (default ../shared/data/museum) holds meshes and a catalogue.csv with the columns file,
title and category, as `make demo MODELS=DIR` loads them. Every model queries all the others
under SIM (0 = identical; or another `argtool eval --method`'s distance) through
`argtool eval --matrix`. Prints, as Markdown: NN per category
(a model's nearest has its category; categories of one model are left out, having no answer),
each model's nearest and its SIM, and the spread a curator sees: the nearest SIM against the
tenth. Exits 0 with a message when DIR is absent.
"""
import argparse
import csv
import os
import statistics
import subprocess
import sys
import tempfile


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--data", default=os.path.join(root, "..", "shared", "data", "museum"))
    p.add_argument("--argtool", default=os.path.join(root, "build", "argtool"))
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--cache", default="")
    p.add_argument("--weights", default="arg")
    p.add_argument("--method", default="arg")
    a = p.parse_args()
    catalogue = os.path.join(a.data, "catalogue.csv")
    if not os.path.isfile(catalogue):
        print(f"museum_check: skipped, no {catalogue}")
        return 0
    with open(catalogue, newline="") as f:
        rows = list(csv.DictReader(f))
    with tempfile.TemporaryDirectory() as work:
        labels = os.path.join(work, "labels.csv")
        with open(labels, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["model_id", "path", "class"])
            for i, r in enumerate(rows, 1):
                w.writerow([i, os.path.abspath(os.path.join(a.data, r["file"])), r["category"]])
        matrix = os.path.join(work, "sim.txt")
        cmd = [a.argtool, "eval", "--labels", labels, "--method", a.method, "--weights", a.weights,
               "--threads", str(a.threads), "--matrix", matrix]
        if a.cache:
            cmd += ["--cache", a.cache]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        with open(matrix) as f:
            d = [[float(x) for x in line.split()] for line in f if line.strip()]
    n = len(rows)
    category = [r["category"] for r in rows]
    size = {c: category.count(c) for c in set(category)}
    hits = {c: 0 for c in size}
    nearest_sim, tenth_sim, lines = [], [], []
    for q in range(n):
        order = sorted((d[q][j], j) for j in range(n) if j != q and d[q][j] != float("inf"))
        if not order:
            lines.append(f"| {rows[q]['title']} | {category[q]} | (failed) | | |")
            continue
        sim, j = order[0]
        hit = category[j] == category[q]
        hits[category[q]] += hit
        nearest_sim.append(sim)
        if len(order) >= 10:
            tenth_sim.append(order[9][0])
        lines.append(f"| {rows[q]['title']} | {category[q]} | {rows[j]['title']} "
                     f"| {sim:.3f} | {'yes' if hit else 'no'} |")
    answerable = [c for c in size if size[c] > 1]
    counted = sum(size[c] for c in answerable)
    print(f"NN over the {counted} models whose category has another member: "
          f"{sum(hits[c] for c in answerable) / counted:.3f}\n")
    print("| category | models | NN |\n|---|---|---|")
    for c in sorted(answerable, key=lambda c: (-size[c], c)):
        print(f"| {c} | {size[c]} | {hits[c] / size[c]:.3f} |")
    print("\n| model | category | nearest | SIM | same category |\n|---|---|---|---|---|")
    print("\n".join(lines))
    if nearest_sim and tenth_sim:
        gaps = [t - s for s, t in zip(nearest_sim, tenth_sim)]
        # The ratio compares methods whose distances have different units.
        ratios = [t / s for s, t in zip(nearest_sim, tenth_sim) if s > 0]
        print(f"\nSIM of the nearest: median {statistics.median(nearest_sim):.3f}; of the tenth: "
              f"median {statistics.median(tenth_sim):.3f}; tenth minus nearest: median "
              f"{statistics.median(gaps):.3f}, smallest {min(gaps):.3f}; tenth over nearest: "
              f"median {statistics.median(ratios):.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
