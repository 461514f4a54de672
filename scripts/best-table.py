#!/usr/bin/env python3
"""The table of docs/answers.md's "Against the fastest software" from best-answers.sh's sweeps:
for each board, scene and N, the board's frame time beside the fastest software's (named), the
speedup against it and its energy ratio, and the speedup against Bullet's sweep and prune where
it was timed.

    scripts/best-table.py SWEEP.csv [SWEEP.csv ...]
"""
import csv
import sys

rows = []
for path in sys.argv[1:]:
    with open(path, newline="") as f:
        rows += [r for r in csv.DictReader(f) if r.get("status") == "ok"]


def ms(ns):
    value = float(ns) / 1e6
    return f"{value:,.0f}" if value >= 1000 else f"{value:.3g}"


def board_of(r):
    return f"{r['board']}, {r.get('board.algorithm') or r.get('config.algorithm', '')}"


print("| board | scene | N | board (ms) | fastest software | its time (ms) | speedup | energy ratio | against sap |")
print("|---|---|---:|---:|---|---:|---:|---:|---:|")
key = lambda r: (r["board"], r.get("board.algorithm", ""), r.get("scene", ""), int(r["objects"]))
for r in sorted(rows, key=key):
    best = r.get("best_baseline")
    if not best:
        continue
    sap = f"{float(r['sap_speedup']):.2f}x" if r.get("sap_speedup") else ""
    print(f"| {board_of(r)} | {r.get('scene', '')} | {int(r['objects']):,} | {ms(r['mean_total_ns'])} | {best} | "
          f"{ms(r['best_mean_host_ns'])} | {float(r['best_speedup']):.2f}x | {float(r['best_energy_ratio']):.2f}x | {sap} |")
