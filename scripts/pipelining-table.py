#!/usr/bin/env python3
"""The pipelining answers from scripts/pipelining.sh's sweep (docs/answers.md, "Pipelining"):

    scripts/pipelining-table.py OUT

OUT/sweep/sweep.csv: one and two box banks x interrupt policy x m on both presets against N (traces).

At each board, number of banks, interrupt policy and N it takes the largest m whose point ran (a
larger m may not fit the device, which refuses it), compares its mean frame (the host's time a
frame: the throughput) with each baseline's, and prints the crossover N per baseline and the mean
throughput and latency at the N nearest 500 as Markdown; writes OUT/pipelining.csv. Software times are pooled: at each board
and N a baseline's time is the median over every point's (the same frames each time).
"""
import csv
import importlib.util
import pathlib
import statistics
import sys
from collections import defaultdict

here = pathlib.Path(__file__).resolve().parent
spec = importlib.util.spec_from_file_location("communication_table", here / "communication-table.py")
communication_table = importlib.util.module_from_spec(spec)
spec.loader.exec_module(communication_table)
BASELINES = communication_table.BASELINES
crossover = communication_table.crossover


def main(out):
    with open(out / "sweep" / "sweep.csv", newline="") as f:
        data = [r for r in csv.DictReader(f) if r["status"] == "ok"]
    if not data:
        sys.exit("pipelining-table.py: no point of the sweep ran")
    software = defaultdict(list)
    best = {}  # (board, banks, interrupts, n) -> the row at the largest m that ran
    for r in data:
        n = int(r["config.capacity"])  # the trace's largest frame
        for b in BASELINES:
            software[(r["board"], b, n)].append(float(r[f"{b}_mean_host_ns"]))
        key = (r["board"], r["box-banks"], r["interrupts"], n)
        if key not in best or int(r["m"]) > int(best[key]["m"]):
            best[key] = r
    table = []
    for bd, banks, interrupts in sorted({k[:3] for k in best}):
        ns = sorted(k[3] for k in best if k[:3] == (bd, banks, interrupts))
        rows = {n: best[(bd, banks, interrupts, n)] for n in ns}
        times = {n: float(rows[n]["mean_total_ns"]) for n in ns}
        row = {"board": bd, "box_banks": banks, "interrupts": interrupts}
        at = min(ns, key=lambda n: abs(n - 500))  # the paper's scene size, or the nearest
        row["n"] = at
        row["m"] = rows[at]["m"]
        row["throughput_us"] = "%.1f" % (times[at] / 1e3)
        row["latency_us"] = "%.1f" % (float(rows[at]["mean_latency_ns"]) / 1e3)
        for b in BASELINES:
            soft = {n: statistics.median(software[(bd, b, n)]) for n in ns}
            n, how = crossover(ns, times, soft)
            row[b] = "never" if n is None else ("%.0f" % n if how == "interpolated" else "<=%d" % n)
        table.append(row)
    with open(out / "pipelining.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0].keys()))
        w.writeheader()
        w.writerows(table)
    print("| board | box banks | interrupts | m at N | frame (throughput) | latency | "
          + " | ".join(f"crossover N vs {b}" for b in BASELINES) + " |")
    print("|---|---:|---|---:|---:|---:|" + "---:|" * len(BASELINES))
    for r in table:
        print(f"| {r['board']} | {r['box_banks']} | {r['interrupts']} | {r['m']} at {r['n']} | "
              f"{r['throughput_us']} us | {r['latency_us']} us | " + " | ".join(r[b] for b in BASELINES) + " |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(pathlib.Path(sys.argv[1]))
