"""cdvp.sweep: the table it returns, resuming, progress and its errors."""

import pytest

import cdvp

AXES = {"m": [1, 4], "objects": [20, 40]}
POINT_OPTIONS = {"board": "adm-xrc-ii", "scene": "spheres", "frames": 2, "plots": False}


def test_sweep_returns_a_row_a_point_and_resumes(tmp_path):
    calls = []
    table = cdvp.sweep(AXES, tmp_path / "out", jobs=2, progress=lambda done, total: calls.append((done, total)),
                       **POINT_OPTIONS)
    assert len(table) == 4 and set(table["status"]) == {"ok"}
    assert sorted(zip(table["m"], table["objects"])) == [(1, 20), (1, 40), (4, 20), (4, 40)]
    assert (table["mean_total_ns"] > 0).all()
    assert table.attrs["outcome"]["run_now"] == 4
    assert calls[0] == (0, 4) and calls[-1] == (4, 4) and len(calls) == 5

    calls.clear()
    again = cdvp.sweep(AXES, tmp_path / "out", jobs=2, progress=lambda done, total: calls.append((done, total)),
                       **POINT_OPTIONS)
    assert again.attrs["outcome"]["run_now"] == 0
    assert calls == [(4, 4)]
    assert again.drop(columns=["point_wall_s"]).equals(table.drop(columns=["point_wall_s"]))


def test_a_point_that_does_not_fit_is_a_refused_row(tmp_path):
    fits_not = {**POINT_OPTIONS, "objects": 600, "memory": "block_ram"}
    table = cdvp.sweep({"m": [4, 32]}, tmp_path / "some", **fits_not)
    assert list(table["status"]) == ["ok", "refused"] and "too few for --m 32" in table["reason"][1]
    with pytest.raises(cdvp.InputError, match="every point was refused"):
        cdvp.sweep({"m": [32]}, tmp_path / "none", **fits_not)


def test_ignore_timing_runs_every_point_and_a_row_beyond_its_estimate_says_so(tmp_path):
    table = cdvp.sweep({"clock_mhz": [66.0, 500.0]}, tmp_path / "fast", ignore_timing=True,
                       **{**POINT_OPTIONS, "objects": 40})
    assert list(table["status"]) == ["ok", "ok"]
    met, beyond = table.sort_values("clock_mhz")["timing_warning"].fillna("")
    assert met == "" and "500.0 MHz is beyond the " in beyond


def test_a_bad_axis_value_is_an_input_error_naming_the_axis(tmp_path):
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.sweep({"m": [0, 4]}, tmp_path, **POINT_OPTIONS)
    assert refused.value.status == 2
    assert str(refused.value) == "cdvp.sweep: axes['m']: expected 1 to 32, got 0"
    with pytest.raises(cdvp.InputError, match=r"axes\['m'\]: expected an integer from 1 to 32, got '0'"):
        cdvp.sweep({"m": "0,4"}, tmp_path, **POINT_OPTIONS)
    with pytest.raises(cdvp.InputError, match="is the same value as"):
        cdvp.sweep({"bus.interrupt_ns": [5000, 5000.0]}, tmp_path, **POINT_OPTIONS)
    with pytest.raises(cdvp.InputError, match=r"axes\['mm'\]: no setting or input has this name; the nearest is 'm'"):
        cdvp.sweep({"mm": [1]}, tmp_path, **POINT_OPTIONS)
    assert not any(tmp_path.iterdir())


def test_a_sweep_from_a_progress_callback_is_refused(tmp_path):
    refusals = []

    def nested(done, total):
        if done == 0:
            try:
                cdvp.sweep({"m": [1]}, tmp_path / "inner", objects=20, **POINT_OPTIONS)
            except cdvp.InputError as refused:
                refusals.append(refused)

    table = cdvp.sweep({"m": [1, 2]}, tmp_path / "outer", progress=nested, objects=20, **POINT_OPTIONS)
    assert len(table) == 2
    assert len(refusals) == 1 and "another sweep is running in this process" in str(refusals[0])
    assert refusals[0].status == 2


def test_a_sweep_takes_typed_values_and_list_text(tmp_path):
    table = cdvp.sweep({"objects": "20:40:x2", "bus.interrupt_ns": [5000, 6000.5]}, tmp_path, m=4,
                       **POINT_OPTIONS)
    assert sorted(zip(table["objects"], table["bus.interrupt_ns"])) == [(20, 5000), (20, 6000.5), (40, 5000),
                                                                         (40, 6000.5)]
    with pytest.raises(TypeError, match="jobs=: expected an int"):
        cdvp.sweep({"m": [1]}, tmp_path / "x", jobs="2", **POINT_OPTIONS)
    with pytest.raises(cdvp.InputError, match="m=: board.m is an axis of the sweep"):
        cdvp.sweep({"m": [1]}, tmp_path / "y", m=2, **POINT_OPTIONS)


def test_an_exception_in_progress_is_raised_after_the_sweep(tmp_path):
    def fail(done, total):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        cdvp.sweep({"m": [1, 2]}, tmp_path, progress=fail, objects=20, **POINT_OPTIONS)
    assert len(cdvp.sweep({"m": [1, 2]}, tmp_path, objects=20, **POINT_OPTIONS)) == 2


def test_wrong_types_are_refused_before_any_point_runs(tmp_path):
    with pytest.raises(TypeError, match="^axes: expected a dict of name -> values, got str$"):
        cdvp.sweep("m", tmp_path / "a")
    with pytest.raises(TypeError, match=r"^progress=: expected a callable, progress\(done, total\), got int$"):
        cdvp.sweep({"m": [1]}, tmp_path / "b", board="adm-xrc-ii", scene="spheres", progress=5)
    assert not (tmp_path / "b").exists()
    with pytest.raises(cdvp.InputError, match="NUL") as refused:
        cdvp.run(board="adm-xrc-ii", scene="spheres\0")
    assert refused.value.status == 2


def test_an_out_that_is_no_sweeps_or_another_shard_is_named_by_its_keyword(tmp_path):
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "notes.txt").write_text("x")
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.sweep({"m": [1]}, tmp_path / "other", **POINT_OPTIONS)
    message = str(refused.value)
    assert message.startswith("cdvp.sweep: out=: ") and message.endswith("give a new or empty out="), message
    assert "--" not in message, message
    cdvp.sweep({"m": [1, 4]}, tmp_path / "out", shard="1/2", **POINT_OPTIONS)
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.sweep({"m": [1, 4]}, tmp_path / "out", shard="2/2", **POINT_OPTIONS)
    message = str(refused.value)
    assert "holds shard 1/2 of this sweep, not 2/2; give the same shard=, or a new out=" in message, message
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.sweep({"m": [1, 4]}, tmp_path / "out", shard="1/2", record="compact", **POINT_OPTIONS)
    message = str(refused.value)
    assert "(record= full, not compact)" in message and "--" not in message, message
