"""Pareto fronts of a sweep's rows: the designs no other design beats on every chosen objective.

Pure numpy. Objectives are minimised by default; an objective written ``max:COL`` is maximised
(``min:COL`` says the default). A design *dominates* another when it is no worse on every objective
and strictly better on at least one; the front is the set of designs no design dominates. Equal
points dominate neither each other: all of them are on the front when one is (:attr:`Front.ties`
says which).

Rows that are not usable (an ``error``, ``failures``: :class:`cams.assess.Assessment`'s rule, or a
``verified`` or ``buildable`` flag not True: :func:`cams.sweep.output.failed`, the sweep's ``failed``
count) and rows with an empty (or not finite) objective are left out of the comparison, and counted
(:attr:`Front.unusable`, :attr:`Front.empty`). A table without ``error`` and ``failures`` columns cannot
say which rows are usable: refused unless the caller says (``usable``).

Cost: sorting, then one pass for two objectives (O(n log n)); for three or more, one vectorised
pass over the remaining points per point of the front (O(n h) for a front of h points), a second or
so for 100,000 rows and a front of a few hundred.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from laws.errors import InputError

__all__ = ["Objective", "parse_objectives", "non_dominated", "usable_mask", "Front", "pareto_front"]


@dataclass(frozen=True)
class Objective:
    """One objective of a front: a column name and its direction.

    Attributes
    ----------
    column : str
        The column, as given (with or without its unit suffix; the reader resolves it).
    maximise : bool
        True for ``max:COL``: larger is better.
    """

    column: str
    maximise: bool = False

    def __str__(self) -> str:
        return f"max:{self.column}" if self.maximise else self.column


def parse_objectives(spec: str | Sequence[str], field: str = "--pareto") -> tuple[Objective, ...]:
    """``"R0,max:L"`` (or a list of such items) -> the objectives, each column once.

    Raises
    ------
    InputError
        Naming ``field``: no objective, an empty item, or a column given twice.

    >>> parse_objectives("R0, max:L")
    (Objective(column='R0', maximise=False), Objective(column='L', maximise=True))
    """
    items = spec.split(",") if isinstance(spec, str) else [s for part in spec for s in part.split(",")]
    out: list[Objective] = []
    for raw in items:
        s = raw.strip()
        low = s.lower()
        maximise = low.startswith("max:")
        if maximise or low.startswith("min:"):
            s = s[4:].strip()
        if not s:
            raise InputError(field, f"{spec!r}: give columns as COL,COL[,...] (max:COL to maximise one)")
        if any(o.column == s for o in out):
            raise InputError(field, f"{spec!r}: column {s!r} is given twice")
        out.append(Objective(s, maximise))
    if not out:
        raise InputError(field, "give at least one column")
    return tuple(out)


def non_dominated(points: np.ndarray, maximise: Sequence[bool] | None = None) -> np.ndarray:
    """Which points no other point dominates (minimising each column unless ``maximise`` says so).

    Parameters
    ----------
    points : array of shape (n, k)
        Finite objective values, one row per design, one column per objective (the columns' units).
    maximise : sequence of k bool, optional
        True where larger is better; default: every column minimised.

    Returns
    -------
    ndarray of bool, shape (n,)
        True for the points on the front. Equal points are all on it or all off it.

    Raises
    ------
    InputError
        ``points`` is not a finite 2-D array, or ``maximise`` has the wrong length.
    """
    p = np.asarray(points, dtype=float)
    if p.ndim != 2:
        raise InputError("points", f"must be a 2-D array (designs x objectives), got shape {p.shape}")
    n, k = p.shape
    if n == 0:
        return np.zeros(0, dtype=bool)
    if k == 0:
        raise InputError("points", "give at least one objective")
    if not np.all(np.isfinite(p)):
        raise InputError("points", "must be finite (leave out the rows with an empty objective)")
    if maximise is not None:
        if len(maximise) != k:
            raise InputError("maximise", f"one flag per objective ({k}), got {len(maximise)}")
        p = np.where(np.asarray(maximise, dtype=bool), -p, p)
    # equal points share one fate: compare the distinct points (np.unique sorts them lexicographically)
    u, inverse = np.unique(p, axis=0, return_inverse=True)
    inverse = np.asarray(inverse).reshape(-1)
    # no distinct point can be dominated by one after it in lexicographic order (a dominator is lexicographically
    # smaller), so the first remaining point is on the front
    if k == 1:
        on = np.zeros(len(u), dtype=bool)
        on[0] = True
    elif k == 2:
        # distinct and sorted by (f1, f2): a point is dominated exactly when an earlier one has f2 <= its f2
        prev_min = np.minimum.accumulate(np.concatenate([[np.inf], u[:-1, 1]]))
        on = u[:, 1] < prev_min
    else:
        on = np.zeros(len(u), dtype=bool)
        alive = np.arange(len(u))
        while alive.size:
            first = u[alive[0]]
            on[alive[0]] = True
            rest = u[alive[1:]]
            # dominated by `first`: no better anywhere (and, the points being distinct, worse somewhere)
            keep = np.any(rest < first, axis=1)
            alive = alive[1:][keep]
    return on[inverse]


def usable_mask(columns: Mapping[str, Sequence], *, field: str = "--pareto", name: str = "the table") -> np.ndarray:
    """True for the rows :func:`cams.sweep.output.failed` passes: neither an ``error`` nor ``failures`` (None, NaN
    and ``""`` are empty) and, where the table has the columns, ``verified`` and ``buildable`` True.

    Parameters
    ----------
    columns : mapping of str to sequence
        The table's columns, all of one length (name -> values).
    field, name : str
        The field and the table named when a column is missing.

    Raises
    ------
    InputError
        Naming ``field``: no ``error`` or no ``failures`` column (the table cannot say which rows are usable).
    """
    from cams.sweep.output import FLAGS, failed  # the package's __init__ imports this module: no cycle at import

    for need in ("error", "failures"):
        if need not in columns:
            raise InputError(field, f"{name} has no {need!r} column: a sweep's table has one, and the front keeps "
                             "only the rows without error and failures")
    keys = [k for k in ("error", "failures", *FLAGS) if k in columns]
    rows = zip(*(columns[k] for k in keys), strict=True)
    return np.array([not failed(dict(zip(keys, r, strict=True))) for r in rows], dtype=bool)


@dataclass(frozen=True)
class Front:
    """The Pareto front of a table's rows.

    Attributes
    ----------
    objectives : tuple of Objective
        The objectives, as resolved (columns named as in the table).
    rows : ndarray of int
        Indices (0-based positions in the table) of the rows on the front, sorted by the first objective
        (best first), then the next ones.
    unusable : int
        Rows left out as not usable (:func:`usable_mask`).
    empty : int
        Usable rows left out for an empty (or not finite) objective.
    compared : int
        Rows compared (the rest).
    ties : tuple of tuple of int
        Groups of front rows with equal objective values (each group on the front together).
    """

    objectives: tuple[Objective, ...]
    rows: np.ndarray
    unusable: int
    empty: int
    compared: int
    ties: tuple[tuple[int, ...], ...]


def pareto_front(
    columns: Mapping[str, Sequence], objectives: Sequence[Objective], *, usable: np.ndarray | None = None
) -> Front:
    """The front of a table given as columns (name -> values), over ``objectives`` named as its columns.

    Parameters
    ----------
    columns : mapping of str to sequence
        The table's columns, all of one length; the objectives' columns numeric (None or NaN: empty).
    objectives : sequence of Objective
        Their ``column`` is a key of ``columns``.
    usable : array of bool, optional
        Which rows may be compared; default: :func:`usable_mask` of ``columns`` (a table without ``error`` and
        ``failures`` columns is refused then: give ``usable`` to compare rows that are not a sweep's).

    Raises
    ------
    InputError
        Naming ``--pareto``: an objective that is not a column, or whose values are not numbers; a table
        without ``error`` or ``failures`` column and no ``usable``.
    """
    names = list(columns)
    n = len(columns[names[0]]) if names else 0
    vals = []
    for o in objectives:
        if o.column not in columns:
            raise InputError("--pareto", f"{o.column!r} is not a column; the columns are: {', '.join(names)}")
        try:
            cells = columns[o.column]
            vals.append(np.array([np.nan if v is None or (isinstance(v, str) and not v) else v for v in cells], float))
        except (TypeError, ValueError):
            raise InputError("--pareto", f"{o.column!r} is not a column of numbers") from None
    usable = usable_mask(columns) if usable is None else np.asarray(usable, dtype=bool)
    p = np.column_stack(vals) if vals else np.zeros((n, 0))
    finite = np.all(np.isfinite(p), axis=1)
    cand = np.flatnonzero(usable & finite)
    on = non_dominated(p[cand], [o.maximise for o in objectives])
    front = cand[on]
    signed = np.where([o.maximise for o in objectives], -p[front], p[front])
    order = np.lexsort(signed.T[::-1]) if len(front) else np.zeros(0, dtype=int)
    front = front[order]
    groups: dict[tuple[float, ...], list[int]] = {}
    for i in front:
        groups.setdefault(tuple(p[i]), []).append(int(i))
    ties = tuple(tuple(g) for g in groups.values() if len(g) > 1)
    return Front(
        objectives=tuple(objectives),
        rows=front,
        unusable=int(np.sum(~usable)),
        empty=int(np.sum(usable & ~finite)),
        compared=len(cand),
        ties=ties,
    )
