#!/usr/bin/env python3
"""The communication answers from scripts/communication.sh's sweeps (docs/answers.md):

    scripts/communication-table.py OUT

OUT/strategies/sweep.csv: every upload x pair format x interrupt policy on both presets against N.
OUT/moving/sweep.csv:     full against delta uploads at one N against the share of moving boxes.

Writes OUT/crossover-by-strategy.csv and OUT/delta-break-even.csv, prints both as Markdown tables,
and writes the data gnuplot draws (OUT/crossover-by-strategy.dat). Software times are pooled: at each
board and N the baseline's time is the median over every strategy's point (the same frames each time),
so strategies differ only by the board's simulated time.
"""
import csv
import math
import pathlib
import statistics
import sys
from collections import defaultdict

BASELINES = ["sap", "dbvt", "brute", "soa"]
STRATEGY = ["upload", "pair-format", "interrupts"]


def rows(path):
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(f) if r["status"] == "ok"]


def crossover(ns, board, software):
    """The smallest N where the board's mean frame beats the software's, linear in log N on log speedup."""
    previous = None
    for n in ns:
        speedup = software[n] / board[n]
        if speedup >= 1:
            if previous is None:
                return n, "at or below"
            pn, ps = previous
            t = (0 - math.log(ps)) / (math.log(speedup) - math.log(ps))
            return math.exp(math.log(pn) + t * (math.log(n) - math.log(pn))), "interpolated"
        previous = (n, speedup)
    return None, "never"


def strategies_table(out):
    data = rows(out / "strategies" / "sweep.csv")
    software = defaultdict(list)
    board = {}
    for r in data:
        n = int(r["objects"])
        for b in BASELINES:
            software[(r["board"], b, n)].append(float(r[f"{b}_mean_host_ns"]))
        board[(r["board"], tuple(r[k] for k in STRATEGY), n)] = float(r["mean_total_ns"])
    boards = sorted({r["board"] for r in data})
    strategies = sorted({tuple(r[k] for k in STRATEGY) for r in data})
    table = []
    for bd in boards:
        # The N every strategy ran at on this board (larger N may not fit its device).
        ns = sorted(n for n in {int(r["objects"]) for r in data} if all((bd, s, n) in board for s in strategies))
        for s in strategies:
            row = {"board": bd, "upload": s[0], "pair_format": s[1], "interrupts": s[2]}
            times = {n: board[(bd, s, n)] for n in ns}
            row["smallest_n"] = ns[0]
            row["board_us_at_smallest_n"] = times[ns[0]] / 1e3
            for b in BASELINES:
                soft = {n: statistics.median(software[(bd, b, n)]) for n in ns}
                n, how = crossover(ns, times, soft)
                row[b] = "" if n is None else ("%.0f" % n if how == "interpolated" else "<=%d" % n)
            table.append(row)
    with open(out / "crossover-by-strategy.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0].keys()))
        w.writeheader()
        w.writerows(table)
    # gnuplot: one block per board, a row per strategy, the crossover against each baseline.
    with open(out / "crossover-by-strategy.dat", "w") as f:
        for bd in boards:
            f.write(f"# {bd}\nstrategy {' '.join(BASELINES)}\n")
            for row in (r for r in table if r["board"] == bd):
                label = f'"{row["upload"]}/{row["pair_format"]}/{row["interrupts"]}"'
                vals = [row[b].lstrip("<=") or "NaN" for b in BASELINES]
                f.write(label + " " + " ".join(vals) + "\n")
            f.write("\n\n")
    print("| board | upload | pair format | interrupts | board frame at the smallest N | " +
          " | ".join(f"crossover N vs {b}" for b in BASELINES) + " |")
    print("|---|---|---|---|---:|" + "---:|" * len(BASELINES))
    for row in table:
        print(f"| {row['board']} | {row['upload']} | {row['pair_format']} | {row['interrupts']} | "
              f"{row['board_us_at_smallest_n']:.1f} us (N = {row['smallest_n']}) | " + " | ".join(row[b] or "never" for b in BASELINES) + " |")


def moving_table(out):
    data = rows(out / "moving" / "sweep.csv")
    upload = {(r["board"], r["upload"], float(r["moving"])): float(r["mean_upload_ns"]) for r in data}
    boards = sorted({r["board"] for r in data})
    shares = sorted({float(r["moving"]) for r in data})
    with open(out / "delta-break-even.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["board", "moving", "full_upload_ns", "delta_upload_ns", "delta_over_full"])
        print("\n| board | moving share | full upload | delta upload | delta / full |")
        print("|---|---:|---:|---:|---:|")
        notes = []
        for bd in boards:
            for m in shares:
                full, delta = upload[(bd, "full", m)], upload[(bd, "delta", m)]
                w.writerow([bd, m, full, delta, delta / full])
                print(f"| {bd} | {m:g} | {full / 1e3:.1f} us | {delta / 1e3:.1f} us | {delta / full:.2f} |")
            # Linear between the shares around the crossing: uploads grow linearly in the moved boxes.
            for a, b in zip(shares, shares[1:]):
                ra = upload[(bd, "delta", a)] / upload[(bd, "full", a)]
                rb = upload[(bd, "delta", b)] / upload[(bd, "full", b)]
                if ra < 1 <= rb:
                    notes.append(f"{bd}: delta breaks even at a moving share of {a + (1 - ra) / (rb - ra) * (b - a):.2f}")
        for note in notes or ["delta is the quicker upload at every share"]:
            print("\n" + note)


if __name__ == "__main__":
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "communication")
    strategies_table(out)
    moving_table(out)
