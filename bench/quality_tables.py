#!/usr/bin/env python3
"""Turns what quality_report.sh wrote into the markdown tables of docs/BENCHMARKS.md."""
import json
import os
import platform
import re
import sys

out = sys.argv[1]
runs = json.load(open(os.path.join(out, "eval.json")))
tune_text = open(os.path.join(out, "tune.txt")).read()


def cpu():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


names = {"arg": "arg (default weights)", "graph": "graph alone (`graph` preset)",
         "mrg": "mrg (Hilaga et al.)", "panorama": "panorama alone", "d2": "d2 (Osada et al.)"}
sets = []
for r in runs:
    if r["set"] not in sets:
        sets.append(r["set"])

# Held-out (leave-one-set-out) scores, and the weights each fold learnt.
held = {}
for m in re.finditer(r"held out, learnt weights\s+(\S+)\s+NN ([0-9.]+)\s+FT ([0-9.]+)\s+ST ([0-9.]+)"
                     r"\s+DCG ([0-9.]+)\s+mAP ([0-9.]+)\n(?:held out, start.*\n)?\s+learnt on the other sets: (.*)",
                     tune_text):
    held[m.group(1)] = [float(m.group(k)) for k in range(2, 7)] + [m.group(7)]
train = {}
for m in re.finditer(r"training \(all sets\)\s+(\S+)\s+NN ([0-9.]+)\s+FT ([0-9.]+)\s+ST ([0-9.]+)"
                     r"\s+DCG ([0-9.]+)\s+mAP ([0-9.]+)", tune_text):
    train[m.group(1)] = [float(m.group(k)) for k in range(2, 7)]

print(f"Machine: {cpu()}, {os.cpu_count()} cores. Every model of a set queries all the others "
      "(PSB measures); a model that fails to build stays in as a query that finds nothing. " +
      ("Build times: one thread" if os.environ.get("THREADS", "1") == "1"
       else "Build times: " + os.environ["THREADS"] + " threads sharing the machine") +
      ", in process, medians; compare: median per pair.\n")
print("| set | method | NN | FT | ST | E | DCG | mAP | build ms | compare us | failed |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for s in sets:
    for r in runs:
        if r["set"] != s:
            continue
        name = names.get(r["method"], r["method"])
        if r["method"] == "arg":
            name += " (training score: the shipped weights were learnt on all three sets)"
        print(f"| {s} | {name} | {r['nn']:.3f} | {r['ft']:.3f} | {r['st']:.3f} | {r['e']:.3f} | "
              f"{r['dcg']:.3f} | {r['map']:.3f} | {r['build_ms_median']:.1f} | "
              f"{r['sim_us_median']:.2f} | {len(r['failed'])} |")
    if s in held:
        h = held[s]
        print(f"| {s} | **arg, held out** (weights learnt on the other two sets) | **{h[0]:.3f}** | "
              f"**{h[1]:.3f}** | {h[2]:.3f} | | **{h[3]:.3f}** | {h[4]:.3f} | | | |")
print("\nWeights each leave-one-set-out fold learnt (`argtool tune --mixing-only --proxy-copies`: "
      "a grid over the weights of SIM's three terms and graph_on_proxy, graph fixed at 1, on the "
      "mean mAP of the two training sets and of their copies built on proxies):\n")
for s in sets:
    if s in held:
        print(f"- held out {s}: `{held[s][5]}`")
final = re.search(r"learnt weights \(all models.*\n(.*)", tune_text)
if final:
    print(f"- all three sets, learnt by this run (the `arg` preset that ships may be an earlier "
          f"run's; its rows above are training scores either way): "
          f"`{final.group(1).strip()}`")

# Robustness: mAP of perturbed queries against the clean set, per transform and strength.
print("\n### Robustness (SHREC 2010 protocol)\n")
print("Two models per class of each set, transformed by `argtool perturb --seed 1` at strengths "
      "1 to 5, query the clean set (their own original counts as relevant). mAP per transform and "
      "strength; `clean` is the same queries untransformed.\n")
for s in sets:
    path = os.path.join(out, f"robust_{s}.json")
    if not os.path.exists(path):
        continue
    rows = [r for r in json.load(open(path)) if "queries" in r]
    clean = next((r["map"] for r in rows if r["queries"] == "clean"), None)
    table = {}
    for r in rows:
        m = re.match(r"(.*)_([1-5])$", r["queries"])
        if m:
            table.setdefault(m.group(1), {})[int(m.group(2))] = r["map"]
    print(f"**{s}** (clean mAP {clean:.3f})\n")
    print("| transform | 1 | 2 | 3 | 4 | 5 | 3 - clean |")
    print("|---|---|---|---|---|---|---|")
    for t, by in table.items():
        cells = " | ".join(f"{by[k]:.3f}" if k in by else "" for k in range(1, 6))
        delta = f"{by[3] - clean:+.3f}" if 3 in by and clean is not None else ""
        print(f"| {t} | {cells} | {delta} |")
    print()
