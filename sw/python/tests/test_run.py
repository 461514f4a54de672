"""cdvp.run: many configurations in one session, the CLI's results byte for byte, its errors."""

import json

import pytest

import cdvp
from conftest import SMALL, cli_words

# Report fields measured on this machine (wall-clock, load) or naming the report's own path.
MEASURED = ("native", "load_average", "command_line", "provenance")


def simulated(value):
    """A report without its measured fields."""
    if isinstance(value, dict):
        return {k: simulated(v) for k, v in value.items() if not any(word in k for word in MEASURED)}
    if isinstance(value, list):
        return [simulated(v) for v in value]
    return value


def test_many_configurations_run_in_one_session():
    narrow = cdvp.run(**SMALL, m=1)
    wide = cdvp.run(**SMALL, m=16)
    pcie = cdvp.run(**{**SMALL, "board": "pcie-gen3-x8"}, m=16)
    slow_irq = cdvp.run(**SMALL, m=16, settings={"bus.interrupt_ns": 50000})
    assert narrow.config["m"] == 1 and wide.config["m"] == 16
    assert narrow.summary.mean_phase_ns["compute"] > wide.summary.mean_phase_ns["compute"]
    assert pcie.summary.total_ns["mean"] < wide.summary.total_ns["mean"]
    assert slow_irq.summary.mean_phase_ns["irq"] > wide.summary.mean_phase_ns["irq"]
    assert narrow.summary.pairs == wide.summary.pairs == pcie.summary.pairs
    assert list(wide.frames["frame"]) == [0, 1]
    assert wide.summary.frames == 2


def test_report_and_pairs_equal_the_commands(cli, tmp_path):
    options = {**SMALL, "m": 4, "quantum_ns": 1000}
    ours = cdvp.run(**options, settings={"bus.interrupt_ns": 5000}, pairs=True)
    report, pairs = tmp_path / "report.json", tmp_path / "pairs.csv"
    done = cli("run", *cli_words(options), "-c", "bus.interrupt_ns=5000", "--report", str(report),
               "--pairs-out", str(pairs), "-q")
    assert done.returncode == 0, done.stderr
    assert simulated(ours.raw) == simulated(json.loads(report.read_text()))
    assert ours.pairs_csv == pairs.read_bytes()
    assert list(ours.pairs.columns) == ["frame", "a", "b"] and len(ours.pairs) == ours.summary.pairs


def test_a_scene_family_runs_with_its_settings_and_refuses_another_familys():
    pile = cdvp.run(scene="pile", objects=200, frames=2, settings={"scene.pile.clusters": 2})
    assert pile.config["source"] == "pile objects=200 seed=1 clusters=2"
    assert pile.summary.frames == 2 and pile.summary.pairs > 0
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.run(scene="heavy", objects=200, frames=2, settings={"scene.pile.clusters": 2})
    assert str(refused.value) == "cdvp.run: settings['scene.pile.clusters']: goes with scene= pile, not scene= heavy"


def test_a_bad_value_is_an_input_error_naming_the_keyword():
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.run(board="adm-xrc-ii", scene="spheres", m=33)
    assert refused.value.status == 2
    assert str(refused.value) == "cdvp.run: m=: expected 1 to 32, got 33"


def test_an_unknown_keyword_is_a_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'bogus_flag'"):
        cdvp.run(board="adm-xrc-ii", scene="spheres", bogus_flag=1)


def test_an_unknown_setting_is_refused_by_name():
    with pytest.raises(cdvp.InputError, match="no.such"):
        cdvp.run(**SMALL, settings={"no.such": 1})


def test_an_injected_fault_is_a_device_fault_and_the_session_goes_on(cli):
    with pytest.raises(cdvp.DeviceFault) as faulted:
        cdvp.run(**SMALL, inject="board-error@frame=1")
    assert faulted.value.status == 3 and isinstance(faulted.value, cdvp.Error)
    done = cli("run", *cli_words(SMALL), "--inject", "board-error@frame=1", "-q")
    assert done.returncode == 3
    assert str(faulted.value).replace("cdvp.run: ", "cdvp run: ", 1) == done.stderr.splitlines()[0]
    assert "injected board-error" in str(faulted.value)
    assert cdvp.run(**SMALL).summary.frames == 2


def test_the_report_path_is_the_modules_own():
    with pytest.raises(cdvp.InputError, match="report=: the module's own"):
        cdvp.run(**SMALL, report="x.json")


def test_the_grid_board_is_a_keyword_as_it_is_a_flag():
    grid = cdvp.run(**SMALL, algorithm="grid")
    setting = grid.raw["config"]["settings"]["board.algorithm"]
    assert setting == {"value": "grid", "origin": "flag --algorithm"}
    same = cdvp.run(**SMALL, settings={"board.algorithm": "grid"})
    assert grid.summary.pairs == same.summary.pairs
    assert grid.raw["frames"][0]["compute_cycles"] == same.raw["frames"][0]["compute_cycles"]
    assert cdvp.run(**SMALL).raw["config"]["settings"]["board.algorithm"]["value"] == "all_pairs"


ENERGY = ("mean_energy_j", "mean_energy_static_j", "mean_energy_dynamic_j", "mean_energy_bus_j",
          "mean_energy_host_j", "mean_energy_per_pair_j", "host_package_w")
BASELINE_ENERGY = ("energy_j", "energy_per_pair_j", "energy_ratio")


def test_the_summarys_energy_is_the_reports_and_none_where_no_power_is_stated():
    board = cdvp.run(**SMALL, baseline="sap")
    raw = board.raw["summary"]
    assert {key: getattr(board.summary, key) for key in ENERGY} == {key: raw[key] for key in ENERGY}
    assert board.summary.mean_energy_j > 0 and board.summary.host_package_w > 0
    sap, raw_sap = board.summary.baselines["sap"], raw["baselines"]["sap"]
    assert {key: getattr(sap, key) for key in BASELINE_ENERGY} == {key: raw_sap[key] for key in BASELINE_ENERGY}
    assert sap.energy_j > 0
    assert sap.native_energy_j == raw_sap.get("native_energy_j"), "measured by RAPL, or None"
    # No --board: the report's energy is all 0, no power being stated; the summary has none.
    bare = cdvp.run(**{**SMALL, "board": None}, baseline="sap")
    assert bare.raw["summary"]["mean_energy_j"] == 0 and bare.raw["summary"]["host_package_w"] == 0
    assert [getattr(bare.summary, key) for key in ENERGY] == [None] * len(ENERGY)
    assert [getattr(bare.summary.baselines["sap"], key) for key in BASELINE_ENERGY] == [None] * len(BASELINE_ENERGY)
