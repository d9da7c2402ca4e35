"""Certified bounds for sampled or iterated solutions of the continuous problem.

A centre found from finitely many positions may sit slightly outside the true
(continuous) zone by the largest violation ``v`` over the continuum. Moving it
towards a strictly interior point ``c`` (slack ``r > 0`` everywhere) by the
fraction ``v / (v + r)`` makes it feasible, because each constraint is affine in
the centre. The objective at that feasible point is an upper bound on the true
optimum; the sampled optimum itself is a lower bound (fewer constraints).
"""

from __future__ import annotations

import numpy as np

from cams.design import CamDesign
from optimize.zone import max_violation, phase_wedges

__all__ = ["interior_point", "push_inside"]


def _recession_direction(design: CamDesign, grid: int = 64) -> tuple[np.ndarray, float] | None:
    """A direction inside every wedge's cone, and its angular margin (radians)."""
    axes, lims = [], []
    u = np.linspace(0.0, 1.0, grid + 1)
    for i, lim in design.constrained_phases():
        w = phase_wedges(design, i, lim, u)
        # axis of the wedge = bisector of the two inward directions: -(n_t + n_t1)
        a = -(w.normals[:, 0] + w.normals[:, 1])
        axes.append(np.arctan2(a[:, 1], a[:, 0]))
        lims.append(w.limit)
    ang = np.concatenate(axes)
    lim = np.concatenate(lims)
    ang = ang[0] + np.angle(np.exp(1j * (ang - ang[0])))
    lo, hi = np.max(ang - lim), np.min(ang + lim)
    if hi <= lo:
        return None
    mid = 0.5 * (lo + hi)
    return np.array([np.cos(mid), np.sin(mid)]), 0.5 * (hi - lo)


def interior_point(design: CamDesign, near: np.ndarray) -> tuple[np.ndarray, float] | None:
    """A point with positive slack in every position, and that slack (length).

    Tries ``near`` moved along a direction of the zone's recession cone, then
    the Chebyshev centre of a sampled zone. ``None`` if neither is interior.
    """
    scale = design.scale
    rd = _recession_direction(design)
    if rd is not None:
        d, _ = rd
        for c in (near + scale * d, near + 0.1 * scale * d):
            slack = -max_violation(design, c)[0].value
            if slack > 0:
                return c, slack
    cands = []
    try:
        from scipy.optimize import linprog

        from optimize.zone import sample_wedges

        N, c = sample_wedges(design, 128).lines()
        # maximize r: N x + r <= c, 0 <= r <= scale
        res = linprog(
            np.array([0.0, 0.0, -1.0]),
            A_ub=np.hstack([N, np.ones((len(N), 1))]),
            b_ub=c,
            bounds=[(None, None), (None, None), (0, scale)],
            method="highs",
        )
        if res.status == 0 and res.x[2] > 0:
            cands.append(res.x[:2])
    except Exception:  # pragma: no cover - linprog failure only loses a candidate
        pass
    best = None
    for c in cands:
        peaks = max_violation(design, c)
        slack = -peaks[0].value
        if slack > 0 and (best is None or slack > best[1]):
            best = (c, slack)
    return best


def push_inside(design: CamDesign, centre: np.ndarray, violation: float) -> np.ndarray | None:
    """A feasible centre near ``centre`` whose largest violation is ``violation``.

    Returns ``centre`` itself when ``violation <= 0``, ``None`` when no interior
    point could be found.
    """
    centre = np.asarray(centre, dtype=float)
    if violation <= 0:
        return centre
    ip = interior_point(design, centre)
    if ip is None:
        return None
    c, r = ip
    lam = violation / (violation + r)
    return centre + lam * (c - centre)
