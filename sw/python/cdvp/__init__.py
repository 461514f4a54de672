"""cdvp from Python: the settings, the presets, runs and sweeps of the virtual
platform (docs/python.md).

Keyword arguments are typed values (the run layer's RunSpec), never
command-line words. A run at the analytic level runs in this process; any
other level in a `cdvp run` child, as `cdvp sweep` runs its points: SystemC
elaborates a design once per process, so a session may run any number of
configurations and a refused or faulting run cannot take Python down.
"""

import functools
import json
import os
import shutil
import subprocess

import pandas as pd

from . import _cdvp
from ._errors import DeviceFault, Error, InputError, InternalError, SystemFailure, error_class, raise_for_outcome
from ._locate import find_binary, use_installed_boards
from ._report import PHASES, Baseline, Report, Summary, frames_table
from ._spread import _block_of, spread_sweep

__all__ = ["settings", "presets", "run", "sweep", "answer", "find_binary", "Report", "Summary", "Baseline", "PHASES",
           "Error", "InputError", "DeviceFault", "SystemFailure", "InternalError"]

use_installed_boards()


@functools.lru_cache(maxsize=1)
def _settings_json():
    done = subprocess.run([find_binary(), "settings", "--json"], capture_output=True, check=False)
    if done.returncode != 0:
        raise error_class(done.returncode)(done.stderr.decode(errors="replace").strip(), done.returncode)
    return json.loads(done.stdout)


def settings():
    """The settings table (`cdvp settings --json`) as a DataFrame, one row a setting: name, type,
    unit, default, min, max, choices, flag (of cdvp run, or None), keyword (of cdvp.run, or None),
    help, source."""
    columns = ["name", "type", "unit", "default", "min", "max", "choices", "flag", "keyword", "help", "source"]
    rows = [{**row, "keyword": row["flag"][2:].replace("-", "_") if row["flag"] else None}
            for row in _settings_json()]
    return pd.DataFrame(rows, columns=columns)


def presets():
    """The board presets, {name: {"description", "path", "values": {setting: value}}}: what each
    preset sets over the defaults."""
    return {p["name"]: {key: p[key] for key in ("description", "path", "values")}
            for p in json.loads(_cdvp.presets_json())}


def run(board=None, scene=None, trace=None, settings=None, pairs=False, **options):
    """One run of the virtual platform; returns its Report.

    board: a preset's name or a .json path; scene ("spheres", "pile", "heavy", "planar", "brownian",
    or one of Bullet's; a family's own settings go in settings=, e.g. {"scene.pile.clusters": 2}) or
    trace (a CSV path), one of them. Paths may be str, bytes or os.PathLike.
    settings: {"bus.interrupt_ns": 5000, ...}: any setting by its dotted name, typed.
    pairs: also read the pairs back (Report.pairs, Report.pairs_csv).
    options: every setting with a keyword (its flag of cdvp run, '_' for '-'), typed: objects=500,
    quantum_ns=100.0, transfer="pio", ignore_capacity=True; and baseline (a str or list of str),
    inject (a fault, or a list of them), config, software_timings. None leaves one out.
    At the analytic level the run is in this process, at any other in a `cdvp run` child.
    Raises TypeError for a value of the wrong type or an unknown keyword, InputError (status 2)
    for a value cdvp refuses, naming the keyword; DeviceFault (3), SystemFailure (4) or
    InternalError (1) with the run's one-line message."""
    if not isinstance(pairs, bool):
        raise TypeError(f"pairs=: expected True or False, got {type(pairs).__name__}")
    keywords = {"board": board, "scene": scene, "trace": trace, **options}
    report_text, summary_text, pairs_csv = _cdvp.run(keywords, settings, pairs, find_binary())
    report = json.loads(report_text)
    return Report(config=report["config"], summary=Summary.from_json(json.loads(summary_text)),
                  frames=frames_table(report["frames"], report["config"].get("baselines", [])), raw=report,
                  pairs_csv=pairs_csv if pairs else None)


_SWEEP_OWN = ("shard", "record", "software_timings", "rerun_invalid")


def sweep(axes, out, jobs=1, progress=None, settings=None, plots=True, quiet=True, executor=None, block=1, **options):
    """A sweep into the directory out; returns out/sweep.csv as a DataFrame (one row a point).

    axes: {"m": [1, 2, 4], "objects": "50:800:x2", "bus.interrupt_ns": [...]}: a setting by its
    keyword or dotted name, or board, trace, scene, config; a list of typed values, or the command
    line's list text. board, scene, trace and fidelity given as keywords are axes too (a value or
    a list).
    options: the sweep's own (shard="1/4", record="compact", software_timings, rerun_invalid) and
    every keyword of run() for each point; settings as run()'s.
    progress: called as progress(done, total) before the first point and after each (with an
    executor, after each task).
    executor: a concurrent.futures.Executor or a dask.distributed.Client: the points run there in
    tasks of block points (each task jobs points at once), merged into out when all have ended.
    Resumable: the same call into the same out runs only the points not done yet (outcome in
    DataFrame.attrs["outcome"], its "run_now" the points this call ran; attrs["out"] the directory,
    which answer() reads). Raises as run() does; KeyboardInterrupt when Ctrl-C stops it."""
    if not isinstance(axes, dict):
        raise TypeError(f"axes: expected a dict of name -> values, got {type(axes).__name__}")
    if not isinstance(out, (str, bytes, os.PathLike)):
        raise TypeError(f"out=: expected a str, bytes or os.PathLike, got {type(out).__name__}")
    if progress is not None and not callable(progress):
        raise TypeError(f"progress=: expected a callable, progress(done, total), got {type(progress).__name__}")
    own = {"out": out, "jobs": jobs, "plots": plots, "quiet": quiet,
           **{key: options.pop(key) for key in _SWEEP_OWN if key in options}}
    if _block_of(block) != 1 and executor is None:
        raise InputError("cdvp.sweep: block=: cuts the sweep into tasks for an executor=; give one", 2)
    if executor is None:
        outcome = _cdvp.sweep(axes, own, options, settings, find_binary(), progress)
        raise_for_outcome(outcome)
    else:
        outcome = spread_sweep(axes, own, options, settings, executor, block, progress)
    table = pd.read_csv(os.path.join(os.fsdecode(os.fspath(out)), "sweep.csv"))
    if executor is not None:
        outcome = _gathered_outcome(outcome, table, out)
    table.attrs["outcome"] = outcome
    table.attrs["out"] = os.fsdecode(os.fspath(out))
    return table


def answer(sweep):
    """The sweep's answer as a DataFrame: its answer.csv, as the sweep wrote it (docs/sweep.md,
    "The answer"), one row a scene and N: the fastest board configuration there (configuration,
    board, algorithm, m, format, point), its board_frame_ns and board_energy_j, the fastest software
    on its host and the speedup and energy_ratio against it (with the ratio's band), what bounds
    the frame, the clock, and the scene's crossovers on time and on energy.

    sweep: the sweep's directory (str, bytes or os.PathLike), or the DataFrame sweep() returned.
    Raises TypeError for anything else, InputError (status 2) when the directory holds no answer."""
    if isinstance(sweep, pd.DataFrame):
        if "out" not in sweep.attrs:
            raise InputError("cdvp.answer: this DataFrame is not one cdvp.sweep() returned (no attrs['out']); "
                             "give the sweep's directory", 2)
        out = sweep.attrs["out"]
    elif isinstance(sweep, (str, bytes, os.PathLike)):
        out = os.fsdecode(os.fspath(sweep))
    else:
        raise TypeError(f"sweep: expected a sweep's directory or the DataFrame cdvp.sweep() returned, "
                        f"got {type(sweep).__name__}")
    path = os.path.join(out, "answer.csv")
    if not os.path.isfile(path):
        raise InputError(f"cdvp.answer: {path}: no such file: not a sweep's directory, a sweep that has not ended, "
                         "or one whose points timed no frame", 2)
    return pd.read_csv(path, dtype={"scene": str, "configuration": str, "board": str, "algorithm": str,
                                    "format": str, "point": str, "software": str}, keep_default_na=False,
                       na_values={column: [""] for column in _ANSWER_NUMBERS})


# answer.csv's numeric columns: an empty field is NaN (a text field stays "").
_ANSWER_NUMBERS = ("objects", "m", "board_frame_ns", "board_energy_j", "software_frame_ns", "software_energy_j",
                   "speedup", "energy_ratio", "energy_ratio_low", "energy_ratio_high", "bus_share", "memory_share",
                   "compute_share", "host_share", "clock_mhz", "fmax_mhz", "time_crossover_n",
                   "energy_crossover_n", "energy_crossover_early_n", "energy_crossover_late_n")


def _gathered_outcome(spread, table, out):
    """A spread sweep's outcome counted from its merged table, refused as a
    whole when every point was refused (as one sweep is: nothing is left of
    an out it began); a table short of the grid is an InternalError."""
    if len(table) != spread["points"]:
        raise InternalError(f"cdvp.sweep: {os.fsdecode(os.fspath(out))}/sweep.csv holds {len(table)} rows of the "
                            f"grid's {spread['points']} after the tasks were merged; call again to run the rest", 1)
    statuses = table["status"].value_counts()
    if len(table) > 0 and statuses.get("refused", 0) == len(table):
        if spread["began_now"]:
            shutil.rmtree(os.fspath(out))
        raise InputError(f"cdvp.sweep: every point was refused; the first, {table['point'][0]}: {table['reason'][0]}", 2)
    failed = int(statuses.get("failed", 0))
    return {"status": 1 if failed else 0, "points": len(table), "ok": int(statuses.get("ok", 0)),
            "refused": int(statuses.get("refused", 0)), "faulted": int(statuses.get("fault", 0)),
            "failed": failed, "run_now": spread["run_now"], "stop_signal": 0, "tasks": spread["tasks"]}
