"""A good citizen of the interpreter: cdvp's signal handlers only around its own work, Ctrl-C as
KeyboardInterrupt with nothing left behind, no state outliving a call. Each case runs a small script
in its own Python process (and session, so that a Ctrl-C can go to its process group as a terminal
sends it)."""

import os
import signal
import subprocess
import sys
import textwrap
import time

PRELUDE = textwrap.dedent("""
    import os, signal, sys, threading, time
    import cdvp
    SMALL = dict(board="adm-xrc-ii", scene="spheres", objects=40, frames=2)
    # A run long enough to be interrupted on any machine: 20,000 frames take
    # about 20 s at the fast level on an idle one (400 took 0.4 s).
    LONG = dict(board="adm-xrc-ii", scene="spheres", objects=4000, frames=20000)
    def caught_signals():
        return [line for line in open("/proc/self/status") if line.startswith("SigCgt")][0]
    """)


def script(tmp_path, body, **kwargs):
    """Starts PRELUDE + body in a new session with TMPDIR a fresh directory; returns (process, tmpdir)."""
    tmpdir = tmp_path / "tmp"
    tmpdir.mkdir()
    env = {**os.environ, "TMPDIR": str(tmpdir)}
    process = subprocess.Popen([sys.executable, "-c", PRELUDE + textwrap.dedent(body)], env=env, text=True,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True, **kwargs)
    return process, tmpdir


def wait_for_line(process, expected):
    line = process.stdout.readline().strip()
    assert line == expected, (line, process.stderr.read() if process.poll() is not None else "")


def test_handlers_are_put_back_after_each_call(tmp_path):
    body = """
        seen = []
        signal.signal(signal.SIGUSR1, lambda number, frame: seen.append(number))
        before = caught_signals()
        cdvp.run(**SMALL)
        cdvp.run(**SMALL, fidelity="analytic")
        cdvp.sweep({"m": [1, 2]}, OUT, plots=False, **SMALL)
        assert caught_signals() == before, (caught_signals(), before)
        os.kill(os.getpid(), signal.SIGUSR1)   # the user's handler, not cdvp's
        time.sleep(0.05)
        assert seen == [signal.SIGUSR1], seen
        try:
            os.kill(os.getpid(), signal.SIGINT)  # Python's Ctrl-C, not cdvp's
            time.sleep(1)
        except KeyboardInterrupt:
            print("ok")
        """
    process, _ = script(tmp_path, f"OUT = {str(tmp_path / 'out')!r}\n" + textwrap.dedent(body))
    out, err = process.communicate(timeout=120)
    assert process.returncode == 0, err
    assert out.strip() == "ok"


def interrupt_after_ready(process, delay=0.5):
    wait_for_line(process, "ready")
    time.sleep(delay)
    os.killpg(process.pid, signal.SIGINT)  # as a terminal's Ctrl-C: the whole process group
    return process.communicate(timeout=120)


def test_ctrl_c_during_a_run_is_a_keyboard_interrupt_leaving_nothing(tmp_path):
    process, tmpdir = script(tmp_path, """
        print("ready", flush=True)
        try:
            cdvp.run(**LONG)
            print("not interrupted")
        except KeyboardInterrupt:
            print("interrupted")
        print(cdvp.run(**SMALL).summary.frames)  # the session goes on
        """)
    out, err = interrupt_after_ready(process)
    assert process.returncode == 0, err
    assert out.split() == ["interrupted", "2"]
    assert list(tmpdir.iterdir()) == []


def test_ctrl_c_stops_an_analytic_run_in_process_between_frames(tmp_path):
    # Some minutes of frames: only a run stopped between them ends within the timeout.
    process, tmpdir = script(tmp_path, """
        print("ready", flush=True)
        try:
            cdvp.run(board="adm-xrc-ii", scene="spheres", objects=2000, frames=200000, fidelity="analytic")
            print("not interrupted")
        except KeyboardInterrupt:
            print("interrupted")
        """)
    out, err = interrupt_after_ready(process, delay=0.5)
    assert process.returncode == 0, err
    assert out.split() == ["interrupted"]
    assert list(tmpdir.iterdir()) == []


def test_a_sweep_stopped_by_ctrl_c_leaves_no_stop_flag(tmp_path):
    out_dir = tmp_path / "sweep"
    process, tmpdir = script(tmp_path, f"""
        OUT = {str(out_dir)!r}
        AXES = {{"m": [1, 2, 3, 4, 5, 6]}}
        POINTS = dict(board="adm-xrc-ii", scene="spheres", objects=3000, frames=4000, plots=False)
        print("ready", flush=True)
        try:
            cdvp.sweep(AXES, OUT, **POINTS)
            print("not interrupted")
        except KeyboardInterrupt:
            print("interrupted")
        table = cdvp.sweep(AXES, OUT, **POINTS)
        print(len(table), set(table["status"]) == {{"ok"}}, table.attrs["outcome"]["run_now"] > 0)
        """)
    out, err = interrupt_after_ready(process, delay=1.0)
    assert process.returncode == 0, err
    assert out.split() == ["interrupted", "6", "True", "True"]
    assert list(tmpdir.iterdir()) == []


def test_a_child_killed_by_sigkill_leaves_no_part_files(tmp_path):
    process, tmpdir = script(tmp_path, """
        def kill_the_child():
            for _ in range(200):
                time.sleep(0.05)
                children = open(f"/proc/{os.getpid()}/task/{os.getpid()}/children").read().split()
                if children:
                    time.sleep(0.3)
                    os.kill(int(children[0]), signal.SIGKILL)
                    return
        threading.Thread(target=kill_the_child).start()
        try:
            cdvp.run(**LONG, pairs=True)
        except cdvp.InternalError as failed:
            print("killed" if "killed by signal 9" in str(failed) else str(failed))
        """)
    out, err = process.communicate(timeout=120)
    assert process.returncode == 0, err
    assert out.split() == ["killed"]
    assert list(tmpdir.iterdir()) == []
