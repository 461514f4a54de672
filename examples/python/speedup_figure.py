#!/usr/bin/env python3
"""The paper's speedup figure from Python: the board's speedup over Bullet's
sweep and prune (`sap`) against the number of objects N, one line per
parallelism m, on the paper's board (the adm-xrc-ii preset), from one
cdvp.sweep. The same grid as the README's sweep; its gnuplot figure is
docs/sweep-speedup.png.

    PYTHONPATH=build/sw/python /usr/bin/python3 examples/python/speedup_figure.py \
        --out results/speedup --png speedup.png

Rerunning into the same --out resumes the sweep (only missing points run).
"""

import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)
from matplotlib import ticker  # noqa: E402

import cdvp  # noqa: E402

BOARD = "adm-xrc-ii"
AXES = {"m": [1, 2, 4, 8, 16, 24], "objects": "50:1600:x2"}
# One marker a series, colour-blind-safe colours (Wong), as the sweep's own figures.
STYLES = list(zip(["#0072B2", "#E69F00", "#009E73", "#D55E00", "#56B4E9", "#CC79A7"], "os^vDp"))


def progress(done, total):
    print(f"\r{done}/{total} points", end="" if done < total else "\n", file=sys.stderr, flush=True)


def title(table):
    """What the points rest on, from the sweep's own columns."""
    row = table[table["status"] == "ok"].iloc[0]
    frames, warmup = int(row["report_frames"]), int(row["config.settings.run.warmup.value"])
    return (f"Speedup of {BOARD} over sap (Bullet's sweep and prune) against N\n"
            f"board simulated on the {row['config.fidelity']} engine; means of the {frames - warmup} frames "
            f"after {warmup} warm-up of {frames} a point\n"
            f"sap: the median at each N of its mean on the modelled host, native x {row['sap_host_factor']:.2g} "
            f"({row['config.host_calibration.basis']} factor)")


def speedups(table):
    """Each point's speedup over sap's median time at its N: every point at one N times the same
    sap work on the same frames, so the median over them stands for sap there, steadier than
    one point's own time on a busy machine (as docs/answers.md reads its sweep)."""
    ok = table[table["status"] == "ok"].copy()
    sap_at_n = ok.groupby("objects")["sap_mean_host_ns"].transform("median")
    ok["speedup"] = sap_at_n / ok["mean_total_ns"]
    return ok


def draw(table, png):
    ok = speedups(table)
    figure, axes = plt.subplots(figsize=(8, 5), dpi=120)
    for (m, points), (colour, marker) in zip(ok.groupby("m"), STYLES):
        points = points.sort_values("objects")
        axes.plot(points["objects"], points["speedup"], marker=marker, color=colour, label=f"m = {m}")
    axes.axhline(1.0, color="black", linestyle=":", linewidth=1, label="break-even (1x)")
    axes.set_xscale("log", base=2)
    axes.set_yscale("log")
    axes.yaxis.set_major_locator(ticker.FixedLocator([0.1, 0.2, 0.5, 1, 2, 5, 10]))
    axes.yaxis.set_major_formatter(ticker.FuncFormatter(lambda y, _: f"{y:g}x"))
    axes.yaxis.set_minor_formatter(ticker.NullFormatter())
    axes.set_xticks(sorted(ok["objects"].unique()), [str(n) for n in sorted(ok["objects"].unique())])
    axes.set_xlabel("N (objects)")
    axes.set_ylabel("speedup: sap's frame time / board's mean")
    axes.set_title(title(table), fontsize=9, loc="left")
    axes.grid(True, which="major", alpha=0.3)
    axes.legend(ncol=4, fontsize=8, loc="lower center", bbox_to_anchor=(0.5, -0.27), frameon=False)
    figure.tight_layout()
    figure.savefig(png)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="the sweep's directory (resumed when it holds one)")
    parser.add_argument("--png", required=True, help="the figure to write")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--frames", type=int, default=30)
    args = parser.parse_args()
    try:
        table = cdvp.sweep(AXES, args.out, jobs=args.jobs, progress=progress, board=BOARD, scene="spheres",
                           frames=args.frames, baseline="sap", plots=False)
    except cdvp.Error as error:
        print(error, file=sys.stderr)
        return error.status
    draw(table, args.png)
    refused = table[table["status"] == "refused"]
    print(f"{len(table)} points ({table.attrs['outcome']['run_now']} run now), {len(refused)} refused "
          f"(they do not fit the device); figure: {args.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
