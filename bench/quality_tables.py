#!/usr/bin/env python3
"""Turns the JSON written by quality_report.sh into the markdown tables of docs/BENCHMARKS.md."""
import json
import os
import platform
import re
import subprocess
import sys

out, labels = sys.argv[1], sys.argv[2]
runs = json.load(open(os.path.join(out, "eval.json")))
curves = json.load(open(os.path.join(out, "eval.curves.json")))
tuned = json.load(open(os.path.join(out, "eval_tuned.json")))
tune_text = open(os.path.join(out, "tune.txt")).read()
cv = re.search(r"cross-validated mAP ([0-9.]+) \(start weights ([0-9.]+)\)", tune_text)

def cpu():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"

print(f"Data: `{labels}` ({runs[0]['models']} models, {runs[0]['classes']} classes). "
      f"Machine: {cpu()}, {os.cpu_count()} cores. Every model queries all the others (PSB measures).\n")
print("| method | NN | FT | ST | E | DCG | mAP | build ms (median) | compare us (median) | failed |")
print("|---|---|---|---|---|---|---|---|---|---|")
names = {"arg": "arg (default weights)", "mrg": "mrg (Hilaga et al.)", "d2": "d2 (Osada et al.)",
         "cords": "cords (Paquet and Rioux)"}
for r in runs:
    print(f"| {names.get(r['method'], r['method'])} | {r['nn']:.3f} | {r['ft']:.3f} | {r['st']:.3f} | "
          f"{r['e']:.3f} | {r['dcg']:.3f} | {r['map']:.3f} | {r['build_ms_median']:.1f} | "
          f"{r['sim_us_median']:.2f} | {len(r['failed'])} |")
print(f"| arg (tuned, in-sample) | {tuned['nn']:.3f} | {tuned['ft']:.3f} | {tuned['st']:.3f} | "
      f"{tuned['e']:.3f} | {tuned['dcg']:.3f} | {tuned['map']:.3f} | | {tuned['sim_us_median']:.2f} | |")
if cv:
    print(f"\nTuned weights, honestly: 2-fold cross-validated mAP **{cv.group(1)}** on held-out folds "
          f"(the default weights score {cv.group(2)} on the same folds). The in-sample row above uses "
          "weights learnt on all models, so it overstates.\n")
by = {c["method"]: c for c in curves}
if "arg" in by and "mrg" in by:
    a, m = by["arg"]["ft_per_class"], by["mrg"]["ft_per_class"]
    print("\nFirst tier per class, arg vs mrg (sorted by arg):\n")
    print("| class | arg FT | mrg FT | gain |")
    print("|---|---|---|---|")
    for k in sorted(a, key=lambda k: a[k]):
        print(f"| {k} | {a[k]:.3f} | {m[k]:.3f} | {a[k] - m[k]:+.3f} |")
