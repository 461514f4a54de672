"""Where a run runs: the analytic level in this process, the others in a `cdvp run` child; the same results."""

import json

import cdvp
from cdvp import _cdvp
from conftest import SMALL
from test_run import simulated

ANALYTIC = {**SMALL, "fidelity": "analytic", "objects": 200, "frames": 3, "m": 4}


def without_origins(value):
    """A report's settings without where each came from (the module names keywords, the command flags)."""
    if isinstance(value, dict):
        return {k: without_origins(v) for k, v in value.items() if k != "origin"}
    if isinstance(value, list):
        return [without_origins(v) for v in value]
    return value


def test_an_analytic_run_needs_no_child_and_others_do():
    # /bin/false as the binary: a run that started a child would fail.
    report_text, _, _ = _cdvp.run(dict(ANALYTIC), None, False, "/bin/false")
    assert json.loads(report_text)["config"]["fidelity"] == "analytic"
    try:
        _cdvp.run({**ANALYTIC, "fidelity": "fast"}, None, False, "/bin/false")
    except cdvp.InternalError as failed:
        assert failed.status == 1
    else:
        raise AssertionError("a fast run ran without its child")


def test_in_process_and_child_give_the_same_results(cli, tmp_path):
    ours = cdvp.run(**ANALYTIC, pairs=True)
    report, pairs = tmp_path / "report.json", tmp_path / "pairs.csv"
    words = ["--board", "adm-xrc-ii", "--scene", "spheres", "--objects", "200", "--frames", "3", "--m", "4",
             "--fidelity", "analytic"]
    done = cli("run", *words, "--report", str(report), "--pairs-out", str(pairs), "-q")
    assert done.returncode == 0, done.stderr
    theirs = json.loads(report.read_text())
    assert without_origins(simulated(ours.raw)) == without_origins(simulated(theirs))
    assert ours.pairs_csv == pairs.read_bytes()
    assert ours.raw["config"]["settings"]["board.m"]["origin"] == "keyword m"
    assert theirs["config"]["settings"]["board.m"]["origin"] == "flag --m"
