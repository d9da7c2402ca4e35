"""Independent drawings made side by side, in processes forked from this one.

A command that draws several pictures of one solved cam (``cams plot``, ``cams report``) spends most of its time in
matplotlib, one picture after another, on one core. The pictures share nothing but the cam, so each can be drawn
in a child process forked from the one that solved it: the child inherits the solved cam (nothing is solved
again, nothing is pickled on the way in) and sends back only the bytes of the files it drew.

Forking is used where it is the operating system's own way of starting a process (Linux); elsewhere, or with one
core, or with one drawing, everything runs here, one after another, with the same results.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Sequence
from typing import TypeVar

__all__ = ["forked_map", "workers"]

T = TypeVar("T")

#: The tasks of the :func:`forked_map` running now: a child forked from this process finds them here (a closure
#: cannot be sent to a process; it is inherited instead).
_TASKS: Sequence[Callable[[], object]] = ()


def workers(jobs: int | None, tasks: int) -> int:
    """How many processes draw ``tasks`` drawings: ``jobs`` (None: every core this process may use), at most one a
    task, and 1 where processes are not forked (not Linux)."""
    if jobs is None:
        jobs = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    if not sys.platform.startswith("linux"):
        return 1
    return max(1, min(jobs, tasks))


class _Failed:
    """What a child sends back for a task that raised (the exception itself may not pickle back)."""


def _run(k: int) -> object:
    """Task ``k`` of :data:`_TASKS`, in a child; :class:`_Failed` if it raised."""
    try:
        return _TASKS[k]()
    except Exception:
        return _Failed()


def forked_map(tasks: Sequence[Callable[[], T]], *, jobs: int | None = None,
               done: Callable[[int], None] | None = None, effort: Sequence[float] | None = None) -> list[T]:
    """``[task() for task in tasks]``, the tasks run by up to ``jobs`` forked processes (:func:`workers`).

    ``effort`` (one number a task, any unit) orders the tasks handed out, the longest first: the processes then
    end nearly together (with 4 pictures on 2 processes, the two longest first, each then joined by a short one).

    Each task may use anything this process holds (the children are forked from it); what it returns must pickle
    (the bytes of a file: a few hundred kB). ``done(k)`` is called here, in this process, as task ``k`` ends
    (in the order they end); the results come back in the tasks' order. A task that raised in a child is run again
    here, after the others are cancelled, so that its exception is raised here as the task raises it.
    """
    n = workers(jobs, len(tasks))
    if n <= 1:
        out = []
        for k, task in enumerate(tasks):
            out.append(task())
            if done is not None:
                done(k)
        return out

    import multiprocessing
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

    global _TASKS
    _TASKS = tasks
    for stream in (sys.stdout, sys.stderr):  # a child would write what waits in a buffer a second time
        stream.flush()
    failed = None
    try:
        with ProcessPoolExecutor(max_workers=n, mp_context=multiprocessing.get_context("fork")) as pool:
            first = sorted(range(len(tasks)), key=lambda k: -effort[k]) if effort is not None else range(len(tasks))
            index = {pool.submit(_run, k): k for k in first}
            futures = sorted(index, key=index.__getitem__)
            pending = set(futures)
            while pending and failed is None:
                finished, pending = wait(pending, return_when=FIRST_COMPLETED)
                for f in finished:
                    if isinstance(f.result(), _Failed):
                        failed = index[f]
                    elif done is not None:
                        done(index[f])
            for f in pending:
                f.cancel()
            results = [f.result() for f in futures] if failed is None else []
    finally:
        _TASKS = ()
    if failed is None:
        return results  # type: ignore[return-value]
    tasks[failed]()  # raises here what it raised in the child
    raise RuntimeError(f"drawing {failed} failed in a child process but not when drawn again here")
