"""cdvp from Python: the settings, the presets, runs and sweeps of the virtual
platform (docs/python.md).

Every simulation is a `cdvp run` child process, as `cdvp sweep` runs its
points: SystemC elaborates a design once per process, so a session may run
any number of configurations, a refused or faulting run cannot take Python
down, and the results are the command's byte for byte.
"""

import json
import os
import signal

import pandas as pd

from . import _cdvp
from ._errors import DeviceFault, Error, InputError, InternalError, SystemFailure, error_class
from ._locate import find_binary, use_installed_boards
from ._options import flag_words, setting_words, value_text
from ._report import PHASES, Baseline, Report, Summary, frames_table

__all__ = ["settings", "presets", "run", "sweep", "find_binary", "Report", "Summary", "Baseline", "PHASES",
           "Error", "InputError", "DeviceFault", "SystemFailure", "InternalError"]

use_installed_boards()


def settings():
    """The settings table (`cdvp settings --json`) as a DataFrame, one row a setting: name, type,
    unit, default, min, max, choices, flag (of cdvp run, or None), help, source."""
    columns = ["name", "type", "unit", "default", "min", "max", "choices", "flag", "help", "source"]
    return pd.DataFrame(json.loads(_cdvp.settings_json()), columns=columns)


def presets():
    """The board presets, {name: {"description", "path", "values": {setting: value}}}: what each
    preset sets over the defaults."""
    return {p["name"]: {key: p[key] for key in ("description", "path", "values")}
            for p in json.loads(_cdvp.presets_json())}


def run(board=None, scene=None, trace=None, settings=None, pairs=False, **options):
    """One `cdvp run` in a child process; returns its Report.

    board: a preset's name or a .json path; scene ("spheres", ...) or trace (a CSV path), one of them.
    settings: {"bus.interrupt_ns": 5000, ...}, each as -c NAME=VALUE.
    pairs: also read the pairs back (Report.pairs, Report.pairs_csv).
    options: any other flag of cdvp run, underscores for dashes: objects=500 -> --objects 500,
    quantum_ns=100 -> --quantum-ns 100, baseline=["sap", "soa"] -> --baseline sap,soa,
    ignore_capacity=True -> --ignore-capacity.
    Raises InputError (status 2), DeviceFault (3), SystemFailure (4) or InternalError (1), each
    with the command's one-line message."""
    words = flag_words({"board": board, "scene": scene, "trace": trace, **options}) + setting_words(settings)
    report_text, summary_text, pairs_csv = _cdvp.run(words, pairs, find_binary())
    report = json.loads(report_text)
    return Report(config=report["config"], summary=Summary.from_json(json.loads(summary_text)),
                  frames=frames_table(report["frames"]), raw=report, pairs_csv=pairs_csv if pairs else None)


def sweep(axes, out, jobs=1, progress=None, settings=None, plots=True, quiet=True, **options):
    """`cdvp sweep` into the directory out; returns out/sweep.csv as a DataFrame (one row a point).

    axes: {"m": [1, 2, 4], "objects": "50:800:x2", "bus.interrupt_ns": [...]}, each as --set
    NAME=LIST (a list, or the command's own list text); a board list is board=["adm-xrc-ii", ...].
    options: the sweep's own (board, scene, trace, fidelity, shard, rerun_invalid) and every other
    flag of cdvp run passed on to each point, as run() spells them; settings as run()'s.
    progress: called as progress(done, total) before the first point and after each.
    Resumable: the same call into the same out runs only the points not done yet (outcome in
    DataFrame.attrs["outcome"], its "run_now" the points this call ran). Raises as run() does."""
    if not isinstance(axes, dict):
        raise TypeError(f"cdvp.sweep: axes must be a dict of name -> values, not {type(axes).__name__}")
    if progress is not None and not callable(progress):
        raise TypeError(f"cdvp.sweep: progress must be callable as progress(done, total), not {type(progress).__name__}")
    words = []
    for name, values in axes.items():
        words += ["--set", f"{name}={value_text(values)}"]
    words += flag_words({**options, "out": os.fspath(out), "jobs": jobs, "no_plots": not plots, "quiet": quiet})
    words += setting_words(settings)
    outcome = _cdvp.sweep(words, find_binary(), progress)
    if outcome["stop_signal"] == signal.SIGINT:
        raise KeyboardInterrupt
    if outcome["stop_signal"]:
        raise InternalError(f"cdvp sweep: stopped by signal {outcome['stop_signal']}", 1)
    if outcome["status"] != 0:
        status = outcome["status"]
        raise error_class(status)(f"cdvp sweep: ended with status {status} after {outcome['points']} points "
                                 "(the reason is on standard error)", status)
    table = pd.read_csv(os.path.join(os.fspath(out), "sweep.csv"))
    table.attrs["outcome"] = outcome
    return table

