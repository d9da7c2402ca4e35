"""Pressure angle of a finished design, by kinematic inversion.

This is the independent check of every solver: it does not use the zone's
wedges or the instant point D. The roller centre's path on the cam (the pitch
curve) is ``P(phi) = R(-eps phi) (A(phi) - O)``; its tangent is the relative
velocity ``W = dA/dphi - eps k x (A - O)`` turned into the cam frame, its
outward normal ``n = R(eps 90 deg) W / |W|`` (the curve runs round the cam
centre in the sense ``-eps``). The pressure angle is the angle between the
force the driving side exerts on the roller and the roller centre's velocity:
``n`` on a rise, ``-n`` on a return, which both reduce to
``gamma = arccos(n . e)`` with ``e`` the unit direction of the rise. Values
above 90 degrees mean the cam would pull, not push (the wrong branch).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.design import CamDesign

__all__ = ["pressure_angle", "contact_normal", "PressureReport", "check_pressure"]


def contact_normal(design: CamDesign, centre: np.ndarray, s: np.ndarray, ds: np.ndarray):
    """Outward contact normal, rise direction and cam-centre-to-roller vector (fixed frame).

    The one place of the inversion formula (used by :func:`pressure_angle` and
    :mod:`cams.camforces`).

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre O in the follower's fixed frame, length unit.
    s, ds : ndarray
        Displacement (rad or length) and its derivative per radian of cam angle.

    Returns
    -------
    n, e, r : ndarray, shape s.shape + (2,)
        Unit outward normal of the pitch curve (NaN where the roller centre sits
        on the cam centre with no relative motion: undefined), unit direction of
        the rise, and ``A - O`` (length unit). ``cos(gamma) = n . e``.
    """
    f = design.follower
    O = np.asarray(centre, dtype=float)
    A = f.position(s)
    T = f.tangent(s)
    V = np.asarray(ds)[..., None] * T
    r = A - O
    eps = design.cam_sense
    W = V - eps * np.stack([-r[..., 1], r[..., 0]], axis=-1)
    # outward normal: W turned by eps * 90 degrees
    n = eps * np.stack([-W[..., 1], W[..., 0]], axis=-1)
    norm = np.linalg.norm(n, axis=-1, keepdims=True)
    defined = norm > 1e-12 * design.scale
    n = np.where(defined, n / np.where(defined, norm, 1.0), np.nan)
    e = T / np.linalg.norm(T, axis=-1, keepdims=True)
    return n, e, r


def pressure_angle(design: CamDesign, centre: np.ndarray, phase: int, u: np.ndarray) -> np.ndarray:
    """Pressure angle (radians, in [0, pi]) inside ``phase`` at normalized ``u``.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre O in the follower's fixed frame.
    phase : int
        Index of a rise or return phase.
    u : array_like
        Normalized positions in [0, 1] (one-sided at the phase ends).

    Returns
    -------
    ndarray
        Radians; NaN where undefined (see :func:`contact_normal`), which the
        maxima below skip.
    """
    m = design.program.evaluate_phase(phase, np.asarray(u, dtype=float))
    n, e, _ = contact_normal(design, centre, m.s, m.ds)
    return np.arccos(np.clip(np.sum(n * e, axis=-1), -1.0, 1.0))


@dataclass(frozen=True)
class PressureReport:
    """Largest pressure angles over the rise and return phases.

    Angles in radians; ``None`` where the program has no such phase.
    ``where_*`` is the cam angle (radians) of the maximum.
    """

    rise: float | None
    rise_at: float | None
    ret: float | None
    ret_at: float | None
    rise_limit: float
    return_limit: float | None
    ok: bool


def _phase_max(design: CamDesign, centre, i: int, grid: int) -> tuple[float, float]:
    u = np.linspace(0.0, 1.0, grid + 1)
    g = pressure_angle(design, centre, i, u)
    if np.all(np.isnan(g)):
        return float("nan"), float(design.program.starts[i])
    k = int(np.nanargmax(g))
    best_u, best = u[k], g[k]
    lo, hi = u[max(k - 1, 0)], u[min(k + 1, grid)]
    # zoom in on the bracket: 21 points a step, the bracket shrinks tenfold each time
    for _ in range(6):
        x = np.linspace(lo, hi, 21)
        gx = np.nan_to_num(pressure_angle(design, centre, i, x), nan=-1.0)
        j = int(np.argmax(gx))
        if gx[j] > best:
            best_u, best = float(x[j]), float(gx[j])
        lo, hi = x[max(j - 1, 0)], x[min(j + 1, 20)]
    phi = design.program.starts[i] + best_u * design.program.phases[i].angle
    return float(best), float(phi)


def check_pressure(design: CamDesign, centre: np.ndarray, *, grid: int = 2000, tol: float = 1e-7) -> PressureReport:
    """Pressure angle over the whole cycle for the centre ``centre``.

    Every rise and return phase is sampled on ``grid + 1`` positions and the
    largest value refined by zooming into its bracket (tenfold a step). ``ok`` is True when the
    constrained phases stay within their limits plus ``tol`` radians.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre O in the follower's fixed frame (:mod:`cams.follower`),
        length unit.
    grid : int, optional
        Steps per phase of the first scan.
    tol : float, optional
        Allowed excess over the limits, radians.

    Returns
    -------
    PressureReport
        The largest pressure angle over all rise phases and over all return
        phases (radians, in [0, pi]; above pi/2 the cam would pull) and the
        cam angles where they occur (radians from the start of the cycle);
        None where the program has no such phase or the angle is undefined
        throughout. The return is checked against its limit only for form
        closure (``return_limit`` is None otherwise).
    """
    rise = ret = None
    rise_at = ret_at = None
    for i, p in enumerate(design.program.phases):
        if p.kind == "dwell":
            continue
        g, at = _phase_max(design, centre, i, grid)
        if np.isnan(g):
            continue
        if p.kind == "rise" and (rise is None or g > rise):
            rise, rise_at = g, at
        if p.kind == "return" and (ret is None or g > ret):
            ret, ret_at = g, at
    lim = design.limits
    ok = rise is None or rise <= lim.pressure_angle + tol
    if lim.closure == "form" and ret is not None:
        ok = ok and ret <= lim.return_limit + tol
    return PressureReport(rise, rise_at, ret, ret_at, lim.pressure_angle,
                          lim.return_limit if lim.closure == "form" else None, bool(ok))
