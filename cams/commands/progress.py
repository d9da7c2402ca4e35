"""Progress of long work on standard error: one home for every command.

A command whose work may run past about two seconds (``cams plot``, ``cams report``, ``--animate``, the motion
design of ``cams solve`` with ``[optimize]``, ``cams sweep``) wraps it in :func:`progress`. The bar is drawn
only when standard error is a terminal and the command was not given ``--quiet``; in a pipe, a log file or a
test it draws nothing and the library is not even imported, so a plain ``cams solve`` stays light.

The library is tqdm: one pure-Python wheel with no dependencies of its own, maintained, about 40 ms to import
(rich, the other candidate, brings pygments and markdown-it and draws far more than a bar needs). tqdm's
``delay`` keeps a bar off the screen until the work has run :data:`DELAY_S` seconds, so quick commands stay
quiet; a background thread redraws the bar while one long step (a solve, a motion design) runs, so its elapsed
time keeps counting. That thread never draws while this process forks (:func:`os.register_at_fork`): a forked
child (:mod:`cams.present.forked`, a sweep's workers) inherits no lock of the bar's or of standard error taken by
a thread it does not have, which would hang the child the first time it wrote to standard error.
"""

from __future__ import annotations

import os
import sys
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

__all__ = ["DELAY_S", "Progress", "wanted", "progress"]

#: Seconds of work before a bar appears (tqdm's ``delay``): shorter work shows none.
DELAY_S = 2.0
#: Seconds between redraws of a bar while one step runs.
_HEARTBEAT_S = 0.5


def wanted(args: Any) -> bool:
    """Whether the command draws progress: standard error is a terminal and ``--quiet`` was not given."""
    if getattr(args, "quiet", False):
        return False
    try:
        return bool(sys.stderr.isatty())
    except (AttributeError, ValueError):  # a replaced or closed stream
        return False


class Progress:
    """The progress of one command's work: a stage's words, and steps done of a known total.

    Without a bar (:func:`wanted` false) every method does nothing, so the commands call them unconditionally.
    """

    def __init__(self, bar: Any = None) -> None:
        self._bar = bar

    def note(self, line: str) -> None:
        """Write ``line`` on standard error, above the bar when one is drawn (the bar is drawn again below it)."""
        if self._bar is not None:
            self._bar.write(line, file=sys.stderr)
        else:
            print(line, file=sys.stderr)

    @property
    def drawn(self) -> bool:
        """Whether a bar exists (standard error is a terminal, no ``--quiet``)."""
        return self._bar is not None

    def stage(self, words: str) -> None:
        """Say what is being done now (e.g. ``"designing the motion"``)."""
        if self._bar is not None:
            self._bar.set_description_str(words, refresh=False)

    def advance(self, steps: int = 1) -> None:
        """Count ``steps`` more steps done."""
        if self._bar is not None:
            self._bar.update(steps)

    def to(self, done: int, total: int | None = None) -> None:
        """Set the steps done to ``done`` (of ``total``, when it changes): a callback for work that counts."""
        bar = self._bar
        if bar is None:
            return
        if total is not None and total != bar.total:
            bar.total, bar.bar_format = total, None  # a count from now on: the bar, n/total and the rate
        bar.update(done - bar.n)
        if done == bar.total and time.time() - bar.start_t >= bar.delay:
            bar.refresh()  # the last step is shown even when it came quicker than tqdm redraws


#: The drawing locks of the bars drawn now (one a :func:`progress` block): each is taken while this process forks.
_DRAWING: list[threading.Lock] = []
_FORK_GUARDED = False


def _before_fork() -> None:
    for lock in _DRAWING:
        lock.acquire()


def _after_fork_in_parent() -> None:
    for lock in reversed(_DRAWING):
        lock.release()


def _after_fork_in_child() -> None:
    _DRAWING.clear()  # no bar is drawn in a child (its thread was not forked): a fork of its own waits on none


@contextmanager
def progress(enabled: bool, what: str, total: int | None = None, unit: str = "step") -> Iterator[Progress]:
    """A bar on standard error for the work inside the ``with`` block, when ``enabled`` (see :func:`wanted`).

    Parameters
    ----------
    enabled : bool
        Draw the bar (:func:`wanted`); otherwise nothing is drawn and tqdm is not imported.
    what : str
        The first stage's words.
    total : int, optional
        The steps of the work; None: no count, the stage's words and the elapsed time only.
    unit : str
        What one step is (``"picture"``, ``"design"``...).

    The bar is erased when the block ends, so the command's own output starts on a clean line.
    """
    if not enabled:
        yield Progress()
        return
    from tqdm import tqdm

    global _FORK_GUARDED
    if not _FORK_GUARDED and hasattr(os, "register_at_fork"):
        os.register_at_fork(
            before=_before_fork, after_in_parent=_after_fork_in_parent, after_in_child=_after_fork_in_child
        )
        _FORK_GUARDED = True
    tqdm.monitor_interval = 0  # no thread of tqdm's own that may draw at any time: the heartbeat below redraws
    fmt = None if total is not None else "{desc}: {elapsed}"
    try:
        sized = os.get_terminal_size(sys.stderr.fileno()).columns > 0
    except (OSError, ValueError, AttributeError):
        sized = False
    # a terminal that tells no size (0 x 0: a pseudo-terminal nobody sized) gets 80 x 24, tqdm would draw nothing
    size = {"dynamic_ncols": True} if sized else {"ncols": 80, "nrows": 24}
    bar = tqdm(total=total, desc=what, unit=unit, file=sys.stderr, delay=DELAY_S, leave=False, bar_format=fmt, **size)
    stop = threading.Event()
    drawing = threading.Lock()  # held by the heartbeat while it draws, and by this thread while it forks

    def beat() -> None:  # redraw while one long step holds the main thread (a solve releases the GIL often)
        while not stop.wait(_HEARTBEAT_S):
            if time.monotonic() - started >= DELAY_S:
                with drawing:
                    bar.refresh()
                    bar.last_print_t = time.time()  # drawn (tqdm's clock): erased on close

    started = time.monotonic()
    thread = threading.Thread(target=beat, name="cams-progress", daemon=True)
    _DRAWING.append(drawing)
    thread.start()
    try:
        yield Progress(bar)
    finally:
        stop.set()
        thread.join()
        if drawing in _DRAWING:
            _DRAWING.remove(drawing)
        bar.close()
