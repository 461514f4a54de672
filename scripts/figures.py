#!/usr/bin/env python3
"""Every figure in docs/ from the command that draws it, and whether the
checked-in one is stale.

    scripts/figures.py check [NAME ...]    (default: the fast figures)
    scripts/figures.py update [NAME ...]   redraw them into docs/
    scripts/figures.py list

    CDVP=path/to/cdvp (default build/sw/cli/cdvp), JOBS=2; NAME 'all' is every figure.

Each figure has a data file beside it in docs/ (a .csv, or the .dot of the
layer graph): the numbers it is drawn from, without the measured ones (wall
and CPU times, speedups, anything a machine's load moves), since the pixels
of a timing figure differ from run to run; a sweep's figure keeps, of each
point, its status, pairs, the board's mean frame time and its memory. `check` runs each figure's
command in a scratch directory and compares the data it gives with the
checked-in data, printing the first difference and failing (exit 1) when
they differ: the figure in docs/ was drawn from another model. `update`
runs the commands and copies the PNGs and their data into docs/.

Fast figures (seconds: the layer graph, the README's sweep, cdvp fidelity)
run in ctest (docs.figures_fresh); the slow ones (the answers' sweeps in
scripts/answers.sh, communication.sh and grid-answers.sh, minutes to an hour
on two cores) run only here, by name or with 'all'.
"""
import csv
import io
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CDVP = os.path.abspath(os.environ.get("CDVP", os.path.join(ROOT, "build", "sw", "cli", "cdvp")))
JOBS = os.environ.get("JOBS", "2")

# The deterministic columns of a sweep row a board-time figure rests on.
BOARD_TIME_COLUMNS = ["point", "status", "median_pairs", "mean_total_ns", "config.block_rams", "config.memory"]


class Stale(Exception):
    pass


def run(args, cwd, **kwargs):
    result = subprocess.run(args, cwd=cwd, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        sys.exit(f"figures: {' '.join(args)} exited with {result.returncode}: {result.stderr.strip()[-2000:]}")
    return result.stdout


def sweep(work, out, args):
    run([CDVP, "sweep", "--jobs", JOBS, "-q", "--out", out] + args, work)
    return os.path.join(work, out)


def csv_columns(path, columns):
    """The CSV's rows with only `columns` (those it has), as CSV text."""
    with open(path, encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    kept = [c for c in columns if rows and c in rows[0]]
    text = io.StringIO()
    writer = csv.writer(text, lineterminator="\n")
    writer.writerow(kept)
    for row in rows:
        writer.writerow([row[c] for c in kept])
    return text.getvalue()


def csv_without(path, measured):
    """The CSV without its measured columns, as CSV text."""
    with open(path, encoding="utf-8", newline="") as f:
        header = next(csv.reader(f))
    return csv_columns(path, [c for c in header if c not in measured])


# Each figure: its PNGs (file in the command's output -> path in docs/), its
# data file in docs/, how it compares, and the command. make(work) returns
# (the PNGs' directory, the data text to check, the data file to install).
class Figure:
    def __init__(self, name, fast, pngs, data, make, compare):
        self.name, self.fast, self.pngs, self.data, self.make, self.compare = name, fast, pngs, data, make, compare


def layers(work):
    dot = run([sys.executable, os.path.join(ROOT, "scripts", "check-layers.py"), "--dot", "--root", ROOT], work)
    with open(os.path.join(work, "layers.dot"), "w", encoding="utf-8") as f:
        f.write(dot)
    run(["dot", "-Tpng", "-Gdpi=90", "-o", "layers.png", "layers.dot"], work)
    return work, os.path.join(work, "layers.dot")


def readme_sweep(work):
    # The README's "Exploring architectures in one command".
    out = sweep(work, "results", ["--board", "adm-xrc-ii,pcie-gen3-x8", "--set", "m=1,2,4,8,16,24",
                                  "--set", "objects=50:2000:x2", "--frames", "30", "--baseline", "sap,soa"])
    return out, os.path.join(out, "sweep.csv")


def fidelity(work):
    # The README's "Two engines, and speed against error".
    run([CDVP, "fidelity", "--board", "adm-xrc-ii", "--scene", "mixed", "--objects", "700", "--frames", "30",
         "--m", "8", "--fifo-depth", "15", "--pair-buffer", "128", "--wait", "poll",
         "-c", "bus.load_bytes_per_s=20e6", "--out", "fidelity"], work)
    out = os.path.join(work, "fidelity")
    return out, os.path.join(out, "fidelity.csv")


def formats(work):
    # scripts/answers.sh, its first sweep.
    out = sweep(work, "formats", ["--board", "adm-xrc-ii,pcie-gen3-x8", "--set",
                                  "format=float32,fixed32,fixed24,fixed18,fixed16,fixed12,fixed9,fixed8",
                                  "--set", "objects=256:65536:x2", "--m", "8", "--frames", "6", "--warmup", "1"])
    return out, os.path.join(out, "fit.csv")


def speedup(work):
    # scripts/answers.sh, its second sweep.
    out = sweep(work, "speedup", ["--board", "adm-xrc-ii,pcie-gen3-x8", "--set", "format=float32,fixed16",
                                  "--set", "m=4,8,11,16,24,32", "--set", "objects=100,300,1000,3000,10000,30000,65536",
                                  "--frames", "12", "--warmup", "2", "--baseline", "sap"])
    return out, os.path.join(out, "sweep.csv")


def grid(work):
    # scripts/grid-answers.sh, its first sweep, as docs/answers.md ran it (SOFTWARE_OBJECTS up to
    # 30,000, FRAMES=3, WARMUP=1).
    out = sweep(work, "software", ["--board", "adm-xrc-ii,pcie-gen3-x8", "--set", "board.algorithm=all_pairs,grid",
                                   "--set", "m=4,8,11,32", "--fidelity", "analytic", "--frames", "3", "--warmup", "1",
                                   "--set", "objects=100,300,1000,3000,10000,30000", "--baseline", "sap,dbvt"])
    return out, os.path.join(out, "sweep.csv")


def answer(work):
    # docs/exploring.md, "A question answered in one command".
    out = sweep(work, "u250", ["--board", "alveo-u250", "--set", "algorithm=all_pairs,grid", "--set", "m=2,8,32",
                               "--set", "format=float32,fixed16", "--set", "objects=100,500,2000,20000",
                               "--frames", "10", "--baseline", "sap,dbvt"])
    return out, os.path.join(out, "sweep.csv")


def exact(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def columns(names):
    return lambda path: csv_columns(path, names)


FIDELITY_MEASURED = {"mean_sim_wall_native_ns"}

FIGURES = [
    Figure("layers", True, {"layers.png": "docs/layers.png"}, "docs/layers.dot", layers, exact),
    Figure("sweep-speedup", True, {"speedup-adm-xrc-ii-sap.png": "docs/sweep-speedup.png"},
           "docs/sweep-speedup.csv", readme_sweep, columns(BOARD_TIME_COLUMNS)),
    Figure("fidelity", True, {"fidelity.png": "docs/fidelity.png"}, "docs/fidelity.csv", fidelity,
           lambda path: csv_without(path, FIDELITY_MEASURED)),
    Figure("formats", False, {f"{kind}-{board}.png": f"docs/answers/{kind}-{board}.png"
                              for kind in ("largest-m", "lanes-extra") for board in ("adm-xrc-ii", "pcie-gen3-x8")},
           "docs/answers/formats-fit.csv", formats, exact),
    Figure("speedup", False, {f"time-{board}.png": f"docs/answers/time-{board}.png"
                              for board in ("adm-xrc-ii", "pcie-gen3-x8")},
           "docs/answers/time.csv", speedup, columns(BOARD_TIME_COLUMNS)),
    Figure("grid", False, {f"time-{board}.png": f"docs/answers/grid-time-{board}.png"
                           for board in ("adm-xrc-ii", "pcie-gen3-x8")},
           "docs/answers/grid-time.csv", grid, columns(BOARD_TIME_COLUMNS)),
    Figure("answer", False, {"answer-time.png": "docs/answer-time.png", "answer-energy.png": "docs/answer-energy.png"},
           "docs/answer-u250.csv", answer, columns(BOARD_TIME_COLUMNS)),
]


def first_difference(old, new):
    old_lines, new_lines = old.splitlines(), new.splitlines()
    for k in range(max(len(old_lines), len(new_lines))):
        a = old_lines[k] if k < len(old_lines) else "(nothing)"
        b = new_lines[k] if k < len(new_lines) else "(nothing)"
        if a != b:
            return f"line {k + 1}: checked in {a[:200]!r}, now {b[:200]!r}"
    return "none"


def check(figure, work):
    data = os.path.join(ROOT, figure.data)
    if not os.path.exists(data):
        raise Stale(f"{figure.data} is missing: run scripts/figures.py update {figure.name}")
    _, made = figure.make(work)
    old, new = figure.compare(data), figure.compare(made)
    if old != new:
        raise Stale(f"{', '.join(figure.pngs.values())} stale: {figure.data} differs from what its command gives "
                    f"now ({first_difference(old, new)}); redraw with scripts/figures.py update {figure.name}")
    print(f"figures: {figure.name}: fresh ({figure.data}, {len(new.splitlines())} lines)")


def update(figure, work):
    directory, made = figure.make(work)
    for name, target in figure.pngs.items():
        shutil.copyfile(os.path.join(directory, name), os.path.join(ROOT, target))
    with open(os.path.join(ROOT, figure.data), "w", encoding="utf-8") as f:
        f.write(figure.compare(made))
    print(f"figures: {figure.name}: {', '.join(figure.pngs.values())} and {figure.data} redrawn")


def chosen(names):
    by_name = {f.name: f for f in FIGURES}
    if not names:
        return [f for f in FIGURES if f.fast]
    if names == ["all"]:
        return FIGURES
    unknown = [n for n in names if n not in by_name]
    if unknown:
        sys.exit(f"figures: no figure named {', '.join(unknown)}; expected one of {', '.join(by_name)} or all")
    return [by_name[n] for n in names]


def main(argv):
    if len(argv) < 2 or argv[1] not in ("check", "update", "list"):
        sys.exit(__doc__)
    if argv[1] == "list":
        for f in FIGURES:
            print(f"{f.name:14} {'fast' if f.fast else 'slow'}  {f.data}: {', '.join(f.pngs.values())}")
        return
    stale = []
    for figure in chosen(argv[2:]):
        with tempfile.TemporaryDirectory() as work:
            try:
                (check if argv[1] == "check" else update)(figure, work)
            except Stale as e:
                stale.append(str(e))
    for message in stale:
        print(f"figures: {message}", file=sys.stderr)
    sys.exit(1 if stale else 0)


if __name__ == "__main__":
    main(sys.argv)
