#!/usr/bin/env python3
"""What cdvp.run costs over the command line on the same run: the wall time
of `cdvp run ... --report FILE -q` started from Python (subprocess) against
cdvp.run with the same options (which also reads the report back and builds
its objects), alternated, medians of --repeats each.

    PYTHONPATH=build/sw/python /usr/bin/python3 examples/python/run_overhead.py --objects 500 --frames 3
"""

import argparse
import os
import statistics
import subprocess
import tempfile
import time

import cdvp


def timed(call):
    start = time.perf_counter()
    call()
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--objects", type=int, default=500)
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--repeats", type=int, default=10)
    args = parser.parse_args()
    options = {"board": "adm-xrc-ii", "scene": "spheres", "objects": args.objects, "frames": args.frames}
    words = [w for name, value in options.items() for w in ("--" + name, str(value))]
    report = os.path.join(tempfile.mkdtemp(), "report.json")
    command = [cdvp.find_binary(), "run", *words, "--report", report, "-q"]
    cli, module = [], []
    for _ in range(args.repeats):
        cli.append(timed(lambda: subprocess.run(command, check=True)))
        module.append(timed(lambda: cdvp.run(**options)))
    cli_ms, module_ms = statistics.median(cli) * 1e3, statistics.median(module) * 1e3
    print(f"cdvp run {' '.join(words)}: medians of {args.repeats}, alternated")
    print(f"  command line (subprocess): {cli_ms:8.2f} ms")
    print(f"  cdvp.run:                  {module_ms:8.2f} ms")
    print(f"  ratio: {module_ms / cli_ms:.3f} (cdvp.run over the command line), "
          f"difference {module_ms - cli_ms:+.2f} ms")


if __name__ == "__main__":
    main()
