"""Certified bounds for sampled or iterated solutions of the continuous problem.

A centre found from finitely many positions may sit slightly outside the true
(continuous) zone by the largest violation ``v`` over the continuum. Each
constraint is affine in the centre, so it becomes feasible when moved

* along a direction ``d`` inside every wedge's cone with angular margin ``mu``
  (a recession direction of the zone): every signed distance falls by at least
  ``sin(mu)`` per unit length, so a step of ``v / sin(mu)`` is enough; or
* towards a strictly interior point ``c`` (slack ``r > 0`` everywhere) by the
  fraction ``v / (v + r)``, where the zone has no recession direction.

The objective at that feasible point is an upper bound on the true optimum;
the sampled optimum itself is a lower bound (fewer constraints).
"""

from __future__ import annotations

import numpy as np

from cams.model.design import CamDesign
from optimize.zone import GRID, max_violation, scan_peaks, zone_table

__all__ = ["interior_point", "push_inside", "recession_direction"]


def recession_direction(design: CamDesign, grid: int = GRID) -> tuple[np.ndarray, float] | None:
    """A direction inside every wedge's cone, and its angular margin (radians).

    From the wedges at the scan positions of :func:`optimize.zone.zone_table`;
    the margin is reduced by how far a wedge's axis can turn between two scan
    positions (it turns with the follower: ``turn s``), so it holds for every
    cam angle.

    Returns
    -------
    (direction, margin) or None
        A unit vector (fixed frame) and the margin, radians; None when the cones share no direction (or no phase
        is constrained): the zone may then be bounded.
    """
    t = zone_table(design, grid)
    if not t.phases:
        return None
    # axis of the wedge = bisector of the two inward directions: -(n_t + n_t1), turned by turn s
    n = t.n0[:, 0] + t.n0[:, 1]
    ang = (np.arctan2(-n[:, 1], -n[:, 0])[:, None] + t.turn * t.s[:, 0]).ravel()
    lim = np.repeat(t.limit, t.s.shape[-1])
    ang = ang[0] + np.mod(ang - ang[0] + np.pi, 2 * np.pi) - np.pi
    # between scan positions the axis turns by at most |turn s'| dphi, s' within |s''| dphi of the scan's
    dphi = np.max(np.diff(t.u)) * t.angle[:, None]
    w1 = np.max(np.abs(t.ds[:, 0]), axis=1, keepdims=True)
    w2 = np.max(np.abs(t.d2s[:, 0]), axis=1, keepdims=True)
    drift = abs(t.turn) * float(np.max((w1 + w2 * dphi) * dphi))
    lo, hi = np.max(ang - lim) + drift, np.min(ang + lim) - drift
    if hi <= lo:
        return None
    mid = 0.5 * (lo + hi)
    return np.array([np.cos(mid), np.sin(mid)]), 0.5 * (hi - lo)


def interior_point(design: CamDesign, near: np.ndarray) -> tuple[np.ndarray, float] | None:
    """A point with positive slack in every position, and that slack (length).

    Tries ``near`` moved along a direction of the zone's recession cone, then
    the Chebyshev centre of a sampled zone. ``None`` if neither is interior.

    Parameters
    ----------
    design : CamDesign
    near : ndarray, shape (2,)
        A cam centre to start from, the follower's fixed frame
        (:mod:`cams.model.follower`), length unit.

    Returns
    -------
    (ndarray, float) or None
        A cam centre (shape (2,), same frame) strictly inside the continuous
        zone, and its slack: the smallest distance to the zone's half-planes
        over the cycle (length unit, > 0). None when no interior point was
        found.
    """
    scale = design.scale
    rd = recession_direction(design)
    if rd is not None:
        d, _ = rd
        t = zone_table(design)
        for c in (near + scale * d, near + 0.1 * scale * d):
            slack = -float(np.max(scan_peaks(t, c).value))
            if slack > 0:
                return c, slack
    cands = []
    try:
        from scipy.optimize import linprog

        from optimize.zone import sample_wedges

        N, c = sample_wedges(design, 128).lines()
        # maximize r: N x + r <= c, 0 <= r <= scale (a cap on the slack sought, not a tolerance: any r > 0 will do)
        res = linprog(
            np.array([0.0, 0.0, -1.0]),
            A_ub=np.hstack([N, np.ones((len(N), 1))]),
            b_ub=c,
            bounds=[(None, None), (None, None), (0, scale)],
            method="highs",
        )
        if res.status == 0 and res.x is not None and res.x[2] > 0:
            cands.append(res.x[:2])
    except ValueError:  # pragma: no cover - linprog refusing non-finite rows, or the sampled zone's own refusal
        pass            # (InputError, InfeasibleError): only this candidate is lost
    best = None
    for c in cands:
        peaks = max_violation(design, c)
        slack = -peaks[0].value
        if slack > 0 and (best is None or slack > best[1]):
            best = (c, slack)
    return best


def push_inside(design: CamDesign, centre: np.ndarray, violation: float) -> np.ndarray | None:
    """A feasible centre near ``centre`` whose largest violation is ``violation``.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre, the follower's fixed frame (:mod:`cams.model.follower`), length unit.
    violation : float
        Largest signed distance of ``centre`` outside the continuous zone
        (length unit; e.g. ``max_violation(design, centre)[0].value``).

    Returns
    -------
    ndarray, shape (2,) or None
        ``centre`` itself when ``violation <= 0``; else ``centre`` moved by
        ``violation / sin(margin)`` along a recession direction of the zone,
        or towards an interior point by the fraction ``v / (v + r)`` (module
        notes); None when the zone has no recession direction and no interior
        point could be found.
    """
    centre = np.asarray(centre, dtype=float)
    if violation <= 0:
        return centre
    rd = recession_direction(design)
    if rd is not None:
        d, margin = rd
        return centre + (violation / np.sin(margin)) * d
    ip = interior_point(design, centre)
    if ip is None:
        return None
    c, r = ip
    lam = violation / (violation + r)
    return centre + lam * (c - centre)
