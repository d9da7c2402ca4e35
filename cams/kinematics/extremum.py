"""The one extremum search of the product: largest values of sampled functions, refined, batched.

A grid of positions, then every bracket of a local maximum refined on the
functions' analytic slopes, all brackets of all functions together (one array
evaluation a step). The profile checks (curvature, pressure angle), the cam's
smallest radius and the follower's jump speed use it; the independent check
(:mod:`cams.verify.pressure`) and the solvers keep their own searches by design.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from laws.program import Program

__all__ = ["maximize", "phase_positions", "MAX_STEPS", "U_TOL"]

#: Largest number of refinement steps (one array evaluation each) of :func:`maximize`.
MAX_STEPS = 60
#: Width of a bracket (in the positions' unit: normalized position ``u``) at which its refinement stops.
U_TOL = 1e-12


def phase_positions(program: Program, i: int, grid: int) -> np.ndarray:
    """Normalized positions ``u`` in [0, 1] at which phase ``i`` is searched.

    ``grid + 1`` even positions, and both sides of each breakpoint of the
    phase's law: a piecewise law's derivatives may jump there, and with the
    positions one rounding step either side of it each piece is smooth between
    neighbouring positions and its one-sided ends are on the grid. A dwell's
    kinematics are constant (the follower rests): its two ends only.

    Parameters
    ----------
    program : laws.program.Program
    i : int
        Phase index.
    grid : int
        Even steps of a rise or return.

    Returns
    -------
    ndarray, shape (m,)
        Increasing positions, 0 and 1 included.

    Examples
    --------
    >>> from laws.program import Phase, Program
    >>> prog = Program((Phase("rise", np.pi, "cycloidal"), Phase("dwell", 0.5 * np.pi),
    ...                 Phase("return", 0.5 * np.pi, "cycloidal")), 10.0)
    >>> len(phase_positions(prog, 0, 4)), phase_positions(prog, 1, 4).tolist()
    (5, [0.0, 1.0])
    """
    p = program.phases[i]
    if p.kind == "dwell":
        return np.array([0.0, 1.0])
    u = np.linspace(0.0, 1.0, grid + 1)
    bps = np.asarray(getattr(p.law, "breakpoints", ()), dtype=float)
    bps = bps[(bps > 0) & (bps < 1)]
    if len(bps) == 0:
        return u
    return np.unique(np.concatenate([u, bps, np.nextafter(bps, 0.0), np.nextafter(bps, 1.0)]))


def maximize(
    fun: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]],
    u: np.ndarray,
    *,
    refine: bool = True,
    tol: float = U_TOL,
) -> tuple[np.ndarray, np.ndarray]:
    """Largest values of ``q`` smooth functions over sorted positions, refined between them.

    Parameters
    ----------
    fun : callable
        ``fun(x) -> (values, slopes)``, arrays of shape ``(q, len(x))``: the
        functions at positions ``x`` and their derivatives (any positive
        multiple of ``d/dx``).
    u : ndarray, shape (n,)
        Increasing positions covering the interval; the functions are smooth
        between neighbouring positions.
    refine : bool
        Refine the local maxima between positions (else the grid's best).
    tol : float
        Width of a bracket at which its refinement stops (the positions' unit).

    Returns
    -------
    best, at : ndarray, shape (q,)
        Largest value of each function and its position.

    Notes
    -----
    Every pair of neighbouring positions where a function's slope turns from
    positive to non-positive brackets a local maximum. All brackets of all
    functions are refined together: each step evaluates ``fun`` once, at the
    regula-falsi point on the slopes of every open bracket (the Illinois
    variant: the slope of an end kept twice in a row is halved, so both ends
    converge), at least ``tol / 2`` inside it, and keeps the part where the
    slope changes sign. A bracket closes at width ``tol`` (or where the
    slope is 0); there are at most :data:`MAX_STEPS` steps. The best value
    evaluated in a bracket replaces the grid's best if it is larger. A
    minimum is the maximum of the negated function.

    Examples
    --------
    The largest value of ``sin x`` on [0, 3] is 1, at pi/2:

    >>> best, at = maximize(lambda x: (np.sin(x)[None], np.cos(x)[None]), np.linspace(0.0, 3.0, 7))
    >>> round(float(best[0]), 15), round(float(at[0]), 10)
    (1.0, 1.5707963268)
    """
    v, dv = fun(u)
    rows = np.arange(len(v))
    k = np.nanargmax(v, axis=1)
    best, at = v[rows, k], u[k]
    if not refine:
        return best, at
    row, j = np.nonzero((dv[:, :-1] > 0) & (dv[:, 1:] <= 0))
    a, b = u[j], u[j + 1]
    fa, fb = dv[row, j], dv[row, j + 1]
    a = np.where(fb == 0, b, a)  # the slope vanishes at the right end: that is the maximum
    top, top_u = np.full(len(j), -np.inf), a.copy()
    kept = np.zeros(len(j), dtype=int)  # +1: a moved last, -1: b moved last
    for _ in range(MAX_STEPS):
        act = np.nonzero(b - a > tol)[0]
        if len(act) == 0:
            break
        A, B, FA, FB = a[act], b[act], fa[act], fb[act]
        x = B - FB * (B - A) / (FB - FA)  # FA > 0 > FB
        # at least tol / 2 inside: a root within that of an end closes the bracket next step
        x = np.clip(np.where(np.isfinite(x), x, 0.5 * (A + B)), A + tol / 2, B - tol / 2)
        vx, dx = fun(x)
        n = np.arange(len(act))
        vx, dx = vx[row[act], n], dx[row[act], n]
        better = vx > top[act]
        top[act[better]], top_u[act[better]] = vx[better], x[better]
        up, down = dx > 0, dx < 0
        ia, ib, done = act[up], act[down], act[~(up | down)]  # slope 0 (or not a number): stop there
        fb[ia[kept[ia] == 1]] *= 0.5
        fa[ib[kept[ib] == -1]] *= 0.5
        a[ia], fa[ia], kept[ia] = x[up], dx[up], 1
        b[ib], fb[ib], kept[ib] = x[down], dx[down], -1
        a[done] = b[done] = x[~(up | down)]
    for q in rows:
        mine = np.nonzero(row == q)[0]
        if len(mine) and top[mine].max() > best[q]:
            w = mine[np.argmax(top[mine])]
            best[q], at[q] = top[w], top_u[w]
    return best, at
