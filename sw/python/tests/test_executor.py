"""cdvp.sweep(executor=): the points in tasks on a concurrent.futures executor,
gathered into the same directory the command writes."""

import concurrent.futures
import csv
import os

import pytest

import cdvp

GRID = {"m": [1, 4], "objects": [20, 40, 80]}
POINTS = {"board": "adm-xrc-ii", "scene": "spheres", "frames": 3, "baseline": "sap", "plots": False}
# The same grid on the command line, its axes in the same order (the first outermost).
COMMAND = ["sweep", "--set", "m=1,4", "--set", "objects=20,40,80", "--board", "adm-xrc-ii", "--scene", "spheres",
           "--frames", "3", "--baseline", "sap", "--no-plots", "-q"]


def measured(column):
    """sw/study/sweep_table.cpp's is_measured_column: what varies from run to run."""
    baseline_energy = column.endswith(("_energy_j", "_energy_ratio")) and not column.startswith(("mean_", "median_"))
    return (column in ("point_wall_s", "checksum", "load_average_end")
            or column.startswith(("config.provenance.", "config.budgets."))
            or column.endswith(("_native_ns", "_host_ns", "_speedup")) or baseline_energy or "_timing_" in column)


def rows(directory):
    with open(os.path.join(directory, "sweep.csv"), newline="") as table:
        reader = csv.DictReader(table)
        return reader.fieldnames, [{k: v for k, v in row.items() if not measured(k)} for row in reader]


def test_a_process_pool_sweep_is_the_commands_sweep(tmp_path, cli):
    calls = []
    with concurrent.futures.ProcessPoolExecutor(2) as pool:
        table = cdvp.sweep(GRID, tmp_path / "spread", executor=pool, block=2,
                           progress=lambda done, total: calls.append((done, total)), **POINTS)
    outcome = table.attrs["outcome"]
    assert (outcome["points"], outcome["ok"], outcome["run_now"], outcome["tasks"]) == (6, 6, 6, 3)
    assert calls[0] == (0, 6) and calls[-1] == (6, 6) and len(calls) == 4
    done = cli(*COMMAND, "--out", str(tmp_path / "local"))
    assert done.returncode == 0, done.stderr
    spread, local = tmp_path / "spread", tmp_path / "local"
    assert (spread / "sweep.json").read_bytes() == (local / "sweep.json").read_bytes()
    assert rows(spread) == rows(local)
    assert (spread / "fit.csv").read_bytes() == (local / "fit.csv").read_bytes()
    for listed in (".", "points", "software"):
        assert sorted(os.listdir(spread / listed)) == sorted(os.listdir(local / listed)), listed
    assert len(os.listdir(spread / "software")) == 3  # sap timed once a workload (objects), shared by the tasks

    # Done: the same call submits no task.
    calls.clear()
    with concurrent.futures.ProcessPoolExecutor(2) as pool:
        again = cdvp.sweep(GRID, spread, executor=pool, block=2,
                           progress=lambda done, total: calls.append((done, total)), **POINTS)
    assert (again.attrs["outcome"]["run_now"], again.attrs["outcome"]["tasks"]) == (0, 0)
    assert calls == [(6, 6)]


def test_the_tasks_leave_out_the_points_out_holds(tmp_path):
    out = tmp_path / "out"
    whole = cdvp.sweep(GRID, out, **POINTS)
    lines = (out / "sweep.csv").read_text().splitlines(keepends=True)
    (out / "sweep.csv").write_text("".join(lines[:-2]))  # the last two points lost
    with concurrent.futures.ThreadPoolExecutor(2) as threads:
        table = cdvp.sweep(GRID, out, executor=threads, **POINTS)
    outcome = table.attrs["outcome"]
    assert (outcome["points"], outcome["run_now"]) == (6, 2)
    # One task a point, two of them: the two points whose rows were lost.
    assert outcome["tasks"] == 2
    kept = [column for column in whole.columns if not measured(column)]
    assert table[kept].equals(whole[kept])
    assert not (out / "tasks").exists()


def test_refused_points_are_rows_and_a_sweep_all_refused_leaves_nothing(tmp_path):
    fits_not = {**POINTS, "objects": 600, "memory": "block_ram", "baseline": None}
    with concurrent.futures.ThreadPoolExecutor(2) as threads:
        table = cdvp.sweep({"m": [4, 32]}, tmp_path / "some", executor=threads, **fits_not)
        assert list(table["status"]) == ["ok", "refused"] and "too few for --m 32" in table["reason"][1]
        with pytest.raises(cdvp.InputError, match="every point was refused; the first, m-16_") as refused:
            cdvp.sweep({"m": [16, 32]}, tmp_path / "none", executor=threads, **fits_not)
    assert refused.value.status == 2
    assert not (tmp_path / "none").exists()


def test_a_failed_task_raises_once_the_others_have_ended_and_a_rerun_runs_what_is_left(tmp_path):
    out = tmp_path / "out"

    def stray_in_task_2(done, total):  # before the tasks start: task 2-of-3's directory holds a file of no sweep's
        if done == 0:
            os.makedirs(out / "tasks" / "2-of-3")
            (out / "tasks" / "2-of-3" / "stray").write_text("not a sweep's\n")

    with concurrent.futures.ThreadPoolExecutor(2) as threads:
        # That task is refused; the others finish first, their rows kept.
        with pytest.raises(cdvp.InputError, match=r"holds stray but no sweep.json"):
            cdvp.sweep(GRID, out, executor=threads, block=2, progress=stray_in_task_2, **POINTS)
        assert (out / "sweep.csv").read_text().count("\n") == 1  # nothing merged: the header alone
        assert len((out / "tasks" / "1-of-3" / "sweep.csv").read_text().splitlines()) == 3
        os.remove(out / "tasks" / "2-of-3" / "stray")
        with pytest.raises(cdvp.InputError, match="holds unfinished tasks of this sweep cut into 3 tasks, not 2: give the "
                                                  "block= they were given"):
            cdvp.sweep(GRID, out, executor=threads, block=3, **POINTS)
        table = cdvp.sweep(GRID, out, executor=threads, block=2, **POINTS)
    assert len(table) == 6 and set(table["status"]) == {"ok"}
    assert table.attrs["outcome"]["run_now"] == 2  # task 2-of-3's two points; the other tasks had run theirs
    assert not (out / "tasks").exists()


def test_what_an_executor_sweep_refuses(tmp_path):
    with pytest.raises(TypeError, match="executor= must be a concurrent.futures.Executor"):
        cdvp.sweep(GRID, tmp_path / "a", executor=4, **POINTS)
    with concurrent.futures.ThreadPoolExecutor(1) as threads:
        with pytest.raises(TypeError, match="block=: expected an int, got float"):
            cdvp.sweep(GRID, tmp_path / "a", executor=threads, block=2.0, **POINTS)
        with pytest.raises(cdvp.InputError, match="block=: expected a whole number of points from 1 up, got 0"):
            cdvp.sweep(GRID, tmp_path / "a", executor=threads, block=0, **POINTS)
        with pytest.raises(cdvp.InputError, match="give shard= or executor=, not both"):
            cdvp.sweep(GRID, tmp_path / "a", executor=threads, shard="1/2", **POINTS)
        assert not (tmp_path / "a").exists()
    with pytest.raises(cdvp.InputError, match="block=: cuts the sweep into tasks for an executor="):
        cdvp.sweep(GRID, tmp_path / "c", block=2, **POINTS)


def test_an_exception_in_progress_is_raised_after_the_tasks_are_merged(tmp_path):
    def fail(done, total):
        raise RuntimeError("stop here")

    with concurrent.futures.ThreadPoolExecutor(2) as threads:
        with pytest.raises(RuntimeError, match="stop here"):
            cdvp.sweep(GRID, tmp_path, executor=threads, block=3, progress=fail, **POINTS)
        again = cdvp.sweep(GRID, tmp_path, executor=threads, block=3, **POINTS)
    assert len(again) == 6 and again.attrs["outcome"]["run_now"] == 0


# Executors are not trusted: fakes of concurrent.futures' shape whose futures
# lie, checked against what the tasks left in out.
FOUR = {"m": [1, 4], "objects": [20, 40]}
LIGHT = {"board": "adm-xrc-ii", "scene": "spheres", "frames": 2, "plots": False}


class Claiming(concurrent.futures.Executor):
    """Runs no task: each future is already done with `result`."""

    def __init__(self, result):
        self.result = result

    def submit(self, fn, *args, **kwargs):
        future = concurrent.futures.Future()
        future.set_result(self.result)
        return future


class EveryOtherTask(concurrent.futures.Executor):
    """Runs the 1st, 3rd, ... task; the others claim a row run without running
    (a worker that cannot see out)."""

    def __init__(self):
        self.submitted = 0

    def submit(self, fn, *args, **kwargs):
        self.submitted += 1
        future = concurrent.futures.Future()
        future.set_result(fn(*args, **kwargs) if self.submitted % 2 else (1, 1))
        return future


@pytest.mark.parametrize("result, message", [
    (None, "task 1-of-4 returned NoneType where a task returns its (rows, run now)"),
    ("ab", "task 1-of-4 returned str where a task returns its (rows, run now)"),
    ((True, True), "task 1-of-4 returned tuple where a task returns its (rows, run now)"),
    (object(), "task 1-of-4 returned object where a task returns its (rows, run now)"),
    ((1, 1), "task 1-of-4 returned (1, 1) as its (rows, run now), but {out}/tasks/1-of-4 holds 0 of its 1 points"),
    ((10**30, -5), "task 1-of-4 returned (1000000000000000000000000000000, -5) as its (rows, run now), but "),
])
def test_a_task_that_claims_success_without_its_rows_is_an_error_naming_it(tmp_path, result, message):
    out = tmp_path / "out"
    with pytest.raises(cdvp.InternalError) as failed:
        cdvp.sweep(FOUR, out, executor=Claiming(result), **LIGHT)
    assert message.format(out=out) in str(failed.value), str(failed.value)
    assert str(failed.value).endswith("the points it recorded stay: call again to run the rest")
    assert failed.value.status == 1 and "\n" not in str(failed.value)
    assert (out / "sweep.csv").read_text().count("\n") == 1  # nothing merged: the header alone


def test_tasks_that_never_wrote_their_rows_fail_the_sweep_and_a_rerun_completes_it(tmp_path):
    out = tmp_path / "out"
    with pytest.raises(cdvp.InternalError, match=r"task 2-of-4 returned \(1, 1\) as its \(rows, run now\), but "
                                                 r".*/tasks/2-of-4 holds 0 of its 1 points \(its worker could not see"):
        cdvp.sweep(FOUR, out, executor=EveryOtherTask(), **LIGHT)
    with concurrent.futures.ThreadPoolExecutor(2) as threads:
        table = cdvp.sweep(FOUR, out, executor=threads, **LIGHT)
    outcome = table.attrs["outcome"]
    # The rows the two tasks that ran kept stay; the other two run now.
    assert (len(table), outcome["points"], outcome["ok"], outcome["run_now"], outcome["tasks"]) == (4, 4, 4, 2, 4)


def test_an_executor_whose_submit_gives_no_future_is_refused(tmp_path):
    class NoFutures(concurrent.futures.Executor):
        def submit(self, fn, *args, **kwargs):
            return (1, 1)

    with pytest.raises(TypeError, match=r"^executor=: submit\(\) returned tuple, not a concurrent.futures.Future$"):
        cdvp.sweep(FOUR, tmp_path / "out", executor=NoFutures(), **LIGHT)
