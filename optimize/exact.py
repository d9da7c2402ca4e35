"""The exact solver: every cam angle of a constrained phase, not samples.

An exchange (cutting-plane) method for the semi-infinite convex problem
``min |O - T|`` over the continuous zone, in two stages on the design's
:class:`optimize.zone.ZoneTable`:

1. the zone sampled at the table's scan positions: starting from the target
   point T, each side's most violated scan position is added as a half-plane
   and the finite problem is solved exactly (:func:`optimize.planar.nearest_point`)
   until no scan position is violated; each step costs a matrix product;
2. the continuum: the local maxima of every constraint's signed distance over
   every cam angle (:func:`optimize.zone.scan_peaks`: the scan, then Newton
   steps on the continuous laws) that are violated are added, until none is
   violated by more than ``tol * scale``. The last scan is the verification.

The finite optimum is a lower bound of the true optimum;
:func:`optimize.bounds.push_inside` gives a feasible point and so an upper
bound, their gap is the stated error bound.
"""

from __future__ import annotations

import numpy as np

from cams.design import CamDesign
from laws.errors import InfeasibleError
from optimize.bounds import push_inside
from optimize.planar import nearest_point
from optimize.result import Binding, CentreSolution
from optimize.zone import scan_peaks, zone_table

__all__ = ["nearest_exact"]


def nearest_exact(
    design: CamDesign,
    target: np.ndarray,
    *,
    extra: tuple[np.ndarray, np.ndarray] | None = None,
    tol: float = 1e-12,
    max_iter: int = 100,
) -> CentreSolution:
    """Admissible centre nearest to ``target`` over the continuous zone.

    Parameters
    ----------
    design : CamDesign
    target : array_like, shape (2,)
        The roller centre at the near dwell (minimum R0) or the rocker pivot
        (minimum L), fixed frame.
    extra : (N, c), optional
        Additional half-planes ``N O <= c`` (e.g. a fixed offset as two).
    tol : float
        Allowed violation relative to the design's scale; values below 1e-13
        are raised to it (round-off of the planar solves).

    Raises
    ------
    InfeasibleError
        When the zone (with ``extra``) is empty.
    """
    scale = design.scale
    T = np.asarray(target, dtype=float)
    N = np.zeros((0, 2)) if extra is None else np.asarray(extra[0], float)
    c = np.zeros(0) if extra is None else np.asarray(extra[1], float)
    atol = max(tol, 1e-13) * scale
    feas_tol = max(1e-3 * atol, 1e-14 * scale)  # above the round-off of line crossings
    O = T
    if len(N):
        first = nearest_point(T, N, c, atol)
        if first is None:
            raise InfeasibleError("follower.offset", "the fixed constraints have no common point")
        O = first[0]
    t = zone_table(design)
    it = 0

    def add(normals, offsets):
        nonlocal N, c, O, it
        it += 1
        if it > max_iter:
            raise InfeasibleError("solve", f"the exact method did not converge in {max_iter} iterations")
        N = np.vstack([N, normals])
        c = np.concatenate([c, offsets])
        # the crossing of two nearly parallel lines far out carries round-off above feas_tol: retry with
        # a tolerance still well below atol (the verification scan judges the result)
        res = nearest_point(T, N, c, feas_tol) or nearest_point(T, N, c, 0.1 * atol)
        if res is None:
            raise InfeasibleError("limits.pressure_angle", "no cam centre satisfies the pressure-angle limits")
        O = res[0]

    if not t.phases:
        return CentreSolution(centre=O, objective=float(np.linalg.norm(O - T)), method="exact", samples=None,
                              error_bound=0.0, violation=-np.inf, iterations=0)
    # 1. the zone sampled at the scan positions: each side's worst position
    rows = np.arange(2 * len(t.phases))
    nx, ny, off = (a.reshape(len(rows), -1) for a in (t.nx, t.ny, t.off))
    while True:
        g = t.grid_violation(O).reshape(len(rows), -1)
        worst = np.argmax(g, axis=1)
        bad = g[rows, worst] > atol
        if not np.any(bad):
            break
        r, q = rows[bad], worst[bad]
        add(np.stack([nx[r, q], ny[r, q]], axis=1), off[r, q])
    # 2. the continuum: the violated local maxima of every side
    while True:
        pk = scan_peaks(t, O)
        v = float(np.max(pk.value))
        if v <= atol:
            break
        bad = pk.value > atol
        add(np.stack([pk.nx[bad], pk.ny[bad]], axis=1), pk.offset[bad])
    feasible = push_inside(design, O, v)
    obj = float(np.linalg.norm(O - T))
    if feasible is None:
        bound = None
    else:
        bound = float(abs(np.linalg.norm(feasible - T) - obj) + 4 * np.finfo(float).eps * (obj + scale))
    prog = design.program
    near = np.nonzero(pk.value >= -1e-9 * scale)[0]
    near = near[np.argsort(-pk.value[near], kind="stable")]
    binding = tuple(
        Binding(t.phases[pk.j[q]], float(prog.starts[t.phases[pk.j[q]]] + pk.u[q] * t.angle[pk.j[q]]),
                int(pk.side[q]))
        for q in near
    )
    return CentreSolution(
        centre=O, objective=obj, method="exact", samples=None, binding=binding,
        error_bound=bound, violation=v, iterations=it,
    )
