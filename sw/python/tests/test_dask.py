"""cdvp.sweep(executor=client) on a dask.distributed LocalCluster on the
loopback: a worker killed midway, and a client that dies."""

import glob
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest

import cdvp

try:
    import distributed
except ImportError:
    if os.environ.get("CDVP_REQUIRE_DASK") == "1":
        raise  # CI installs python3-distributed (scripts/setup.sh): the tests may not skip there
    pytest.skip("distributed is not installed (apt-get install python3-distributed)", allow_module_level=True)

# Debian's distributed 2022.12 on its tornado: a warning of theirs, not of cdvp's.
pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")

# Eight points of a few tenths of a second each: a task is still running when one is killed.
GRID = {"m": [4, 8], "objects": [200, 400, 800, 1600]}
POINTS = {"board": "adm-xrc-ii", "scene": "spheres", "frames": 100, "baseline": "sap", "plots": False}
CLUSTER = {"n_workers": 2, "threads_per_worker": 1, "processes": True, "host": "127.0.0.1", "dashboard_address": None}


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(**CLUSTER) as cluster, distributed.Client(cluster) as connected:
        yield connected


def rows_in(table):
    """The whole rows of a task's sweep.csv (a row cut short by a kill is not one)."""
    try:
        with open(table, "rb") as text:
            return max(0, text.read().count(b"\n") - 1)
    except FileNotFoundError:
        return 0


def test_a_sweep_whose_worker_is_killed_midway_completes(tmp_path, client):
    out = tmp_path / "out"
    killed = {}

    def kill_a_task_after_its_first_row():
        # The worker running a task holds its directory's sweep.lock, which names its pid.
        deadline = time.monotonic() + 60
        while not killed and time.monotonic() < deadline:
            for task in sorted(glob.glob(str(out / "tasks" / "*-of-*") + "/")):
                rows = rows_in(os.path.join(task, "sweep.csv"))
                try:
                    with open(os.path.join(task, "sweep.lock")) as lock:
                        pid = int(lock.read())
                except (FileNotFoundError, ValueError):
                    continue
                if 1 <= rows < 4:
                    os.kill(pid, signal.SIGKILL)
                    killed.update(task=task, rows=rows)
                    return
            time.sleep(0.01)

    killer = threading.Thread(target=kill_a_task_after_its_first_row)
    killer.start()
    table = cdvp.sweep(GRID, out, executor=client, block=4, **POINTS)
    killer.join()
    assert killed, "no task was caught between its first and its last point"
    assert len(table) == 8 and set(table["status"]) == {"ok"}
    # Dask ran the killed task again on a worker: it ran only the points its directory lacked
    # (one more may have been written between the count and the kill).
    run_now = table.attrs["outcome"]["run_now"]
    assert 8 - killed["rows"] - 1 <= run_now <= 8 - killed["rows"], (run_now, killed)
    assert not (out / "tasks").exists()


CLIENT_THAT_DIES = textwrap.dedent("""
    import os, signal, sys
    import cdvp, distributed

    def die_after_the_first_task(done, total):
        if done > 0:  # the client, its cluster and every point it started, at once
            os.killpg(0, signal.SIGKILL)

    if __name__ == "__main__":
        with distributed.LocalCluster(**{cluster}) as cluster, distributed.Client(cluster) as client:
            cdvp.sweep({grid}, sys.argv[1], executor=client, block=2, progress=die_after_the_first_task, **{points})
""")


def test_a_rerun_after_the_client_died_runs_only_the_missing_points(tmp_path, client):
    out = tmp_path / "out"
    script = tmp_path / "client.py"
    script.write_text(CLIENT_THAT_DIES.format(cluster=CLUSTER, grid=GRID, points=POINTS))
    died = subprocess.run([sys.executable, str(script), str(out)], start_new_session=True, capture_output=True,
                          text=True, timeout=120, check=False)
    assert died.returncode == -signal.SIGKILL, died.stderr
    kept = sum(rows_in(table) for table in glob.glob(str(out / "tasks" / "*-of-4" / "sweep.csv")))
    assert 2 <= kept < 8  # the first task's two points, and whatever the others wrote before the kill

    table = cdvp.sweep(GRID, out, executor=client, block=2, **POINTS)
    assert len(table) == 8 and set(table["status"]) == {"ok"}
    assert table.attrs["outcome"]["run_now"] == 8 - kept
    assert not (out / "tasks").exists()
