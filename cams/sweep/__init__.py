"""Parameter sweeps: many designs from design files, streamed as they are solved, resumable.

A sweep varies dotted design-file keys (``limits.pressure_angle``, ``follower.arm``, ``motion[0].law``,
``limits.closure`` ...) over numbers (ranges ``a:b:n``, lists) or words (laws, closures, senses...), as a full grid
or paired (zip), over one or several base design files (:mod:`cams.sweep.grid`), and solves every combination on
an executor, chunk by chunk (:mod:`cams.sweep.engine`), handing each chunk's rows on as it completes: the command
streams them into a CSV or Parquet table with a sidecar identity for ``--resume`` (:mod:`cams.sweep.output`).

Each row says whether the cam is ``verified`` and ``buildable`` (:mod:`cams.assess`: the checks of the finished
profile and the ``[dynamics]`` table included, as every command), and ``failures`` lists why not. Infeasible
combinations are rows with an ``error`` and no sizes, not failures of the batch; a base design that is wrong
whatever the varied keys are (a required key missing, an unknown table), a key that does not exist, a value of
the wrong kind for its key, is an :class:`~laws.errors.InputError` before anything is solved.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from cams.sweep.engine import MAX_WORKERS_PER_CPU, run, workers_for
from cams.sweep.grid import MAX_DESIGNS, BaseFile, Grid, key_parts, make_grid, parse_vary, read_sweep_file
from cams.sweep.output import COLUMN_UNITS, COLUMNS, csv_header, csv_row, failed

__all__ = ["parse_vary", "key_parts", "sweep", "SweepResult", "COLUMNS", "COLUMN_UNITS", "csv_header", "csv_row",
           "MAX_WORKERS_PER_CPU", "MAX_DESIGNS", "BaseFile", "Grid", "make_grid", "read_sweep_file", "run_grid"]


@dataclass(frozen=True)
class SweepResult:
    """A sweep's rows (dicts: ``index``, ``file``, the varied keys, then :data:`COLUMNS`, in index order; empty
    when not kept), how many were solved and failed, and the timing.

    ``count`` and ``failures`` are counted as the rows come (:func:`run_grid`), kept or not."""

    keys: tuple[str, ...]
    rows: list
    seconds: float
    workers: int
    count: int
    failures: int

    @property
    def failed(self) -> int:
        """Rows that are not usable: no solution (an ``error``), or an assessment with failures.

        A row's ``failures`` are its :class:`cams.assess.Assessment`'s, empty exactly when it is usable
        (certified, verified and buildable).
        """
        return self.failures

    @property
    def solved(self) -> int:
        """Designs solved by this run."""
        return self.count

    @property
    def per_second(self) -> float:
        """Designs solved per second of wall time."""
        return self.solved / self.seconds if self.seconds > 0 else float("inf")


def run_grid(grid: Grid, *, workers: int | None = None, done: Sequence[int] | set[int] = (),
             sink: Callable[[list[dict]], None] | None = None, keep: bool = True,
             progress: Callable[[int, int], None] | None = None,
             estimate: Callable[[float, int, int], None] | None = None, cluster: str | None = None,
             per_design: bool = False) -> SweepResult:
    """Solve the combinations of ``grid`` not in ``done``, handing each chunk's rows to ``sink`` as it completes.

    Parameters
    ----------
    grid : Grid
        From :func:`make_grid` (checked).
    workers : int, optional
        Processes (default: the machine's cores), an integer >= 1; never more than the designs nor
        :data:`MAX_WORKERS_PER_CPU` per core. 1 runs in this process. On a cluster: its workers.
    done : set of int
        Indexes already solved (``--resume``): skipped.
    sink : callable, optional
        Called with each completed chunk's rows (the command's streamed file).
    keep : bool
        Keep the rows in the result (False: only counted; a long sweep's rows live in its file).
    progress : callable, optional
        ``progress(done, total)`` as designs are solved (the command's bar, :mod:`cams.commands.progress`).
    estimate : callable, optional
        ``estimate(seconds, timed, workers)``: the time expected for the designs to solve, from ``timed`` designs
        timed first (their time included).
    cluster : str, optional
        Run on a cluster (``cams.sweep.cluster.executor``) instead of this machine's processes.
    per_design : bool
        Size each design by itself (the comparison path); default: the batch solver (:mod:`cams.batch`), which
        sends the designs it does not take to that path.

    Raises
    ------
    InputError
        A bad ``workers``.
    KeyboardInterrupt
        Passed on after the processes are stopped and the pending designs cancelled; the rows handed to
        ``sink`` stay.
    """
    done_set = set(done)
    todo = [i for i in range(grid.size) if i not in done_set]
    w = workers_for(workers, max(1, len(todo)))
    kept: list[dict] = []
    counts = [0, 0]

    def take(rows: list[dict]) -> None:
        counts[0] += len(rows)
        counts[1] += sum(1 for r in rows if failed(r))
        if keep:
            kept.extend(rows)
        if sink is not None:
            sink(rows)

    t0 = time.perf_counter()
    run(grid, todo, workers=w, sink=take, progress=progress, estimate=estimate, cluster=cluster,
        per_design=per_design)
    kept.sort(key=lambda r: r["index"])
    return SweepResult(keys=grid.keys, rows=kept, seconds=time.perf_counter() - t0, workers=w, count=counts[0],
                       failures=counts[1])


def sweep(base: dict | Sequence[BaseFile], vary: list[tuple[str, Any]], *, method: str | None = None,
          workers: int | None = None, mode: str = "grid",
          progress: Callable[[int, int], None] | None = None, per_design: bool = False) -> SweepResult:
    """Solve every combination of the varied keys over a base design (a design-file dict) or several.

    Parameters
    ----------
    base : dict or sequence of BaseFile
        A parsed design file, or several (one more axis: the rows' ``file``).
    vary : list of (key, values)
        Dotted keys into the design file (list items by index) and their values: numbers, words (a law's
        name, a closure...), booleans.
    method : str, optional
        Overrides the design's method.
    workers : int, optional
        Processes (see :func:`run_grid`).
    mode : {"grid", "zip"}
        Every combination, or the k-th values of the keys together.
    progress : callable, optional
        ``progress(done, total)`` as designs are solved.
    per_design : bool
        Size each design by itself (the comparison path); default: the batch solver, as :func:`run_grid`.

    Raises
    ------
    InputError
        A bad ``workers``; a key varied twice (``--vary``) or that does not fit the design file; a value of
        the wrong kind for its key; a base design that is wrong whatever the varied values (the design's own
        error, e.g. ``follower.swing: is required``). An infeasible combination is no error: its row carries it.
    KeyboardInterrupt
        Passed on after the processes are stopped and the pending designs cancelled.
    """
    workers_for(workers, 1)
    files = [BaseFile("", base)] if isinstance(base, dict) else list(base)
    grid = make_grid(files, vary, mode=mode, method=method)
    return run_grid(grid, workers=workers, progress=progress, per_design=per_design)
