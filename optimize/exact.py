"""The exact solver: every cam angle of a constrained phase, not samples.

An exchange (cutting-plane) method for the semi-infinite convex problem
``min |O - T|`` over the continuous zone, in two stages on the design's
:class:`optimize.zone.ZoneTable`:

1. the zone sampled at the table's scan positions: starting from the target
   point T, each side's most violated scan position is added as a half-plane
   (a cut) and the finite problem is solved exactly
   (:class:`optimize.planar.NearestPoint`, which goes on from the last
   optimum) until no scan position is violated;
2. the continuum: the local maxima of every constraint's signed distance over
   every cam angle (:func:`optimize.zone.scan_peaks`: the scan, then Newton
   steps on the continuous laws) that are violated are added, until none is
   violated beyond the rounding of the numbers compared.

Every cut is a real constraint (the zone at one cam angle), so the finite
problem is a relaxation and its distance never decreases as cuts are added
(checked at every iteration: :class:`ExchangeInvariantError`).

The answer is certified by two bounds of the true optimum ``d*``:

* lower: the dual value of the finite problem at the nearest-point method's
  multipliers ``lam >= 0``, ``-|N^T lam|^2 / 2 + lam . (N T - c) <= d*^2 / 2``
  (weak duality; the rounding of the cuts is subtracted);
* upper: ``|F - T|`` for a centre F checked feasible over the continuum (no
  violation beyond the rounding of the numbers compared): the finite optimum
  itself, or else that optimum moved inside by
  :func:`optimize.bounds.push_inside` and scanned again.

The centre returned is F, its distance the objective, ``upper - lower`` the
error bound. A result is certified when that gap is within ``CERT_RTOL`` of
the objective (or the rounding of the coordinates); otherwise it is returned
with ``certified=False`` and the command line reports it as not certified.
"""

from __future__ import annotations

import numpy as np

from cams.model.design import CamDesign
from laws.errors import InfeasibleError, SolverError
from optimize.bounds import push_inside
from optimize.planar import EPS, NearestPoint
from optimize.result import Binding, CentreSolution
from optimize.zone import scan_peaks, zone_table

__all__ = ["nearest_exact", "ExchangeInvariantError", "CERT_RTOL"]

#: A result is certified when ``upper - lower <= CERT_RTOL * upper`` (or the coordinates' rounding).
CERT_RTOL = 1e-9


class ExchangeInvariantError(SolverError):
    """An internal invariant of the exchange method broke (the relaxation's distance decreased).

    A fault of the solver, not of the input (:class:`laws.errors.SolverError`).
    """

    def __init__(self, message: str):
        super().__init__(f"internal error of the exact method: {message}")


def _magnitude(*points: np.ndarray) -> float:
    """Sum of the coordinates' magnitudes: what the rounding of a signed distance is relative to."""
    return float(sum(np.abs(p).sum() for p in points))


def nearest_exact(
    design: CamDesign,
    target: np.ndarray,
    *,
    half_planes: tuple[np.ndarray, np.ndarray] | None = None,
    tol: float = 0.0,
    max_iter: int | None = None,
) -> CentreSolution:
    """Admissible centre nearest to ``target`` over the continuous zone.

    Parameters
    ----------
    design : CamDesign
    target : array_like, shape (2,)
        The roller centre at the near dwell (minimum R0) or the rocker pivot
        (minimum L), the follower's fixed frame (:mod:`cams.model.follower`),
        length unit.
    half_planes : (N, c), optional
        Additional half-planes ``N O <= c`` (e.g. a fixed offset as two).
    tol : float
        Allowed violation of a constraint relative to the magnitude of the
        numbers compared (``|offset| + 2 (|T| + |O - T|)``, 1-norms); values
        below the rounding ``optimize.planar.EPS`` are raised to it (the
        default).
    max_iter : int, optional
        Cap on the continuum stage's iterations; default ``100 + 10 P`` for
        P constrained phases. Reaching it does not fail: the result carries
        its bounds and is certified or not by them.

    Returns
    -------
    CentreSolution
        ``centre`` checked feasible, ``objective = |centre - target|``,
        ``lower_bound``, ``error_bound = objective - lower_bound``,
        ``certified``; ``violation`` is that of the finite optimum.

    Raises
    ------
    InfeasibleError
        When the zone (with ``half_planes``) is empty.
    ExchangeInvariantError
        When the relaxation's distance decreases between iterations (never
        in exact arithmetic; beyond rounding it is a fault).
    SolverError
        When the nearest-point method cannot settle on the cuts
        (:meth:`optimize.planar.NearestPoint.solve`; never in exact
        arithmetic): a fault of the solver, not of the input.
    """
    rel = max(float(tol), EPS)
    T = np.asarray(target, dtype=float)
    q = NearestPoint(T)
    if half_planes is not None and len(half_planes[0]):
        q.add(np.asarray(half_planes[0], float), np.asarray(half_planes[1], float))
        try:
            q.solve()
        except InfeasibleError:
            raise InfeasibleError("follower.offset", "the fixed constraints have no common point") from None
    t = zone_table(design)
    if not t.phases:
        O = q.x
        d = float(np.linalg.norm(O - T))
        return CentreSolution(centre=O, objective=d, method="exact", samples=None, error_bound=0.0,
                              violation=-np.inf, iterations=0, lower_bound=d, certified=True)
    cap = max_iter if max_iter is not None else 100 + 10 * len(t.phases)
    state = {"it": 0, "obj": float(np.linalg.norm(q.x - T))}

    def allowed(offsets: np.ndarray) -> np.ndarray:
        """Violation below which a cut is not added: rounding of the numbers compared."""
        return rel * (np.abs(offsets) + 2.0 * _magnitude(T, q.y))

    def add(normals: np.ndarray, offsets: np.ndarray) -> bool:
        """Add cuts, solve; False when the point did not move (nothing left to gain)."""
        state["it"] += 1
        before = q.x
        q.add(normals, offsets)
        q.solve()
        obj = float(np.linalg.norm(q.y))
        if obj < state["obj"] - EPS * (state["obj"] + _magnitude(T)):
            raise ExchangeInvariantError(f"the relaxation's distance fell from {state['obj']!r} to {obj!r} "
                                         f"at iteration {state['it']}")
        state["obj"] = max(state["obj"], obj)
        return not np.array_equal(before, q.x)

    # 1. the zone sampled at the scan positions: each side's worst position (each position is added
    # at most once: once a cut, it is satisfied within the same rounding)
    rows = np.arange(2 * len(t.phases))
    nx, ny, off = (a.reshape(len(rows), -1) for a in (t.nx, t.ny, t.off))
    for _ in range(nx.size + 1):
        g = t.grid_violation(q.x).reshape(len(rows), -1)
        worst = np.argmax(g, axis=1)
        bad = g[rows, worst] > allowed(off[rows, worst])
        if not np.any(bad):
            break
        r, k = rows[bad], worst[bad]
        if not add(np.stack([nx[r, k], ny[r, k]], axis=1), off[r, k]):
            break
    # 2. the continuum: the violated local maxima of every side
    pk, at = None, None
    for _ in range(cap):
        at = q.x
        pk = scan_peaks(t, at)
        bad = pk.value > allowed(pk.offset)
        if not np.any(bad):
            break
        if not add(np.stack([pk.nx[bad], pk.ny[bad]], axis=1), pk.offset[bad]):
            break
    O = q.x
    if pk is None or at is None or not np.array_equal(at, O):
        pk = scan_peaks(t, O)
    v = float(np.max(pk.value))
    obj = float(np.linalg.norm(O - T))
    # the bounds: lower from the multipliers (weak duality, cuts' rounding subtracted), upper from F
    lower = min(q.lower_bound(), obj)
    found = _feasible_point(design, t, O, pk, rel, T)
    if found is None:
        centre, upper, bound, certified = O, obj, None, False
    else:
        centre, upper = found
        upper *= 1.0 + 4 * EPS
        bound = upper - lower
        certified = bool(bound <= CERT_RTOL * upper + EPS * _magnitude(T, centre))
    prog = design.program
    # binding: within the rounding of the numbers compared (as for adding a cut), not a fraction of the
    # follower's size, which a cam 1e7 times larger than its follower exceeds
    near = np.nonzero(pk.value >= -allowed(pk.offset))[0]
    near = near[np.argsort(-pk.value[near], kind="stable")]
    binding = tuple(
        Binding(t.phases[pk.j[k]], float(prog.starts[t.phases[pk.j[k]]] + pk.u[k] * t.angle[pk.j[k]]),
                int(pk.side[k]))
        for k in near
    )
    return CentreSolution(
        centre=centre, objective=float(np.linalg.norm(centre - T)), method="exact", samples=None, binding=binding,
        error_bound=bound, violation=v, iterations=int(state["it"]), lower_bound=lower, certified=certified,
    )


def _feasible_point(design: CamDesign, t, O: np.ndarray, pk, rel: float, T: np.ndarray
                    ) -> tuple[np.ndarray, float] | None:
    """A centre checked feasible near ``O``, and the distance to ``T`` that bounds the optimum from above.

    ``pk`` is the continuum scan at ``O``. The centre is ``O`` itself when
    that scan finds no violation beyond the rounding of the numbers compared,
    else ``O`` moved inside by :func:`optimize.bounds.push_inside` and scanned
    again. A violation left within rounding still counts: the upper bound is
    the distance of the point pushed inside by it. None when no such point is
    found (then nothing is proven).
    """
    F = np.asarray(O, float)
    for k in range(4):
        if k:
            pk = scan_peaks(t, F)
        v = float(np.max(pk.value))
        slack = rel * (np.abs(pk.offset) + 2.0 * _magnitude(T, F - T))
        if np.all(pk.value <= slack):
            upper = float(np.linalg.norm(F - T))
            if v > 0:
                G = push_inside(design, F, v)
                if G is None:
                    return None
                upper = max(upper, float(np.linalg.norm(G - T)))
            return F, upper
        moved = push_inside(design, F, v)
        if moved is None:
            return None
        F = moved
    return None
