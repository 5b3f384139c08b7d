#!/usr/bin/env python3
"""Turns argtool eval --per-class's JSON into the per-class tables of docs/BENCHMARKS.md."""
import json
import sys

# What museums hold, flagged in bold: vessels, busts and heads, statues' figures and hands.
MUSEUM = {"Vase", "Cup", "Mug", "Bottle", "Bust", "HumanHead", "Hand", "hand", "Human",
          "Humanoid"}
# A set with more classes shows its worst ones and every museum class, not all of them.
LONGEST = 25
WORST = 15

sets = json.load(open(sys.argv[1]))
if isinstance(sets, dict):
    sets = [sets]


def f(s, key="ft"):
    return "-" if s is None else f"{s[key]:.3f}"


for t in sets:
    peers = list(t["all"]["peers"])
    heads = [p.split("-")[0].upper() for p in peers]
    rows = [c for c in t["classes"] if c["training"] is not None]
    held = all(c["held_out"] is not None for c in rows)
    rows.sort(key=lambda c: (c["held_out"] or c["training"])["ft"])
    shown = rows
    if len(rows) > LONGEST:
        shown = [c for i, c in enumerate(rows) if i < WORST or c["class"] in MUSEUM]
    print(f"**{t['set']}** ({len(rows)} classes, worst held-out FT first"
          + ("" if shown is rows else f"; the {WORST} worst and every museum class") + ")\n")
    print("| class | size | held-out NN | held-out FT | training NN | training FT | "
          + " | ".join(h + " FT" for h in heads) + " | best peer |")
    print("|---|---|---|---|---|---|" + "---|" * len(heads) + "---|")
    for c in shown + [dict(t["all"], **{"class": "all"})]:
        name = f"**{c['class']}**" if c["class"] in MUSEUM else c["class"]
        ft = [c["peers"][p]["ft"] if c["peers"][p] else None for p in peers]
        best = max(range(len(peers)), key=lambda i: ft[i] if ft[i] is not None else -1)
        print(f"| {name} | {c['size']} | {f(c['held_out'], 'nn')} | {f(c['held_out'])} | "
              f"{f(c['training'], 'nn')} | {f(c['training'])} | "
              + " | ".join(f"{x:.3f}" for x in ft) + f" | {heads[best]} {ft[best]:.3f} |")
    if not held:
        print("\n(no held-out weights given: those columns are empty)")
    print()
