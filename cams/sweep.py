"""Parameter sweeps: many designs from one design file, in parallel.

A sweep varies dotted design-file keys (``limits.pressure_angle``,
``follower.arm``, ``motion.0.angle`` ...) over ranges and solves every
combination. Infeasible combinations are rows with an ``error`` and no sizes,
not failures of the batch.
"""

from __future__ import annotations

import copy
import itertools
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass

import numpy as np

from laws.errors import CamsError, InputError

__all__ = ["parse_vary", "sweep", "SweepResult", "COLUMNS"]

#: Result columns after the varied keys.
COLUMNS = ("R0", "L", "offset", "centre_x", "centre_y", "max_pressure_rise", "max_pressure_return",
           "verified", "error_bound", "error")


def parse_vary(spec: str) -> tuple[str, np.ndarray]:
    """``"KEY=a:b:n"`` -> (KEY, n values from a to b); ``"KEY=v1,v2,..."`` -> listed values."""
    if "=" not in spec:
        raise InputError("--vary", f"{spec!r} must look like KEY=a:b:n or KEY=v1,v2")
    key, rng = spec.split("=", 1)
    key = key.strip()
    try:
        if ":" in rng:
            a, b, n = rng.split(":")
            n = int(n)
            if n < 1:
                raise ValueError
            vals = np.linspace(float(a), float(b), n)
        else:
            vals = np.array([float(v) for v in rng.split(",")])
    except ValueError:
        raise InputError("--vary", f"{spec!r}: range must be a:b:n (n >= 1) or a list of numbers") from None
    if not key:
        raise InputError("--vary", f"{spec!r} names no key")
    return key, vals


def _set(d: dict, key: str, value: float) -> None:
    parts = key.split(".")
    node = d
    for k, p in enumerate(parts[:-1]):
        if isinstance(node, list):
            try:
                node = node[int(p)]
            except (ValueError, IndexError):
                raise InputError("--vary", f"{key!r}: {p!r} is not an index of the list") from None
        else:
            node = node.setdefault(p, {})
    last = parts[-1]
    if isinstance(node, list):
        try:
            node[int(last)] = value
        except (ValueError, IndexError):
            raise InputError("--vary", f"{key!r}: {last!r} is not an index of the list") from None
    else:
        node[last] = value


def _number(v) -> int | float:
    """An integral value as int (for keys like ``solve.samples``), else float."""
    f = float(v)
    return int(f) if f.is_integer() and abs(f) < 2**53 else f


def _solve_one(args) -> dict:
    base, keys, values, method = args
    from cams.designfile import design_from_dict
    from optimize.solve import solve

    d = copy.deepcopy(base)
    for k, v in zip(keys, values):
        _set(d, k, _number(v))
    row = {k: _number(v) for k, v in zip(keys, values)}
    row.update({c: None for c in COLUMNS})
    try:
        design = design_from_dict(d)
        r = solve(design, method=method, objective=design.extra.get("objective", "R0"))
        rep = r.to_dict()
        row.update(R0=r.R0, L=r.L, offset=r.offset, centre_x=float(r.centre[0]), centre_y=float(r.centre[1]),
                   max_pressure_rise=rep["max_pressure_angle"]["rise"],
                   max_pressure_return=rep["max_pressure_angle"]["return"],
                   verified=r.verified, error_bound=r.error_bound)
    except CamsError as e:
        row["error"] = str(e)
    return row


@dataclass(frozen=True)
class SweepResult:
    """Rows of a sweep (dicts with the varied keys then :data:`COLUMNS`) and its timing."""

    keys: tuple[str, ...]
    rows: list
    seconds: float
    workers: int

    @property
    def per_second(self) -> float:
        """Designs solved per second of wall time."""
        return len(self.rows) / self.seconds if self.seconds > 0 else float("inf")


def sweep(base: dict, vary: list[tuple[str, np.ndarray]], *, method: str | None = None,
          workers: int | None = None, progress: bool = False) -> SweepResult:
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
        Processes (default: the machine's cores); 1 runs in this process.
    progress : bool
        Draw a progress bar on stderr.
    """
    keys = tuple(k for k, _ in vary)
    combos = list(itertools.product(*[v for _, v in vary]))
    fo = base.get("follower")
    if isinstance(fo, dict) and fo.get("face") == "flat":
        raise InputError("follower.face", "cams sweep solves roller followers only; size flat-faced followers one "
                         "file at a time with cams solve")
    if not combos:
        raise InputError("--vary", "the sweep has no designs")
    # fail early on a key that does not fit the design file
    from cams.designfile import design_from_dict

    probe = copy.deepcopy(base)
    for k, v in zip(keys, combos[0]):
        _set(probe, k, _number(v))
    try:
        design_from_dict(probe)
    except InputError as e:
        # a key that does not exist in the schema is a mistake in the sweep, not an infeasible design
        if "unknown key" in str(e):
            raise InputError("--vary", str(e)) from None
    workers = workers or os.cpu_count() or 1
    jobs = [(base, keys, c, method) for c in combos]
    t0 = time.perf_counter()
    rows = []
    n = len(jobs)

    def tick(k):
        if progress:
            w = 40
            done = int(w * k / n)
            sys.stderr.write(f"\r[{'#' * done}{'.' * (w - done)}] {k}/{n}")
            sys.stderr.flush()

    if workers == 1:
        for k, j in enumerate(jobs, 1):
            rows.append(_solve_one(j))
            tick(k)
    else:
        chunk = max(1, min(64, n // (workers * 8) or 1))
        with ProcessPoolExecutor(max_workers=workers) as ex:
            for k, r in enumerate(ex.map(_solve_one, jobs, chunksize=chunk), 1):
                rows.append(r)
                if k % chunk == 0 or k == n:
                    tick(k)
    if progress:
        sys.stderr.write("\n")
    return SweepResult(keys=keys, rows=rows, seconds=time.perf_counter() - t0, workers=workers)
