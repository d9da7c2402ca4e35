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

from cams.model.design import CamDesign
from laws.errors import InputError, show_value

__all__ = ["pressure_angle", "contact_normal", "PressureReport", "check_pressure", "check_pressure_many"]


def contact_normal(design: CamDesign, centre: np.ndarray, s: np.ndarray, ds: np.ndarray):
    """Outward contact normal, rise direction and cam-centre-to-roller vector (fixed frame).

    The one place of the inversion formula (used by :func:`pressure_angle` and
    :mod:`cams.dynamics.forces`).

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
    # |n| = |W| is of the size of |A - O| and of the follower's motion (both scale with the unit); it is
    # near 0 only at the degenerate A = O, so a fraction of the follower's size cannot mislabel a defined normal
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


#: Points of every bracket at each zoom step (the bracket shrinks to two of
#: its ``ZOOM_POINTS - 1`` intervals: tenfold).
ZOOM_POINTS = 21
#: Zoom steps: the bracket, two sampling steps wide, ends 1e-10 times as wide.
ZOOM_STEPS = 10
#: Sampled positions (centres times positions) evaluated at once.
CHUNK = 200_000


def _angles(design: CamDesign, i: int, centres: np.ndarray, u: np.ndarray) -> np.ndarray:
    """Pressure angle (radians) in phase ``i``; -1 where undefined (below every angle).

    ``centres`` has shape ``u.shape + (2,)`` (one centre per position) or
    broadcasts to it.
    """
    m = design.program.evaluate_phase(i, u.ravel())
    n, e, _ = contact_normal(design, centres, m.s.reshape(u.shape), m.ds.reshape(u.shape))
    g = np.arccos(np.clip(np.sum(n * e, axis=-1), -1.0, 1.0))
    return np.nan_to_num(g, nan=-1.0)


def _phase_max(design: CamDesign, centres: np.ndarray, i: int, grid: int) -> tuple[np.ndarray, np.ndarray]:
    """Largest pressure angle in phase ``i`` for each of the centres (shape (k, 2)), and its normalized position.

    Every local maximum of the sampled angle (the phase ends included: the
    angle may jump at a join between phases, where each side is its own
    one-sided limit) is refined, all at once, by zooming into its bracket of
    two sampling steps; the largest refined value wins. Refining only the
    highest sample would miss a second peak that the sampling lowered.

    Returns
    -------
    g, u : ndarray, shape (k,)
        Radians (-1 where the angle is undefined throughout) and positions in [0, 1].
    """
    u = np.linspace(0.0, 1.0, grid + 1)
    g = _angles(design, i, centres[:, None, :], np.broadcast_to(u, (len(centres), grid + 1)))
    low = np.full((len(centres), 1), -np.inf)
    left, right = np.hstack([low, g[:, :-1]]), np.hstack([g[:, 1:], low])
    c, k = np.nonzero((g >= left) & (g >= right) & (g >= 0.0))
    best_g, best_u = g[c, k], u[k]
    lo, hi = u[np.maximum(k - 1, 0)], u[np.minimum(k + 1, grid)]
    t = np.linspace(0.0, 1.0, ZOOM_POINTS)
    rows = np.arange(len(c))
    for _ in range(ZOOM_STEPS):
        x = lo[:, None] + (hi - lo)[:, None] * t
        gx = _angles(design, i, centres[c][:, None, :], x)
        j = np.argmax(gx, axis=1)
        better = gx[rows, j] > best_g
        best_g = np.where(better, gx[rows, j], best_g)
        best_u = np.where(better, x[rows, j], best_u)
        lo, hi = x[rows, np.maximum(j - 1, 0)], x[rows, np.minimum(j + 1, ZOOM_POINTS - 1)]
    # the best peak of each centre: sort by (centre, value), keep the last of each centre
    out_g, out_u = np.full(len(centres), -1.0), np.zeros(len(centres))
    order = np.lexsort((best_g, c))
    out_g[c[order]], out_u[c[order]] = best_g[order], best_u[order]
    return out_g, out_u


def _as_centres(centres) -> np.ndarray:
    """Centres as a finite float array of shape (k, 2), else :class:`InputError`."""
    try:
        C = np.asarray(centres, dtype=float)
    except (TypeError, ValueError):
        raise InputError("centre", f"must be numbers [x, y] or an array of shape (k, 2), "
                                   f"got a {type(centres).__name__} that is not") from None
    if C.ndim not in (1, 2) or C.shape[-1] != 2:
        raise InputError("centre", f"must be [x, y] or an array of shape (k, 2), got shape {C.shape}")
    if not np.all(np.isfinite(C)):
        raise InputError("centre", "must be finite numbers, got infinity or NaN")
    return C.reshape(-1, 2)


def check_pressure_many(design: CamDesign, centres: np.ndarray, *, grid: int = 2000,
                        tol: float = 1e-7) -> list[PressureReport]:
    """:func:`check_pressure` for many centres at once, vectorized.

    Parameters
    ----------
    design : CamDesign
    centres : array_like, shape (k, 2) or (2,)
        Cam centres O in the follower's fixed frame (:mod:`cams.model.follower`),
        length unit.
    grid, tol
        As in :func:`check_pressure`.

    Returns
    -------
    list of PressureReport
        One per centre, in order; each is ``check_pressure(design, centre)`` to
        rounding (the angles to a few units in the last place; the cam angle
        of a flat maximum to what its flatness allows).

    Raises
    ------
    InputError
        ``centres`` is not a finite array of shape (k, 2) or (2,), or ``grid`` is not a positive integer.
    """
    C = _as_centres(centres)
    if isinstance(grid, bool) or not isinstance(grid, (int, np.integer)) or grid < 1:
        raise InputError("grid", f"must be a positive integer, got {show_value(grid)}")
    k = len(C)
    prog = design.program
    rise, rise_at = np.full(k, np.nan), np.full(k, np.nan)
    ret, ret_at = np.full(k, np.nan), np.full(k, np.nan)
    block = max(1, CHUNK // (grid + 1))
    for i, p in enumerate(prog.phases):
        if p.kind == "dwell":
            continue
        g, u = np.concatenate([np.stack(_phase_max(design, C[a:a + block], i, grid), axis=1)
                               for a in range(0, k, block)] or [np.empty((0, 2))]).T
        g = np.where(g >= 0.0, g, np.nan)
        at = prog.starts[i] + u * p.angle
        worst, where = (rise, rise_at) if p.kind == "rise" else (ret, ret_at)
        higher = g > np.where(np.isnan(worst), -np.inf, worst)
        worst[higher], where[higher] = g[higher], at[higher]
    lim = design.limits
    form = lim.closure == "form"
    out = []
    for a in range(k):
        r = None if np.isnan(rise[a]) else float(rise[a])
        b = None if np.isnan(ret[a]) else float(ret[a])
        ok = r is None or r <= lim.pressure_angle + tol
        if form and b is not None:
            ok = ok and b <= lim.return_limit + tol
        out.append(PressureReport(r, None if r is None else float(rise_at[a]), b,
                                  None if b is None else float(ret_at[a]), lim.pressure_angle,
                                  lim.return_limit if form else None, bool(ok)))
    return out


def check_pressure(design: CamDesign, centre: np.ndarray, *, grid: int = 2000, tol: float = 1e-7) -> PressureReport:
    """Pressure angle over the whole cycle for the centre ``centre``.

    Every rise and return phase is sampled on ``grid + 1`` positions and every
    local maximum of the samples (phase ends included) refined by zooming
    into its bracket of two steps (tenfold a step, :data:`ZOOM_STEPS` steps);
    the largest wins. ``ok`` is True when the constrained phases stay within
    their limits plus ``tol`` radians. :func:`check_pressure_many` does the
    same for many centres at once.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre O in the follower's fixed frame (:mod:`cams.model.follower`),
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
    C = _as_centres(centre)
    if len(C) != 1:
        raise InputError("centre", f"must be one point [x, y], got shape {np.shape(centre)}")
    return check_pressure_many(design, C, grid=grid, tol=tol)[0]
