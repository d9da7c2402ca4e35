"""Parameter sweeps: many designs from one design file, in parallel.

A sweep varies dotted design-file keys (``limits.pressure_angle``,
``follower.arm``, ``motion.0.angle`` or ``motion[0].angle`` ...) over ranges
and solves every combination. Each row says whether the cam is ``verified``
and ``buildable`` (:mod:`cams.assess`: the checks of the finished profile and
the ``[dynamics]`` table included, as every command), and ``failures`` lists
why not. Infeasible combinations are rows with an ``error`` and no sizes, not
failures of the batch; a base design that is wrong
whatever the varied keys are (a required key missing, an unknown table) is an
:class:`~laws.errors.InputError` before anything is solved.
"""

from __future__ import annotations

import contextlib
import copy
import itertools
import math
import os
import re
import signal
import time
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass

import numpy as np

from laws.errors import CamsError, InputError, SolverError

__all__ = ["parse_vary", "key_parts", "sweep", "SweepResult", "COLUMNS", "COLUMN_UNITS", "csv_header", "csv_row",
           "MAX_WORKERS_PER_CPU", "MAX_DESIGNS"]

#: At most this many processes per core (and never more than designs).
MAX_WORKERS_PER_CPU = 4

#: At most this many designs in one sweep (the product of the varied keys' counts): about an hour on two cores.
MAX_DESIGNS = 100_000

#: Result columns after the varied keys.
COLUMNS = ("R0", "L", "offset", "centre_x", "centre_y", "max_pressure_rise", "max_pressure_return",
           "verified", "buildable", "error_bound", "failures", "error")

#: Unit of each result column, written into the CSV header as ``name_unit`` (none for flags and text).
COLUMN_UNITS = {"R0": "mm", "L": "mm", "offset": "mm", "centre_x": "mm", "centre_y": "mm",
                "max_pressure_rise": "deg", "max_pressure_return": "deg", "error_bound": "mm"}


def csv_header(keys: tuple[str, ...]) -> list[str]:
    """The CSV header: the varied keys (units as in the design file) then :data:`COLUMNS` with their units.

    >>> csv_header(("follower.arm",))[:3]
    ['follower.arm', 'R0_mm', 'L_mm']
    """
    return list(keys) + [f"{c}_{COLUMN_UNITS[c]}" if c in COLUMN_UNITS else c for c in COLUMNS]


def csv_row(row: dict) -> list:
    """A row's cells in :func:`csv_header`'s order, None as an empty cell.

    Lengths keep every digit (they round-trip, as JSON does); angles in
    degrees, converted from radians, are written to 12 significant digits so
    a limit reads ``30``, not ``29.999999999999996``; the varied inputs to 15
    (``0.3``, not ``0.30000000000000004``).

    >>> csv_row({"R0": 13.240793033539259, "max_pressure_rise": 29.999999999999996, "error": None})
    ['13.240793033539259', '30', '']
    """
    def cell(k, v):
        if v is None:
            return ""
        if isinstance(v, float):
            if k not in COLUMNS:  # a varied input: a range's values without linspace's last-digit noise
                return f"{v:.15g}"
            return f"{v:.12g}" if COLUMN_UNITS.get(k) == "deg" else repr(float(v))
        return v

    return [cell(k, v) for k, v in row.items()]


def parse_vary(spec: str) -> tuple[str, np.ndarray]:
    """``"KEY=a:b:n"`` -> (KEY, n values from a to b); ``"KEY=v1,v2,..."`` -> listed values."""
    if "=" not in spec:
        raise InputError("--vary", f"{spec!r} must look like KEY=a:b:n or KEY=v1,v2")
    key, rng = spec.split("=", 1)
    key = key.strip()
    try:
        if ":" in rng:
            a, b, count = rng.split(":")
            n = int(count)
            if n < 1:
                raise ValueError
            if n > MAX_DESIGNS:
                vals = None
            else:
                vals = np.linspace(float(a), float(b), n)
        else:
            vals = np.array([float(v) for v in rng.split(",")])
    except ValueError:
        raise InputError("--vary", f"{spec!r}: range must be a:b:n (n >= 1) or a list of numbers") from None
    if vals is None:
        raise InputError("--vary", f"{spec!r}: at most {MAX_DESIGNS:,} values, got {n:,}")
    if not np.all(np.isfinite(vals)):
        raise InputError("--vary", f"{spec!r}: values must be finite numbers")
    if not key:
        raise InputError("--vary", f"{spec!r} names no key")
    key_parts(key)
    return key, vals


_SEGMENT = re.compile(r"([^.\[\]]+)((?:\[\d+\])*)")


def key_parts(key: str, field: str = "--vary") -> tuple[str, ...]:
    """The parts of a dotted key: ``"motion[0].angle"`` and ``"motion.0.angle"`` -> ``("motion", "0", "angle")``.

    Raises
    ------
    InputError
        Naming ``field``: an empty part or a malformed ``[index]``.
    """
    parts: list[str] = []
    for seg in key.split("."):
        m = _SEGMENT.fullmatch(seg.strip())
        if not m:
            raise InputError(field, f"{key!r} is not a dotted key (table.key, list items as motion.0 or motion[0])")
        parts.append(m.group(1))
        parts += re.findall(r"\[(\d+)\]", m.group(2))
    return tuple(parts)


def _index(node: list, p: str, key: str) -> int:
    if not p.isdigit() or int(p) >= len(node):
        raise InputError("--vary", f"{key!r}: {p!r} is not an index of the list (0 to {len(node) - 1})")
    return int(p)


def _set(d: dict, key: str, value: float) -> None:
    parts = key_parts(key)
    node = d
    for k, p in enumerate(parts[:-1]):
        if isinstance(node, list):
            node = node[_index(node, p, key)]
        else:
            node = node.setdefault(p, {})
        if not isinstance(node, (dict, list)):
            raise InputError("--vary", f"{key!r}: {'.'.join(parts[:k + 1])!r} is a value, not a table or list")
    last = parts[-1]
    if isinstance(node, list):
        node[_index(node, last, key)] = value
    else:
        node[last] = value


def _involves(field: str, keys: tuple[str, ...]) -> bool:
    """Whether an error about ``field`` can come from the varied ``keys``.

    It does when one is a prefix of the other (``motion`` and ``motion.0.angle``)
    or both are items of the same list (``motion[3].angle`` and ``motion.0.angle``:
    the phases' angles share the turn).
    """
    try:
        f = key_parts(field) if field else ()
    except InputError:
        f = tuple(field.split("."))
    if not f:
        return True  # an error naming no field: cannot tell, keep it a row
    for key in keys:
        k = key_parts(key)
        n = min(len(f), len(k))
        if f[:n] == k[:n]:
            return True
        if len(f) > 1 and len(k) > 1 and f[0] == k[0] and f[1].isdigit() and k[1].isdigit():
            return True
    return False


def _number(v) -> int | float:
    """An integral value as int (for keys like ``solve.samples``), else float."""
    f = float(v)
    return int(f) if f.is_integer() and abs(f) < 2**53 else f


def _solve_one(args) -> dict:
    base, keys, values, method = args
    from cams.cam import Cam
    from cams.io.designfile import design_from_dict

    d = copy.deepcopy(base)
    for k, v in zip(keys, values, strict=True):
        _set(d, k, _number(v))
    row: dict[str, int | float | str | bool | None] = {k: _number(v) for k, v in zip(keys, values, strict=True)}
    row.update({c: None for c in COLUMNS})
    try:
        design = design_from_dict(d)
        cam = Cam(design, method=method)
        r = cam.solution
        rep = r.to_dict()
        a = cam.assessment  # one rule for every command: the profile's checks and [dynamics] too
        row.update(R0=r.R0, L=r.L, offset=r.offset, centre_x=float(r.centre[0]), centre_y=float(r.centre[1]),
                   max_pressure_rise=rep["max_pressure_angle"]["rise"],
                   max_pressure_return=rep["max_pressure_angle"]["return"],
                   verified=a.verified, buildable=a.buildable, error_bound=r.error_bound,
                   failures="; ".join(a.failures) or None)
    except CamsError as e:
        row["error"] = str(e)
    except SolverError as e:  # one design the solver failed on: a row that says so, not a lost batch
        row["error"] = f"solver failure: {e}"
    return row


@dataclass(frozen=True)
class SweepResult:
    """Rows of a sweep (dicts with the varied keys then :data:`COLUMNS`) and its timing."""

    keys: tuple[str, ...]
    rows: list
    seconds: float
    workers: int

    @property
    def failed(self) -> int:
        """Rows that are not usable: no solution (an ``error``), or an assessment with failures.

        A row's ``failures`` are its :class:`cams.assess.Assessment`'s, empty exactly when it is usable
        (certified, verified and buildable).
        """
        return sum(1 for r in self.rows if r["error"] or r["failures"])

    @property
    def per_second(self) -> float:
        """Designs solved per second of wall time."""
        return len(self.rows) / self.seconds if self.seconds > 0 else float("inf")


def _ignore_sigint() -> None:
    """In the workers: Ctrl-C is the parent's to handle (it stops the pool); no traceback per process."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})


@contextlib.contextmanager
def _sigint_held():
    """Hold SIGINT back (POSIX) while the pool forks its workers, so that none gets it before ignoring it."""
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def _stop(ex: ProcessPoolExecutor) -> None:
    """Shut the pool down now: cancel the pending designs, end the running ones."""
    procs = list((getattr(ex, "_processes", None) or {}).values())
    for p in procs:
        if p.is_alive():
            p.terminate()
    ex.shutdown(wait=True, cancel_futures=True)


def _check_workers(workers) -> None:
    if workers is None:
        return
    if isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 1:
        raise InputError("workers", f"must be an integer >= 1 (processes), got {workers!r}")


def _check_base(base: dict, keys: tuple[str, ...], combos: list) -> None:
    """Refuse a base design that is wrong whatever the varied keys are (exit 2, not a table of the same error)."""
    from cams.io.designfile import design_from_dict

    def probe(values):
        d = copy.deepcopy(base)
        if values is not None:  # None: the base design alone
            for k, v in zip(keys, values, strict=True):
                _set(d, k, _number(v))
        try:
            design_from_dict(d)
        except CamsError as e:
            return e
        return None

    e = probe(combos[0])
    if e is None:
        return
    if "unknown key" in str(e):
        b = probe(None)
        if b is not None and str(b) == str(e):
            raise e from None  # the design file's own unknown key
        # a varied key that does not exist in the schema is a mistake in the sweep, not an infeasible design
        raise InputError("--vary", str(e)) from None
    if _involves(getattr(e, "field", "") or "", keys):
        return  # the varied values may be at fault: the rows say so
    last = probe(combos[-1])
    if last is not None and str(last) == str(e):
        raise e from None  # the base design itself is wrong


def sweep(base: dict, vary: list[tuple[str, np.ndarray]], *, method: str | None = None,
          workers: int | None = None,
          progress: Callable[[int, int], None] | None = None) -> SweepResult:
    """Solve every combination of the varied keys over a base design (a design-file dict).

    Parameters
    ----------
    base : dict
        A parsed design file.
    vary : list of (key, values)
        Dotted keys into the design file (list items by index) and their values.
    method : str, optional
        Overrides the design's method.
    workers : int, optional
        Processes (default: the machine's cores), an integer >= 1; never more
        than the designs nor :data:`MAX_WORKERS_PER_CPU` per core. 1 runs in
        this process.
    progress : callable, optional
        Called as ``progress(done, total)`` as designs are solved (the command's bar,
        :mod:`cams.commands.progress`); None: nothing is said.

    Raises
    ------
    InputError
        A bad ``workers``; a key varied twice (``--vary``) or that does not
        fit the design file; a base design that is wrong whatever the varied
        values (the design's own error, e.g. ``follower.swing: is required``).
        An infeasible combination is no error: its row carries it.
    KeyboardInterrupt
        Passed on after the processes are stopped and the pending designs
        cancelled.
    """
    _check_workers(workers)
    keys = tuple(k for k, _ in vary)
    seen: dict[tuple[str, ...], str] = {}  # key parts -> the key as given
    for key in keys:
        parts = key_parts(key)
        if parts in seen:
            same = "" if seen[parts] == key else f" (as {seen[parts]!r})"
            raise InputError("--vary", f"{key!r} is varied twice{same}; give each key once with all its values")
        seen[parts] = key
    count = math.prod(len(v) for _, v in vary)
    if count > MAX_DESIGNS:
        raise InputError("--vary", f"the sweep has {count:,} designs; at most {MAX_DESIGNS:,} are accepted")
    combos = list(itertools.product(*[v for _, v in vary]))
    fo = base.get("follower")
    if isinstance(fo, dict) and fo.get("face") == "flat":
        raise InputError("follower.face", "cams sweep solves roller followers only; size flat-faced followers one "
                         "file at a time with cams solve")
    if not combos:
        raise InputError("--vary", "the sweep has no designs")
    _check_base(base, keys, combos)  # fail early on a key that does not fit, or a base design that cannot work
    n = len(combos)
    cpus = os.cpu_count() or 1
    workers = min(workers or cpus, n, MAX_WORKERS_PER_CPU * cpus)
    jobs = [(base, keys, c, method) for c in combos]
    t0 = time.perf_counter()
    rows = []

    def tick(k):
        if progress:
            progress(k, n)

    if workers == 1:
        for k, j in enumerate(jobs, 1):
            rows.append(_solve_one(j))
            tick(k)
    else:
        chunk = max(1, min(64, n // (workers * 8) or 1))
        ex = ProcessPoolExecutor(max_workers=workers, initializer=_ignore_sigint)
        try:
            with _sigint_held():  # a Ctrl-C while the workers start reaches this process only, just after
                results = ex.map(_solve_one, jobs, chunksize=chunk)
            for k, r in enumerate(results, 1):
                rows.append(r)
                if k % chunk == 0 or k == n:
                    tick(k)
        except BaseException:  # Ctrl-C included: no process, no pending design is left
            _stop(ex)
            raise
        ex.shutdown(wait=True)
    return SweepResult(keys=keys, rows=rows, seconds=time.perf_counter() - t0, workers=workers)
