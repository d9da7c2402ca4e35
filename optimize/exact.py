"""The exact solver: every cam angle of a constrained phase, not samples.

An exchange (cutting-plane) method for the semi-infinite convex problem
``min |O - T|`` over the continuous zone: starting from the target point T,
the local maxima of every constraint's signed distance over the continuum
(:func:`optimize.zone.max_violation`, root finding on the envelope's stationary
points by golden-section search) are added as half-planes, the finite problem
is solved exactly (:func:`optimize.planar.nearest_point`), and the loop stops
when no position is violated by more than ``tol * scale``. The finite optimum
is a lower bound of the true optimum; :func:`optimize.bounds.push_inside` gives
a feasible point and so an upper bound, their gap is the stated error bound.
"""

from __future__ import annotations

import numpy as np

from cams.design import CamDesign
from laws.errors import InfeasibleError
from optimize.bounds import push_inside
from optimize.planar import nearest_point
from optimize.result import Binding, CentreSolution
from optimize.zone import max_violation, wedges

__all__ = ["nearest_exact", "COARSE_GRID", "FINE_GRID"]

#: Positions per phase of the violation scan while iterating, and of the final verification.
COARSE_GRID, FINE_GRID = 48, 384


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
    peaks = []
    grid = COARSE_GRID
    for it in range(1, max_iter + 1):
        peaks = max_violation(design, O, grid=grid)
        v = peaks[0].value
        if v <= atol:
            if grid == FINE_GRID:
                break
            # converged on the coarse scan: verify on a fine one (narrow peaks)
            grid = FINE_GRID
            peaks = max_violation(design, O, grid=grid)
            v = peaks[0].value
            if v <= atol:
                break
        new = [p for p in peaks if p.value > atol]
        pos: dict[int, list[tuple[float, int]]] = {}
        for p in new:
            pos.setdefault(p.phase, []).append((p.u, p.side))
        w = wedges(design, {i: np.array([u for u, _ in us]) for i, us in pos.items()})
        sides = np.array([k for us in pos.values() for _, k in us])
        N = np.vstack([N, w.normals[np.arange(len(w)), sides]])
        c = np.concatenate([c, w.offsets[np.arange(len(w)), sides]])
        res = nearest_point(T, N, c, feas_tol)
        if res is None:
            raise InfeasibleError("limits.pressure_angle", "no cam centre satisfies the pressure-angle limits")
        O = res[0]
    else:
        raise InfeasibleError("solve", f"the exact method did not converge in {max_iter} iterations")
    v = peaks[0].value
    feasible = push_inside(design, O, v)
    obj = float(np.linalg.norm(O - T))
    if feasible is None:
        bound = None
    else:
        bound = float(abs(np.linalg.norm(feasible - T) - obj) + 4 * np.finfo(float).eps * (obj + scale))
    prog = design.program
    binding = tuple(
        Binding(p.phase, float(prog.starts[p.phase] + p.u * prog.phases[p.phase].angle), p.side)
        for p in peaks
        if p.value >= -1e-9 * scale
    )
    return CentreSolution(
        centre=O, objective=obj, method="exact", samples=None, binding=binding,
        error_bound=bound, violation=float(v), iterations=it,
    )
