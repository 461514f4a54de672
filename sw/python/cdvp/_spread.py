"""cdvp.sweep over an executor: a concurrent.futures.Executor or a
dask.distributed Client (docs/python.md, docs/sweep.md: Dask).

The client makes OUT ready and checks what it holds as a resume does. The
points OUT lacks are cut into tasks: task K of N (N = ceil(points / block))
is the shard K/N of the grid, run by the study library on a worker into a
directory of its own, OUT/tasks/K-of-N, its software timings shared through
OUT/software. When every task has ended, the client merges their rows into
OUT in one transaction, as `cdvp merge` merges shards; the tasks' directories
go with the merge. A task that dies keeps the rows it wrote: run again (by
Dask on another worker when its worker dies, or by the same call after the
client died), it runs only the points it lacks.
"""

import concurrent.futures
import fcntl
import math
import operator
import os
import re
import threading

from . import _cdvp
from ._errors import Error, InputError, InternalError, raise_for_outcome
from ._locate import find_binary

TASKS = "tasks"

# The library runs one sweep at a time in a process (it waits for any child
# of the process): tasks that share a process, in threads of one worker,
# take turns.
_one_sweep_at_a_time = threading.Lock()


def _task_dir(out, task, tasks):
    return os.path.join(out, TASKS, f"{task}-of-{tasks}")


class _TaskLock:
    """An exclusive flock on OUT/tasks/K-of-N.lock, waited for: a task run
    again while an earlier run of it still works (its client died, its
    cluster lives on) waits for that run to end, then runs what is left."""

    def __init__(self, directory):
        self._path = directory + ".lock"
        self._fd = -1

    def __enter__(self):
        self._fd = os.open(self._path, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC, 0o644)
        fcntl.flock(self._fd, fcntl.LOCK_EX)
        return self

    def __exit__(self, *exc):
        os.close(self._fd)  # the lock goes with the descriptor


def run_task(axes, own, keywords, settings, out, task, tasks, held):
    """One task, on a worker: the shard task/tasks of the sweep into
    OUT/tasks/K-of-N, leaving out the points OUT holds (held). Returns the
    rows its directory holds and the points it ran now; raises as cdvp.sweep."""
    directory = _task_dir(out, task, tasks)
    task_own = {**own, "out": directory, "shard": f"{task}/{tasks}", "plots": False,
                "gathered_into": (os.fsencode(out), held)}
    with _one_sweep_at_a_time, _TaskLock(directory):
        outcome = _cdvp.sweep(axes, task_own, keywords, settings, find_binary(), None)
    raise_for_outcome(outcome, where=f"(task {task}-of-{tasks}: the reason is on its worker's standard error)")
    return outcome["points"], outcome["run_now"]


def _as_executor(executor):
    if isinstance(executor, concurrent.futures.Executor):
        return executor
    get_executor = getattr(executor, "get_executor", None)  # a dask.distributed Client
    if callable(get_executor):
        # pure=False: a task submitted again (a resume) runs again instead of taking a result Dask kept.
        return get_executor(pure=False)
    raise TypeError("cdvp.sweep: executor= must be a concurrent.futures.Executor or a dask.distributed.Client, "
                    f"not {type(executor).__name__}")


def _block_of(block):
    if isinstance(block, bool) or not hasattr(block, "__index__"):
        raise TypeError(f"block=: expected an int, got {type(block).__name__}")
    block = operator.index(block)
    if block < 1:
        raise InputError(f"cdvp.sweep: block=: expected a whole number of points from 1 up, got {block}", 2)
    return block


def _check_tasks_dir(tasks_dir, tasks):
    """Refuses unfinished tasks of another cut of the sweep (another block=)."""
    try:
        names = os.listdir(tasks_dir)
    except FileNotFoundError:
        return
    for name in sorted(names):
        cut = re.fullmatch(r"\d+-of-(\d+)(\.lock)?", name)
        if cut and int(cut.group(1)) != tasks:
            raise InputError(f"cdvp.sweep: out=: {tasks_dir} holds unfinished tasks of this sweep cut into "
                             f"{cut.group(1)} tasks, not {tasks}: give the block= they were given to resume "
                             "them, or remove that directory", 2)


class _Progress:
    """progress(done, total), as a sweep calls it: the first exception it
    raises is kept for when the sweep ends (its tasks are not left
    half-merged) and silences it."""

    def __init__(self, callback):
        self._callback = callback
        self._failure = None

    def __call__(self, done, total):
        if self._callback is None or self._failure is not None:
            return
        try:
            self._callback(done, total)
        except Exception as failure:
            self._failure = failure

    def rethrow_any(self):
        if self._failure is not None:
            raise self._failure


def _submitted(executor, *args):
    """run_task(*args) submitted to executor, whose submit must give a
    concurrent.futures.Future (Dask's executor's does)."""
    future = executor.submit(run_task, *args)
    if not isinstance(future, concurrent.futures.Future):
        raise TypeError(f"executor=: submit() returned {type(future).__name__}, not a concurrent.futures.Future")
    return future


def _task_failed(name, what):
    return InternalError(f"cdvp.sweep: {name} {what}; the points it recorded stay: call again to run the rest", 1)


def _task_ran(future, task, tasks, out, wanted):
    """The points task K-of-N ran now, once it is checked: the executor is
    not trusted, so its result must be run_task's (rows, run now) and the
    task's directory must hold a checked row for every point it was given
    (wanted). Raises an Error naming the task otherwise."""
    name = f"task {task}-of-{tasks}"
    try:
        result = future.result()
    except Error:
        raise
    except Exception as error:  # a worker lost for good, a pool broken
        raise _task_failed(name, f"failed: {type(error).__name__}: {error}") from error
    if not (isinstance(result, (tuple, list)) and len(result) == 2 and all(type(count) is int for count in result)):
        raise _task_failed(name, f"returned {type(result).__name__} where a task returns its (rows, run now)")
    rows, ran = result
    directory = _task_dir(out, task, tasks)
    held = set(_cdvp.task_rows(os.fsencode(directory)))
    if not wanted <= held or rows != len(held) or not 0 <= ran <= rows:
        raise _task_failed(name, f"returned ({rows}, {ran}) as its (rows, run now), but {directory} holds "
                                 f"{len(wanted & held)} of its {len(wanted)} points (its worker could not see out=, "
                                 "or the executor did not run it)")
    return ran


def spread_sweep(axes, own, keywords, settings, executor, block, progress):
    """Runs the sweep's points on executor in tasks of block points and
    merges them into own["out"]; returns the outcome as cdvp.sweep's. Every
    task is checked when it ends (_task_ran): the counts are of rows written."""
    if own.get("shard") is not None:
        raise InputError("cdvp.sweep: shard=: an executor= runs the whole sweep, cut into tasks of block= points; "
                         "give shard= or executor=, not both", 2)
    block = _block_of(block)
    executor = _as_executor(executor)
    out = os.path.abspath(os.fsdecode(os.fspath(own["out"])))  # the workers' working directory may be another
    own = {**own, "out": out}
    prepared = _cdvp.sweep_prepare(axes, own, keywords, settings)
    points, held = prepared["points"], set(prepared["held"])
    tasks = max(1, math.ceil(points / block))
    tasks_dir = os.path.join(out, TASKS)
    _check_tasks_dir(tasks_dir, tasks)
    shard_points = {task: range(task - 1, points, tasks) for task in range(1, tasks + 1)}
    wanted = {task: set(indices) - held for task, indices in shard_points.items()}  # what each task is to run
    todo = [task for task, missing in wanted.items() if missing]
    done, run_now = len(held), 0
    if todo:
        os.makedirs(tasks_dir, exist_ok=True)
    told = _Progress(progress)
    told(done, points)
    if todo:
        futures, failures = {}, {}
        try:
            for task in todo:
                futures[_submitted(executor, axes, own, keywords, settings, out, task, tasks,
                                   sorted(held.intersection(shard_points[task])))] = task
            for future in concurrent.futures.as_completed(futures):
                task = futures[future]
                try:
                    ran = _task_ran(future, task, tasks, out, wanted[task])
                except Error as error:
                    failures[task] = error
                    continue
                done, run_now = done + len(wanted[task]), run_now + ran
                told(done, points)
        except BaseException:
            for future in futures:
                future.cancel()
            raise
        if failures:
            raise failures[min(failures)]  # every other task has ended, its rows kept
        ran_dirs = [_task_dir(out, task, tasks) for task in shard_points
                    if os.path.exists(os.path.join(_task_dir(out, task, tasks), "sweep.json"))]
        status = _cdvp.merge(os.fsencode(out), [os.fsencode(d) for d in ran_dirs], own["plots"], own["quiet"])
        if status != 0:
            raise InternalError(f"cdvp.sweep: drawing the figures failed (status {status}); the tasks' rows stay "
                                f"in {tasks_dir}: call again to merge them", status)
    told.rethrow_any()
    return {"status": 0, "points": points, "run_now": run_now, "tasks": len(todo), "began_now": prepared["began_now"]}
