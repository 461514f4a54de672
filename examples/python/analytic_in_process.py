#!/usr/bin/env python3
"""What running the analytic level in the Python process saves: the wall time of
cdvp.run(..., fidelity="analytic"), which runs in this process, against the same
run in a `cdvp run` child started from Python with its report read back (what
cdvp.run did for every level before), alternated, medians of --repeats each,
one row a size.

    PYTHONPATH=build/sw/python /usr/bin/python3 examples/python/analytic_in_process.py
"""

import argparse
import json
import os
import statistics
import subprocess
import tempfile

import cdvp
from run_overhead import timed  # beside this script

def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--objects", type=int, nargs="+", default=[100, 500, 2000, 8000])
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    report = os.path.join(tempfile.mkdtemp(), "report.json")
    print(f"analytic runs on adm-xrc-ii, spheres, {args.frames} frames: medians of {args.repeats}, alternated")
    print(f"{'objects':>8} {'in process ms':>14} {'child ms':>10} {'child / in process':>19}")
    for objects in args.objects:
        options = {"board": "adm-xrc-ii", "scene": "spheres", "objects": objects, "frames": args.frames,
                   "fidelity": "analytic"}
        command = [cdvp.find_binary(), "run", *[w for k, v in options.items() for w in ("--" + k, str(v))],
                   "--report", report, "-q"]

        def child():
            subprocess.run(command, check=True)
            with open(report) as file:
                json.load(file)

        inside, outside = [], []
        for _ in range(args.repeats):
            inside.append(timed(lambda: cdvp.run(**options)))
            outside.append(timed(child))
        inside_ms, outside_ms = statistics.median(inside) * 1e3, statistics.median(outside) * 1e3
        print(f"{objects:>8} {inside_ms:>14.2f} {outside_ms:>10.2f} {outside_ms / inside_ms:>19.2f}")


if __name__ == "__main__":
    main()
