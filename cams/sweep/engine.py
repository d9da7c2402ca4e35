"""The sweep's engine: chunks of combinations submitted to an executor, rows handed on as each chunk completes.

Three seams, each one function:

- :func:`executor` ``(spec, workers)``: a context manager yielding ``(executor, stop)``, a
  :class:`concurrent.futures.Executor` and a function that cancels everything now (the pending chunks and the
  running ones: Ctrl-C). ``spec`` None is this machine (a process pool; one worker: this process); another
  ``spec`` is handed to ``cams.sweep.cluster.executor(spec, workers)``, which has the same shape (a Dask cluster:
  ``Client.get_executor()`` is such an executor).
- :func:`evaluate`: one chunk, in a worker: its designs built (:func:`build`), then sized together by the batch
  solver (:func:`size_at_once`, :mod:`cams.batch`), which sends the designs it does not take back to
  :func:`size`, each design by itself (``per_design``: every design so, the comparison path).
- :func:`run`: the loop. At most two chunks per worker are in flight, so an interrupted sweep loses at most
  those; each completed chunk's rows go to ``sink(rows)`` at once.
"""

from __future__ import annotations

import contextlib
import math
import time
from collections.abc import Callable, Iterator
from concurrent.futures import FIRST_COMPLETED, Executor, Future, ProcessPoolExecutor, wait
from typing import Any

from cams.io.processes import cores, end_pool, ignore_sigint, sigint_held
from cams.sweep.grid import Chunk, Grid
from cams.sweep.output import COLUMNS
from laws.errors import CamsError, InputError, SolverError

__all__ = ["MAX_WORKERS_PER_CPU", "executor", "build", "size", "evaluate", "run", "chunk_size"]

#: At most this many processes per core (and never more than designs).
MAX_WORKERS_PER_CPU = 4

#: Seconds of work a chunk aims at (rows reach the file about this often per worker).
CHUNK_S = 2.0
#: At most this many designs in one chunk (the batch solver: :data:`MAX_BATCH_CHUNK`).
MAX_CHUNK = 64
#: At most this many designs in one chunk of the batch solver (it sizes a chunk at once, at about a millisecond a
#: design: a larger chunk spreads its fixed cost).
MAX_BATCH_CHUNK = 256
#: Designs of each base file timed together first when the batch solver sizes them (one alone would pay the whole
#: batch's fixed cost and overstate the time).
BATCH_TIMED = 32


class _Here(Executor):
    """One worker: the chunks run in this process when submitted (Ctrl-C reaches them directly)."""

    def submit(self, fn, /, *args, **kwargs):
        f: Future = Future()
        try:
            f.set_result(fn(*args, **kwargs))
        except Exception as e:  # a fault of the product, passed on by the loop
            f.set_exception(e)
        return f


class _Pool(ProcessPoolExecutor):
    """A process pool whose workers ignore Ctrl-C; its workers start with SIGINT held back."""

    def submit(self, fn, /, *args, **kwargs):
        with sigint_held():  # a Ctrl-C while a worker starts reaches this process only, just after
            return super().submit(fn, *args, **kwargs)


@contextlib.contextmanager
def executor(spec: str | None, workers: int) -> Iterator[tuple[Executor, Callable[[], None]]]:
    """The executor the sweep runs on, and how to stop it now.

    Parameters
    ----------
    spec : str or None
        None: this machine, ``workers`` processes (one: this process). Else a cluster, handed to
        ``cams.sweep.cluster.executor(spec, workers)`` (same shape as this function).
    workers : int

    Yields
    ------
    (executor, stop)
        ``stop()`` cancels the pending chunks and ends the running ones; leaving the block normally waits for
        nothing left.
    """
    if spec is not None:
        import importlib

        cluster = importlib.import_module("cams.sweep.cluster")  # the cluster's executor (an optional extra)
        with cluster.executor(spec, workers) as pair:
            yield pair
        return
    if workers == 1:
        yield _Here(), lambda: None
        return
    ex = _Pool(max_workers=workers, initializer=ignore_sigint)
    try:
        yield ex, lambda: end_pool(ex)
    finally:
        ex.shutdown(wait=True, cancel_futures=True)


def _empty(head: dict) -> dict:
    row = dict(head)
    row.update({c: None for c in COLUMNS})
    return row


def build(chunk: Chunk) -> list[tuple[dict, Any]]:
    """The designs of a chunk's combinations: ``(row, design)`` each, the row holding ``index``, ``file``, the
    keys' values and empty results; ``design`` None where the design file's dict is refused (the row's ``error``
    says why)."""
    from cams.io.designfile import design_from_dict

    out: list[tuple[dict, Any]] = []
    for k in range(len(chunk.items)):
        d, head = chunk.design_dict(k)
        row = _empty(head)
        try:
            out.append((row, design_from_dict(d)))
        except CamsError as e:
            row["error"] = str(e)
            out.append((row, None))
    return out


def _rise_ca(design) -> float | None:
    """Norton's ``Ca`` of the first rise: its normalized law's largest ``|S''|`` (:mod:`laws.characteristics`);
    None where infinite (a velocity jump at a dwell) or without a rise."""
    from laws.characteristics import characteristics
    from laws.registry import get_law

    for ph in design.program.phases:
        if ph.kind == "rise":
            law = get_law(ph.law) if isinstance(ph.law, str) else ph.law
            ca = characteristics(law).ca
            return float(ca) if math.isfinite(ca) else None
    return None


def _results(cam) -> dict:
    """A sized cam's result cells, each read off the cam's own results (nothing computed again here)."""
    r = cam.solution
    rep = r.to_dict()
    a = cam.assessment  # one rule for every command: the profile's checks and [dynamics] too
    pa = rep.get("max_pressure_angle") or {}  # a roller's, by phase; a flat face's is the geometry's, not a limit
    out: dict[str, Any] = dict(
        R0=r.R0, L=r.L, offset=r.offset, centre_x=float(r.centre[0]), centre_y=float(r.centre[1]),
        blank_diameter=2.0 * rep["largest_cam_radius"], max_pressure_angle_rise=pa.get("rise"),
        max_pressure_angle_return=pa.get("return"), Ca_rise=_rise_ca(cam.design),
        verified=a.verified, buildable=a.buildable, failures="; ".join(a.failures) or None,
        error_bound=None if rep.get("error_bound") is None else float(rep["error_bound"]))
    if cam.design.contact is not None and cam.contact is not None:
        out["max_contact_stress"] = cam.contact.to_dict()["max_pressure"]
    if cam.vibration is not None:
        res = [p.residual for p in cam.vibration.phases]  # not to_dict(): it would search the jump speed
        out["residual_vibration"] = max(res) if res and all(x is not None for x in res) else None
    return out


def size(designs: list[tuple[dict, Any]], method: str | None) -> list[dict]:
    """The rows of a chunk's designs: each sized, profiled and checked (:class:`cams.cam.Cam`, the one rule of
    :mod:`cams.assess`), each by itself: the per-design path, and the designs :func:`size_at_once`'s batch solver
    sends back. A design without a solution is a row with its ``error``."""
    from cams.cam import Cam

    rows = []
    for row, design in designs:
        if design is not None:
            try:
                row.update(_results(Cam(design, method=method)))
            except CamsError as e:
                row["error"] = str(e)
            except SolverError as e:  # one design the solver failed on: a row that says so, not a lost batch
                row["error"] = f"solver failure: {e}"
            except (ArithmeticError, ValueError, LookupError, TypeError) as e:  # a fault of the product on one
                # design: its row says so (exit 1), the hours of the others are not lost
                row["error"] = f"internal error: {type(e).__name__}: {e}"
        rows.append(row)
    return rows


def size_at_once(designs: list[tuple[dict, Any]], method: str | None) -> list[dict]:
    """The rows of a chunk's designs by the batch solver (:func:`cams.batch.size_batch`: the chunk's roller
    designs sized, checked and judged at once); the designs it sends back (a kind it does not batch, a row near a
    threshold) are sized by :func:`size`, each by itself."""
    from cams.batch import size_batch

    todo = [k for k, (_, d) in enumerate(designs) if d is not None]
    got = size_batch([designs[k][1] for k in todo], method=method) if todo else []
    back: list[tuple[dict, Any]] = []
    for k, r in zip(todo, got, strict=True):
        row, design = designs[k]
        if r is None:
            back.append((row, design))
        else:
            row.update(r, Ca_rise=_rise_ca(design))
    size(back, method)  # fills the rows in place
    return [row for row, _ in designs]


def evaluate(job: tuple[Chunk, bool]) -> list[dict]:
    """One chunk: ``(chunk, per_design)`` -> its rows, in the chunk's order: by the batch solver, or each design
    by itself (``per_design``, the comparison path)."""
    chunk, per_design = job
    built = build(chunk)
    return size(built, chunk.method) if per_design else size_at_once(built, chunk.method)


def chunk_size(todo: int, workers: int, seconds_each: float, largest: int = MAX_CHUNK) -> int:
    """Designs per chunk: about :data:`CHUNK_S` seconds of work, at least 8 chunks per worker, 1 to
    ``largest``."""
    by_time = int(CHUNK_S / seconds_each) if seconds_each > 0 else largest
    return max(1, min(largest, by_time, todo // (workers * 8) or 1))


def workers_for(workers: int | None, n: int) -> int:
    """Processes for ``n`` designs: ``workers`` (default the cores), never more than the designs nor
    :data:`MAX_WORKERS_PER_CPU` per core."""
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int) or workers < 1):
        raise InputError("workers", f"must be an integer >= 1 (processes), got {workers!r}")
    cpus = cores()
    return max(1, min(workers or cpus, n, MAX_WORKERS_PER_CPU * cpus))


def run(grid: Grid, todo: list[int], *, workers: int, sink: Callable[[list[dict]], None],
        progress: Callable[[int, int], None] | None = None,
        estimate: Callable[[float, int, int], None] | None = None, cluster: str | None = None,
        per_design: bool = False) -> tuple[int, int]:
    """:func:`_run` on this machine, or on ``cluster`` reached before any design is solved (a wrong address is
    said at once, with no row written, and a small sweep's designs all timed here still ask for the cluster)."""
    if cluster is None or not todo:
        return _run(grid, todo, workers=workers, sink=sink, progress=progress, estimate=estimate,
                    pool=lambda: executor(None, workers), per_design=per_design)
    with executor(cluster, workers) as pair:
        return _run(grid, todo, workers=workers, sink=sink, progress=progress, estimate=estimate,
                    pool=lambda: contextlib.nullcontext(pair), per_design=per_design)


def _run(grid: Grid, todo: list[int], *, workers: int, sink: Callable[[list[dict]], None],
         progress: Callable[[int, int], None] | None, estimate: Callable[[float, int, int], None] | None,
         pool: Callable[[], contextlib.AbstractContextManager[tuple[Executor, Callable[[], None]]]],
         per_design: bool) -> tuple[int, int]:
    """Evaluate the combinations ``todo`` and hand each chunk's rows to ``sink`` as it completes.

    A few designs are timed first in this process (the first of each base file's block still to do, and the
    last of the first file's; with the batch solver, up to :data:`BATCH_TIMED` consecutive designs from each;
    ``[optimize]`` designs take seconds, plain ones milliseconds): their rows are the first written, and
    ``estimate(seconds, timed, workers)`` is told the time expected for all of ``todo`` (the
    timed designs' included).

    Returns
    -------
    (rows, workers)
        Rows written and the workers used.

    Raises
    ------
    KeyboardInterrupt
        Passed on after ``stop()``: the rows handed on stay; the chunks in flight are lost.
    """
    n = len(todo)
    done = 0
    if not n:
        return 0, workers
    per = grid.per_file
    firsts: dict[int, int] = {}
    for i in todo:
        firsts.setdefault(i // per, i)
    timed = list(firsts.values())
    if len(todo) > len(timed) and todo[-1] not in timed:
        timed.append(todo[-1])
    timed = timed[: max(1, min(len(timed), 4))]
    # the batch solver times a few consecutive designs of the file together (alone, one pays the batch's fixed cost)
    together = 1 if per_design else BATCH_TIMED
    where = {i: k for k, i in enumerate(todo)}
    taken: set[int] = set()
    secs: dict[int, list[float]] = {}  # base file -> its timed designs' seconds each
    spent = 0.0  # seconds the timed designs took
    for i in timed:  # each group's rows written at once: an [optimize] design takes seconds
        group = [j for j in todo[where[i]:where[i] + together] if j // per == i // per and j not in taken]
        if not group:
            continue
        taken.update(group)
        t0 = time.perf_counter()
        rows = evaluate((grid.chunk(group), per_design))
        took = time.perf_counter() - t0
        spent += took
        secs.setdefault(i // per, []).append(took / len(group))
        sink(rows)
        done += len(rows)
        if progress:
            progress(done, n)
    # a file's designs take about its quickest timed one's time (the first in a process pays for the imports)
    quick = {f: min(v) for f, v in secs.items()}
    each = sum(quick.values()) / len(quick)
    rest = [i for i in todo if i not in taken]
    if estimate:
        # an [optimize] design takes seconds, a plain one milliseconds: each file's own time
        estimate(spent + sum(quick.get(i // per, each) for i in rest) / workers, len(taken), workers)
    if not rest:
        return done, workers
    chunk = chunk_size(len(rest), workers, each, MAX_CHUNK if per_design else MAX_BATCH_CHUNK)
    chunks = [rest[k:k + chunk] for k in range(0, len(rest), chunk)]
    with pool() as (ex, stop):
        try:
            pending: set[Future] = set()
            it = iter(chunks)
            window = 2 * workers
            for c in it:
                pending.add(ex.submit(evaluate, (grid.chunk(c), per_design)))
                if len(pending) >= window:
                    break
            while pending:
                finished, pending = wait(pending, return_when=FIRST_COMPLETED)
                for f in finished:
                    rows = f.result()
                    sink(rows)
                    done += len(rows)
                    if progress:
                        progress(done, n)
                for c in it:
                    pending.add(ex.submit(evaluate, (grid.chunk(c), per_design)))
                    if len(pending) >= window:
                        break
        except BaseException:  # Ctrl-C included: no process, no pending design is left
            stop()
            raise
    return done, workers
