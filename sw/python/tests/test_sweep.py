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


def test_a_bad_axis_is_the_commands_input_error(cli, tmp_path):
    with pytest.raises(cdvp.InputError) as refused:
        cdvp.sweep({"m": [0, 4]}, tmp_path, **POINT_OPTIONS)
    done = cli("sweep", "--set", "m=0,4", "--board", "adm-xrc-ii", "--scene", "spheres", "--frames", "2",
               "--out", str(tmp_path), "--no-plots", "-q")
    assert refused.value.status == 2 == done.returncode
    assert str(refused.value) == done.stderr.splitlines()[0]


def test_an_exception_in_progress_is_raised_after_the_sweep(tmp_path):
    def fail(done, total):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        cdvp.sweep({"m": [1, 2]}, tmp_path, progress=fail, objects=20, **POINT_OPTIONS)
    assert len(cdvp.sweep({"m": [1, 2]}, tmp_path, objects=20, **POINT_OPTIONS)) == 2


def test_wrong_types_are_refused_before_any_point_runs(tmp_path):
    with pytest.raises(TypeError, match="axes must be a dict"):
        cdvp.sweep("m", tmp_path / "a")
    with pytest.raises(TypeError, match="progress must be callable"):
        cdvp.sweep({"m": [1]}, tmp_path / "b", board="adm-xrc-ii", scene="spheres", progress=5)
    assert not (tmp_path / "b").exists()
    with pytest.raises(cdvp.InputError, match="NUL") as refused:
        cdvp.run(board="adm-xrc-ii", scene="spheres", objects="5\0")
    assert refused.value.status == 2
