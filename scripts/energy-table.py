#!/usr/bin/env python3
"""The time and energy answer from scripts/energy-answers.sh's two sweeps: for each set-up, software
and core count, the crossover N on time and on energy (interpolated in log N where the speedup, or
the energy ratio, reaches 1, and where it falls back below 1 if it does) and both ratios at a few N;
and the figure's data (energy a frame against N). At each N the board's row is the fastest m that fits.

    scripts/energy-table.py 2007/sweep.csv today/sweep.csv --dat energy.dat --at 500,3200 > table.md
"""
import argparse
import csv
import math
import sys

THREADS = "config.settings.run.threads.value"


def best_rows(path):
    """{(threads, N): row}: per thread count and N, the row of the fastest m that ran."""
    best = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["status"] != "ok":
                continue
            key = (int(row[THREADS]), int(row["objects"]))
            if key not in best or float(row["mean_total_ns"]) < float(best[key]["mean_total_ns"]):
                best[key] = row
    if not best:
        sys.exit(f"{path}: no row ran (status ok)")
    return best


def interpolate(n0, r0, n1, r1):
    t = (1 - r0) / (r1 - r0)
    return round(math.exp(math.log(n0) + t * (math.log(n1) - math.log(n0))))


def crossover(points):
    """Where the ratio reaches 1 (the board wins) and, if it falls back, where it does: each N
    interpolated in log N; "<= N0" when the board wins from the first N, "none up to N1" never."""
    points = sorted(points)
    words = [f"<= {points[0][0]:,}"] if points[0][1] >= 1 else []
    for (n0, r0), (n1, r1) in zip(points, points[1:]):
        if r0 < 1 <= r1:
            words.append(f"{interpolate(n0, r0, n1, r1):,}")
        elif r1 < 1 <= r0:
            words.append(f"back below 1 at {interpolate(n0, r0, n1, r1):,}")
    return "; ".join(words) if words else f"none up to {points[-1][0]:,}"


def ratio_text(value):
    return f"{value:.2f}x"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("then")
    parser.add_argument("today")
    parser.add_argument("--dat", required=True)
    parser.add_argument("--at", default="500,3200")
    args = parser.parse_args()
    at = [int(n) for n in args.at.split(",")]
    setups = [("2007: adm-xrc-ii, Pentium 4", best_rows(args.then)),
              ("today: alveo-u250, EPYC (2 cores)", best_rows(args.today))]
    head = "| set-up | software | threads | board faster from N | board cheaper in energy from N |"
    rule = "|---|---|---:|---:|---:|"
    for n in at:
        head += f" N = {n:,}: speedup | energy ratio |"
        rule += "---:|---:|"
    print(head)
    print(rule)
    with open(args.dat, "w") as dat:
        for index, (name, rows) in enumerate(setups):
            thread_counts = sorted({t for t, _ in rows})
            objects = sorted({n for _, n in rows})
            lines = [("sap", thread_counts[0])] + [("sap_mt", t) for t in thread_counts]
            for baseline, threads in lines:
                sizes = [n for n in objects if (threads, n) in rows]
                time = [(n, float(rows[(threads, n)][f"{baseline}_speedup"])) for n in sizes]
                energy = [(n, float(rows[(threads, n)][f"{baseline}_energy_ratio"])) for n in sizes]
                # run.threads 0: as many as this machine and the host both have (the Pentium 4: one).
                host_cores = int(rows[(threads, sizes[0])]["config.settings.host.cores.value"])
                used = threads if threads > 0 else min(host_cores, 2)
                cores = (f"{used}" + (" (all)" if used == host_cores else "")) if baseline == "sap_mt" else "1"
                cells = [name, baseline if baseline == "sap_mt" else "sap (Bullet)", cores, crossover(time),
                         crossover(energy)]
                for n in at:
                    row = rows.get((threads, n))
                    cells += [ratio_text(float(row[f"{baseline}_speedup"])) if row else "",
                              ratio_text(float(row[f"{baseline}_energy_ratio"])) if row else ""]
                print("| " + " | ".join(cells) + " |")
            # The figure: energy a frame in mJ, the board's and each software line's, against N.
            dat.write(f"# {name}\n")
            columns = ["N", "board"] + [f"{b}_{t}" for b, t in lines]
            dat.write("# " + " ".join(columns) + " (mJ a frame)\n")
            for n in objects:
                first = rows.get((thread_counts[0], n))
                values = [str(n), f"{float(first['mean_energy_j']) * 1e3:.6g}"]
                for baseline, threads in lines:
                    row = rows.get((threads, n))
                    values.append(f"{float(row[f'{baseline}_energy_j']) * 1e3:.6g}" if row else "NaN")
                dat.write(" ".join(values) + "\n")
            if index + 1 < len(setups):
                dat.write("\n\n")


if __name__ == "__main__":
    main()
