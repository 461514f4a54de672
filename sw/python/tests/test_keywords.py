"""Keyword arguments as typed values: types, values that look like options, file names, empty tables."""

import concurrent.futures
import os
import pathlib
import shutil

import numpy as np
import pytest

import cdvp
from conftest import SMALL

REPO = pathlib.Path(__file__).resolve().parents[3]


def test_a_value_beginning_with_dashes_is_a_value():
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.run(**SMALL, baseline="--help")
    assert refused.value.status == 2
    assert "baseline=" in str(refused.value) and "--help" in str(refused.value)
    with pytest.raises(cdvp.InputError, match="scene="):
        cdvp.run(board="adm-xrc-ii", scene="--version")


@pytest.mark.parametrize("keywords, message", [
    ({"objects": "40"}, "objects=: expected an int, got str"),
    ({"objects": True}, "objects=: expected an int, got bool"),
    ({"objects": 40.0}, "objects=: expected an int, got float"),
    ({"quantum_ns": "100"}, "quantum_ns=: expected a number, got str"),
    ({"transfer": 1}, "transfer=: expected a str, got int"),
    ({"baseline": 3}, "baseline=: expected a str or a list of str, got int"),
    ({"settings": ["bus.interrupt_ns", 5000]}, "settings: expected a dict of setting name -> value, got list"),
    ({"settings": {"bus.interrupt_ns": "5000"}}, r"settings\['bus.interrupt_ns'\]: expected a number, got str"),
    ({"pairs": "no"}, "pairs=: expected True or False, got str"),
    ({"pairs": 1}, "pairs=: expected True or False, got int"),
    ({"pairs": None}, "pairs=: expected True or False, got NoneType"),
    # numpy's bool is no int, though it has __index__ and __float__
    ({"objects": np.bool_(True)}, "objects=: expected an int, got bool_"),
    ({"quantum_ns": np.bool_(False)}, "quantum_ns=: expected a number, got bool_"),
    # a yes/no setting is a bool, not its command line's word or a number
    ({"ignore_capacity": "yes"}, "ignore_capacity=: expected True or False, got str"),
    ({"ignore_capacity": 1}, "ignore_capacity=: expected True or False, got int"),
    ({"settings": {"run.lockstep": "no"}}, r"settings\['run.lockstep'\]: expected True or False, got str"),
    # a text is a str; a file's name also bytes or a path; a CPU's number also an int
    ({"format": 5}, "format=: expected a str, got int"),
    ({"format": b"float32"}, "format=: expected a str, got bytes"),
    ({"host_profile": 5}, "host_profile=: expected a str, bytes or os.PathLike, got int"),
    ({"pin_cpu": 1.0}, "pin_cpu=: expected a str or an int, got float"),
    ({"pin_cpu": True}, "pin_cpu=: expected a str or an int, got bool"),
])
def test_a_value_of_the_wrong_type_is_a_type_error_naming_the_keyword(keywords, message):
    options = {key: value for key, value in SMALL.items() if key not in keywords}
    with pytest.raises(TypeError, match=message):
        cdvp.run(**options, **keywords)


@pytest.mark.parametrize("keywords, message", [
    ({"m": -1}, "m=: expected 1 to 32, got -1"),
    ({"m": 2**70}, "m=: expected 1 to 32, got 1180591620717411303424"),
    ({"transfer": "dmaa"}, "transfer=: expected dma or pio"),
    ({"settings": {"bus.interrupt_ns": -5.0}}, r"settings\['bus.interrupt_ns'\]: expected"),
    ({"settings": {"no.such": 1}}, r"settings\['no.such'\]: no setting has this name"),
])
def test_a_refused_value_is_an_input_error_naming_the_keyword(keywords, message):
    with pytest.raises(cdvp.InputError, match=message) as refused:
        cdvp.run(**{**SMALL, **{k: v for k, v in keywords.items() if k != "settings"}},
                 settings=keywords.get("settings"))
    assert refused.value.status == 2


def test_typed_values_of_numpy_lists_and_switches_run():
    report = cdvp.run(**{**SMALL, "objects": np.int64(40)}, fidelity="analytic", quantum_ns=np.float64(0), baseline=["sap"],
                      ignore_capacity=True, settings={"bus.interrupt_ns": 5000})
    assert report.config["settings"]["run.ignore_capacity"]["value"] == "yes"
    assert report.config["settings"]["bus.interrupt_ns"]["value"] == 5000
    assert report.config["settings"]["scene.objects"]["origin"] == "keyword objects"
    assert list(report.summary.baselines) == ["sap"]


def test_a_clock_beyond_the_estimate_is_refused_unless_ignore_timing_which_the_summary_says():
    fast = {"board": "adm-xrc-ii", "scene": "spheres", "objects": 40, "frames": 2, "clock_mhz": 500.0}
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.run(**fast)
    assert "500.0 MHz is beyond the " in str(refused.value)
    assert "ignore_timing=True runs it anyway" in str(refused.value)
    report = cdvp.run(**fast, ignore_timing=True)
    # The run's own line (its child's words for the flags).
    assert "clock-mhz: 500.0 MHz is beyond the " in report.summary.timing_warning
    assert report.summary.timing_warning.endswith("; running it anyway (--ignore-timing)")
    assert cdvp.run(**{**fast, "clock_mhz": 66.0}).summary.timing_warning == ""


def test_best_names_the_fastest_of_its_candidates():
    report = cdvp.run(**{**SMALL, "objects": 200}, fidelity="analytic", baseline="best,sap", threads=1)
    assert set(report.summary.baselines) == {"prune", "hgrid", "sap"}
    fastest = min(report.summary.baselines.items(), key=lambda item: item[1].mean_host_ns)[0]
    assert report.summary.best_software == fastest


def test_file_names_may_be_str_bytes_paths_and_not_utf8(tmp_path):
    trace = os.fsencode(tmp_path) + b"/tr\xe9ce.csv"
    shutil.copy(REPO / "traces" / "small.csv", trace)
    listed = [name for name in os.listdir(tmp_path) if name.startswith("tr")][0]  # surrogate-escaped str
    runs = [cdvp.run(trace=name, pairs=True) for name in (trace, os.path.join(tmp_path, listed),
                                                          pathlib.Path(os.fsdecode(trace)))]
    assert runs[0].pairs_csv == runs[1].pairs_csv == runs[2].pairs_csv and runs[0].summary.pairs > 0


def test_a_latin1_preset_name_works(tmp_path):
    preset = os.fsencode(tmp_path) + b"/caf\xe9.json"
    shutil.copy(REPO / "platform" / "boards" / "adm-xrc-ii.json", preset)
    for fidelity in ("analytic", "fast"):
        ours = cdvp.run(board=preset, scene="spheres", objects=40, frames=2, fidelity=fidelity)
        paper = cdvp.run(board="adm-xrc-ii", scene="spheres", objects=40, frames=2, fidelity=fidelity)
        assert ours.summary.total_ns == paper.summary.total_ns
        assert ours.config["settings"]["bus.type"]["origin"].endswith("caf\ufffd.json")


def test_empty_tables_keep_their_columns_and_dtypes():
    some = cdvp.run(**SMALL, baseline="sap", pairs=True)
    none = cdvp.run(**{**SMALL, "frames": 0}, baseline="sap", pairs=True)
    assert len(none.frames) == 0 and len(none.pairs) == 0
    assert sorted(none.frames.columns) == sorted(some.frames.columns)
    assert none.frames.dtypes.sort_index().equals(some.frames.dtypes.sort_index())
    assert list(none.pairs.columns) == ["frame", "a", "b"]
    assert (none.pairs.dtypes == "int64").all() and (some.pairs.dtypes == "int64").all()


def test_a_run_for_a_child_is_checked_first_in_the_modules_words():
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.run(board="adm-xrc-ii", scene="spheres", objects=4000, m=32, memory="block_ram", fidelity="fast")
    assert "too few for m=32 at 4000 objects (objects=)" in str(refused.value)
    assert "ignore_capacity=True runs it anyway" in str(refused.value)
    with pytest.raises(cdvp.InputError, match=r"inject=: .* past the run's last frame 1 \(frames=2\)"):
        cdvp.run(**SMALL, inject="board-error@frame=5")


@pytest.mark.parametrize("keywords, message", [
    ({"block": "1"}, "block=: expected an int, got str"),
    ({"jobs": "2"}, "jobs=: expected an int, got str"),
    ({"jobs": np.bool_(True)}, "jobs=: expected an int, got bool_"),
    ({"plots": "no"}, "plots=: expected True or False, got str"),
    ({"quiet": 0}, "quiet=: expected True or False, got int"),
    ({"rerun_invalid": "yes"}, "rerun_invalid=: expected True or False, got str"),
    ({"shard": 1}, "shard=: expected a str, got int"),
    ({"record": b"compact"}, "record=: expected a str, got bytes"),
    ({"software_timings": 3}, "software_timings=: expected a str, bytes or os.PathLike, got int"),
    ({"out": 5}, "out=: expected a str, bytes or os.PathLike, got int"),
    ({"out": 5, "executor": concurrent.futures.ThreadPoolExecutor(1)},
     "out=: expected a str, bytes or os.PathLike, got int"),
])
def test_the_modules_own_keywords_are_typed_too(tmp_path, keywords, message):
    with pytest.raises(TypeError, match=f"^{message}$"):
        cdvp.sweep({"m": [1, 2]}, **{"out": tmp_path / "out", **SMALL, **keywords})
    assert not (tmp_path / "out").exists()


def test_a_count_of_jobs_too_large_for_any_integer_type_is_refused_as_a_value(tmp_path):
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.sweep({"m": [1, 2]}, tmp_path / "out", jobs=2**71, **SMALL)
    assert str(refused.value) == f"cdvp.sweep: jobs=: expected a whole number from 1 to 24, got {2**71}"


@pytest.mark.parametrize("name, shown", [("obj\x00ects", r"'obj\x00ects'"), ("obj\udcffects", r"'obj\udcffects'"),
                                         ("\x1b[31mm", r"'\x1b[31mm'"), ("it's", "\"it's\"")])
def test_a_name_is_shown_escaped_and_whole(tmp_path, name, shown):
    # A NUL, a control character or a lone surrogate (a name of bytes that are no UTF-8) never cuts the message short.
    with pytest.raises(TypeError) as refused:
        cdvp.run(**SMALL, **{name: 5})
    assert str(refused.value).startswith(f"cdvp.run() got an unexpected keyword argument {shown} ("), str(refused.value)
    assert str(refused.value).endswith("any setting goes in settings={NAME: VALUE})"), str(refused.value)
    with pytest.raises(TypeError) as refused:
        cdvp.sweep({"m": [1]}, tmp_path / "out", **SMALL, **{name: 5})
    assert f"cdvp.sweep() got an unexpected keyword argument {shown} (" in str(refused.value), str(refused.value)
    for refusal in (lambda: cdvp.run(**SMALL, settings={"scene." + name: 5}),
                    lambda: cdvp.sweep({"m": [1]}, tmp_path / "out", **SMALL, settings={"scene." + name: 5})):
        with pytest.raises(cdvp.InputError) as refused:
            refusal()
        message = str(refused.value)
        assert f": settings[{repr('scene.' + name)}]: no setting has this name" in message, message
        assert message.endswith("(cdvp.settings() lists them)"), message
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.sweep({name: [1]}, tmp_path / "out", **SMALL)
    assert f"cdvp.sweep: axes[{shown}]: no setting or input has this name" in str(refused.value), str(refused.value)
    assert not (tmp_path / "out").exists()


def test_a_value_of_no_utf8_is_shown_by_its_escapes():
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.run(**{**SMALL, "scene": "sph\udcffres"})
    assert str(refused.value).endswith(r"got 'sph\xffres'"), str(refused.value)


def test_a_name_far_from_every_one_gets_no_suggestion():
    with pytest.raises(TypeError) as refused:
        cdvp.run(**SMALL, speed_grade=5)
    assert "nearest" not in str(refused.value), str(refused.value)
    with pytest.raises(TypeError, match="the nearest is 'objects'"):
        cdvp.run(**SMALL, objcts=5)
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.run(**SMALL, settings={"device.speed_grade": 5})
    assert "nearest" not in str(refused.value), str(refused.value)


@pytest.mark.parametrize("cpu", ["1023", 1023, np.int64(1023)])
def test_a_cpu_the_run_cannot_pin_to_is_named_by_its_keyword(cpu):
    for fidelity in ("fast", "analytic"):
        with pytest.raises(cdvp.InputError) as refused:
            cdvp.run(**SMALL, fidelity=fidelity, quantum_ns=0.0, pin_cpu=cpu)
        message = str(refused.value)
        assert "pin_cpu=: CPU 1023 is not one this process may run on" in message, message
        assert "--pin-cpu" not in message, message
