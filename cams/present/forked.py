"""Independent drawings made side by side, in processes forked from this one.

A command that draws several pictures of one solved cam (``cams plot``, ``cams report``) spends most of its time in
matplotlib, one picture after another, on one core. The pictures share nothing but the cam, so each can be drawn
in a child process forked from the one that solved it: the child inherits the solved cam (nothing is solved
again, nothing is pickled on the way in) and sends back only the bytes of the files it drew.

Forking is used where it is the operating system's own way of starting a process (Linux); elsewhere, or with one
core, or with one drawing, everything runs here, one after another, with the same results.

The children ignore Ctrl-C: the parent takes it and ends them at once (one line from the command, no traceback
from each child), and they end with the parent however it ends (``PR_SET_PDEATHSIG``). A child that dies (killed)
costs time, not pictures: what it had not sent back is drawn here. A child has only the thread that forked it, so
no other thread may hold a lock at the fork that the child would then wait on for ever: the progress bar's thread
is kept from drawing while this process forks (:mod:`cams.commands.progress`).
"""

from __future__ import annotations

import os
import signal
import sys
from collections.abc import Callable, Sequence
from typing import TypeVar

from cams.io.processes import cores, end_pool, ignore_sigint, sigint_held

__all__ = ["forked_map", "workers"]

T = TypeVar("T")

#: The tasks of the :func:`forked_map` running now: a child forked from this process finds them here (a closure
#: cannot be sent to a process; it is inherited instead).
_TASKS: Sequence[Callable[[], object]] = ()


def workers(jobs: int | None, tasks: int) -> int:
    """How many processes draw ``tasks`` drawings: ``jobs`` (None: every core this process may use), at most one per
    task (a huge ``jobs`` starts no more), and 1 where processes are not forked (not Linux)."""
    if jobs is None:
        jobs = cores()
    if not sys.platform.startswith("linux"):
        return 1
    return max(1, min(jobs, tasks))


class _Failed:
    """What a child sends back for a task that raised (the exception itself may not pickle back)."""


def _run(k: int) -> object:
    """Task ``k`` of :data:`_TASKS`, in a child; :class:`_Failed` if it raised."""
    try:
        return _TASKS[k]()
    except BaseException:
        return _Failed()


#: The process the children of the :func:`forked_map` running now were forked from.
_PARENT = 0
#: Linux's ``prctl`` option: the signal a process gets when the thread that forked it ends.
_PR_SET_PDEATHSIG = 1


def _child() -> None:
    """What a child does first: Ctrl-C is left to the parent (which ends the children: no traceback from each),
    and the child ends with the parent however that ends (killed, it leaves no child waiting for work for ever)."""
    ignore_sigint()
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
    except (OSError, AttributeError):  # no prctl: the parent still ends its children when it ends normally
        pass
    if os.getppid() != _PARENT:  # the parent ended before the line above
        os._exit(1)


def forked_map(
    tasks: Sequence[Callable[[], T]],
    *,
    jobs: int | None = None,
    done: Callable[[int], None] | None = None,
    effort: Sequence[float] | None = None,
    note: Callable[[str], None] | None = None,
) -> list[T]:
    """``[task() for task in tasks]``, the tasks run by up to ``jobs`` forked processes (:func:`workers`).

    ``effort`` (one number a task, any unit) orders the tasks handed out, the longest first: the processes then
    end nearly together (with 4 pictures on 2 processes, the two longest first, each then joined by a short one).

    Each task may use anything this process holds (the children are forked from it); what it returns must pickle
    (the bytes of a file: a few hundred kB). ``done(k)`` is called here, in this process, as task ``k`` ends
    (in the order they end); the results come back in the tasks' order.

    When a task raises in a child, or a child ends abruptly (killed), the children are ended and the tasks not yet
    back are run here, one after another, the one that raised first: its exception is raised here as the task
    raises it (an exception need not pickle), and a child that was killed costs time, not pictures (``note`` is
    told so in one line). Ctrl-C (:class:`KeyboardInterrupt`, here: the children ignore it) ends the children
    at once.
    """
    n = workers(jobs, len(tasks))
    results: dict[int, T] = {}
    failed: list[int] = []  # the tasks that raised in a child, to be run here first
    if n > 1:
        _forked(tasks, n, done, effort, note, results, failed)
    for k in [*failed, *(k for k in range(len(tasks)) if k not in results and k not in failed)]:
        results[k] = tasks[k]()
        if done is not None:
            done(k)
    return [results[k] for k in range(len(tasks))]


def _forked(tasks, n, done, effort, note, results, failed) -> None:
    """The children's part of :func:`forked_map`: ``results`` filled with what came back, ``failed`` with the
    tasks that raised; what is in neither is left to be run here."""
    import gc
    import multiprocessing
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
    from concurrent.futures.process import BrokenProcessPool

    global _TASKS, _PARENT
    _TASKS, _PARENT = tasks, os.getpid()
    for stream in (sys.stdout, sys.stderr):  # a child would write what waits in a buffer a second time
        stream.flush()
    pool = ProcessPoolExecutor(max_workers=n, mp_context=multiprocessing.get_context("fork"), initializer=_child)
    whole = False
    # the objects made so far out of the collector's reach while the children live: a child's collections then
    # do not walk (and copy, page by page) everything it inherited, which it never frees
    gc.freeze()
    try:
        first = sorted(range(len(tasks)), key=lambda k: -effort[k]) if effort is not None else range(len(tasks))
        # Ctrl-C held back while the children are forked (all at the first submit): none gets it before it
        # ignores it; it reaches this process just after
        with sigint_held():
            index = {pool.submit(_run, k): k for k in first}
        pending = set(index)
        broken = False
        while pending and not failed and not broken:
            finished, pending = wait(pending, return_when=FIRST_COMPLETED)
            for f in sorted(finished, key=index.__getitem__):
                k = index[f]
                try:
                    value = f.result()
                except BrokenProcessPool:
                    broken = True
                    continue
                except Exception:  # what it returned did not pickle: run again here
                    failed.append(k)
                    continue
                if isinstance(value, _Failed):
                    failed.append(k)
                else:
                    results[k] = value
                    if done is not None:
                        done(k)
        whole = not pending and not failed and not broken
        if broken and note is not None:
            left = len(tasks) - len(results)
            note(
                f"a process drawing side by side ended abruptly; the {left} drawing{'s' if left > 1 else ''} "
                f"not yet back {'are' if left > 1 else 'is'} drawn in this process, one after another"
            )
    finally:
        _TASKS = ()
        if whole:
            pool.shutdown(wait=True)
        else:  # the children are ended now: a Ctrl-C or a failure does not wait for the drawings under way
            end_pool(pool)
        gc.unfreeze()  # a caller that goes on running collects them again
