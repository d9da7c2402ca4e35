"""Worker processes of this one: Ctrl-C left to the parent, a pool ended at once, the cores there are.

Shared by the sweep's process pool (:mod:`cams.sweep.engine`) and the pictures drawn side by side
(:mod:`cams.present.forked`): the parent takes Ctrl-C and ends its workers (one line from the command, no
traceback from each worker); SIGINT is held back while the workers are forked, so that none gets it before it
ignores it.
"""

from __future__ import annotations

import contextlib
import os
import signal
from collections.abc import Iterator
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the pool's module (and multiprocessing) is imported by whoever makes a pool
    from concurrent.futures import ProcessPoolExecutor

__all__ = ["cores", "ignore_sigint", "sigint_held", "end_pool"]


def cores() -> int:
    """The cores this process may run on (its affinity where the system tells it, else the machine's)."""
    if hasattr(os, "sched_getaffinity"):
        return len(os.sched_getaffinity(0))
    return os.cpu_count() or 1


def ignore_sigint() -> None:
    """In a worker, first: Ctrl-C is the parent's to handle (it ends the workers); SIGINT unblocked again (it was
    held back while the worker was forked, :func:`sigint_held`)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})


@contextlib.contextmanager
def sigint_held() -> Iterator[None]:
    """Hold SIGINT back (POSIX) inside the block: while a pool forks its workers; it reaches this process after."""
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def end_pool(pool: ProcessPoolExecutor) -> None:
    """End ``pool`` now: its workers killed (the work under way is not waited for), the pending work cancelled."""
    for p in list((getattr(pool, "_processes", None) or {}).values()):
        if p.is_alive():
            p.kill()
    pool.shutdown(wait=True, cancel_futures=True)
