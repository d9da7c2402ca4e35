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

A rocker's safety factor K_C (seed 3.26) is checked from the same normal:
where it crosses the rocker line, and the seed's lines moved from there
(:mod:`cams.verify.safety`), not from the zone's instant point D.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from cams.model.design import CamDesign
from cams.model.follower import Rocker
from cams.verify.safety import safety_terms
from cams.words import phase_words
from laws.errors import InputError, show_value
from laws.units import turn_degrees

__all__ = ["pressure_angle", "contact_normal", "PressureReport", "SafetyReport", "check_pressure",
           "check_pressure_many", "Inverted", "invert", "grid_peaks", "zoom", "ZOOM_POINTS", "ZOOM_STEPS"]


def contact_normal(design: CamDesign, centre: np.ndarray, s: np.ndarray, ds: np.ndarray):
    """Outward contact normal, rise direction and cam-centre-to-roller vector (fixed frame).

    The inversion formula (:func:`invert`) for one design, as :func:`pressure_angle` and
    :mod:`cams.dynamics.forces` use it.

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
    O = np.asarray(centre, dtype=float)
    v = _inverted(design, O[..., 0], O[..., 1], s, ds)
    return np.stack([v.nx, v.ny], axis=-1), np.stack([v.ex, v.ey], axis=-1), np.stack([v.rx, v.ry], axis=-1)


def _inverted(design: CamDesign, ox, oy, s: np.ndarray, ds: np.ndarray) -> Inverted:
    """:func:`invert` for one design at the motion ``s, ds``: the follower's frame at ``s``; ``ox, oy`` (the
    centres' coordinates) broadcast with ``s`` and ``ds``."""
    A, T, _ = design.follower.frame(s)
    return invert(A[..., 0], A[..., 1], T[..., 0], T[..., 1], ox, oy, ds, design.cam_sense, 1e-12 * design.scale)


@dataclass(frozen=True)
class Inverted:
    """The kinematic inversion at positions (:func:`invert`): arrays of one broadcast shape, the fixed frame.

    Attributes
    ----------
    wx, wy : ndarray
        ``W = dA/dphi - eps k x (A - O)``, the roller centre's velocity relative to the cam, length per radian.
    w2, w : ndarray
        ``|W|^2`` and ``|W|``, length squared per radian squared and length per radian.
    nx, ny : ndarray
        The pitch curve's unit outward normal (``W`` turned by ``eps`` 90 degrees, over ``|W|``); NaN where
        ``|W|`` is not above the floor (the roller centre on the cam centre with no relative motion: undefined).
    ex, ey : ndarray
        The unit direction of the rise, ``T / |T|``.
    rx, ry : ndarray
        ``A - O``, length.
    """

    wx: np.ndarray
    wy: np.ndarray
    w2: np.ndarray
    w: np.ndarray
    nx: np.ndarray
    ny: np.ndarray
    ex: np.ndarray
    ey: np.ndarray
    rx: np.ndarray
    ry: np.ndarray

    @property
    def angle(self) -> np.ndarray:
        """The pressure angle ``arccos(n . e)``, radians in [0, pi]; NaN where the normal is undefined."""
        return np.arccos(np.clip(self.nx * self.ex + self.ny * self.ey, -1.0, 1.0))


def invert(ax, ay, tx, ty, ox, oy, ds, eps, floor) -> Inverted:
    """The one place of the inversion formula, on arrays: the relative velocity, the outward normal, the rise.

    Every argument is an array or a number, all broadcast together: positions of one design, or of many
    designs at once (each with its own centre, sense and floor). Every value is computed from its own
    position, centre, sense and floor alone, by the same operations whatever the shapes, so a value does not
    depend on the other designs, centres or positions evaluated with it.

    Parameters
    ----------
    ax, ay : array_like
        The roller centre A (fixed frame, length).
    tx, ty : array_like
        Its tangent ``T = dA/ds`` (length per unit of s: 1 for a translating follower, the arm for a rocker).
    ox, oy : array_like
        The cam centre O (fixed frame, length).
    ds : array_like
        The displacement's derivative per radian of cam angle (rad or length per radian).
    eps : array_like
        The cam's sense of rotation, +1 counter-clockwise, -1 clockwise.
    floor : array_like
        The ``|W|`` (length) at or below which the normal is undefined: a small fraction of the follower's
        size (``|W|`` is of the size of ``|A - O|`` and of the follower's motion, near 0 only at ``A = O``).

    Returns
    -------
    Inverted
    """
    rx, ry = ax - ox, ay - oy
    # W = dA/dphi - eps k x (A - O), the roller centre's velocity relative to the cam (per radian)
    wx = ds * tx + eps * ry
    wy = ds * ty - eps * rx
    # outward normal: W turned by eps * 90 degrees (the pitch curve runs round the cam centre in the sense -eps)
    nx, ny = -eps * wy, eps * wx
    w2 = wx * wx + wy * wy
    w = np.sqrt(w2)
    defined = w > floor
    if np.all(defined):  # the same values as below, without the masks
        nx, ny = nx / w, ny / w
    else:
        norm = np.where(defined, w, 1.0)
        nx, ny = np.where(defined, nx / norm, np.nan), np.where(defined, ny / norm, np.nan)
    t = np.sqrt(tx * tx + ty * ty)
    return Inverted(wx, wy, w2, w, nx, ny, tx / t, ty / t, rx, ry)


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
    O = np.asarray(centre, dtype=float)
    return _inverted(design, O[..., 0], O[..., 1], m.s, m.ds).angle


@dataclass(frozen=True)
class PressureReport:
    """Largest pressure angles over the rise and return phases, and the safety factor's zone.

    Angles in radians; ``None`` where the program has no such phase.
    ``rise_at``, ``ret_at`` are the cam angles (radians) of the maxima.
    ``safety`` is the check of the safety factor K_C (:class:`SafetyReport`),
    None where it does not apply (K_C = 1, a translating follower). ``ok``:
    every limit the design sets holds, K_C included.
    """

    rise: float | None
    rise_at: float | None
    ret: float | None
    ret_at: float | None
    rise_limit: float
    return_limit: float | None
    ok: bool
    safety: SafetyReport | None = None


@dataclass(frozen=True)
class SafetyReport:
    """The safety factor K_C (seed 3.26) at a rocker's cam centre: the moved lines of :mod:`cams.verify.safety`.

    Attributes
    ----------
    factor : float
        The K_C required (``limits.safety_factor``, above 1).
    met : float
        The largest K_C the centre meets over every constrained position (below 1 where it fails the
        pressure angle itself).
    outside : float
        The largest distance of the centre outside a moved line, over every constrained position, length
        unit (mm); <= 0 inside, by that much.
    at : float
        Cam angle of that line's position, radians from the start of the cycle.
    phase : int
        Its phase, the index into the program (of its ``[[motion]]`` table, from 0).
    kind : str
        That phase's kind, ``"rise"`` or ``"return"``.
    line : str
        Which of its two lines: ``"t-t"``, where the pressure angle signed positive in the cam's sense of
        rotation reaches +[γ], or ``"t1-t1"`` (-[γ]).
    excess : float
        The largest sine of the angle by which the direction from the centre to a moved line's pole exceeds
        the limit (the pressure angle's excess, were the poles not moved; negative inside), over every
        constrained position.
    ok : bool
        ``excess`` within the check's tolerance (radians, as the pressure angle's).
    """

    factor: float
    met: float
    outside: float
    at: float
    phase: int
    kind: str
    line: str
    excess: float
    ok: bool

    def failure(self) -> str | None:
        """The line a failed check prints: by how much (mm, and the K_C met) and where; None when it passes."""
        if self.ok:
            return None
        digits = 6  # as many as tell the K_C met from the one required
        while digits < 15 and f"{self.met:.{digits}g}" == f"{self.factor:.{digits}g}":
            digits += 1
        return (f"safety factor K_C = {self.factor:g} not met: the largest K_C the centre meets is "
                f"{self.met:.{digits}g}; "
                f"it lies {self.outside:.6g} mm outside the K_C zone's {self.line} line at cam angle "
                f"{turn_degrees(self.at):.4f} deg in {phase_words(self.kind, self.phase)}")

    def to_dict(self) -> dict:
        """JSON-ready: ``required``, ``met`` (None when not finite), ``outside`` (mm), ``at_deg``, ``phase``,
        ``line``, ``ok``."""
        return {"required": float(self.factor), "met": float(self.met) if np.isfinite(self.met) else None,
                "outside": float(self.outside),
                "at_deg": float(turn_degrees(self.at)), "phase": int(self.phase), "line": self.line,
                "ok": bool(self.ok)}


#: Points of every bracket at each zoom step (the bracket shrinks to two of
#: its ``ZOOM_POINTS - 1`` intervals: tenfold).
ZOOM_POINTS = 21
#: Zoom steps: the bracket, two sampling steps wide, ends 1e-10 times as wide.
ZOOM_STEPS = 10
#: Sampled positions (centres times positions) evaluated at once.
CHUNK = 200_000


def grid_peaks(g: np.ndarray, u: np.ndarray, keep: np.ndarray | bool = True):
    """The local maxima of the rows of ``g``, sampled at the positions ``u``, and their brackets to zoom into.

    A local maximum is a sample at least its neighbours (the ends included, with one neighbour: a value may
    jump at a join between phases, where each side is its own one-sided limit; every sample of a plateau),
    above -inf (-inf marks an undefined value) and where ``keep`` holds.

    Parameters
    ----------
    g : ndarray, shape (k, n + 1)
        Values of ``k`` rows (centres or designs) at the same positions.
    u : ndarray, shape (n + 1,)
        The positions, increasing.
    keep : ndarray of bool (broadcast with ``g``) or bool, optional
        The samples that may be a maximum.

    Returns
    -------
    rows : ndarray of int
        Each maximum's row of ``g``, in increasing order.
    best, at : ndarray
        Its value and position.
    lo, hi : ndarray
        Its bracket, the positions one sample either side (clipped at the ends): two sampling steps wide.
    """
    low = np.full((len(g), 1), -np.inf)
    left, right = np.hstack([low, g[:, :-1]]), np.hstack([g[:, 1:], low])
    c, j = np.nonzero((g >= left) & (g >= right) & (g > -np.inf) & keep)
    n = len(u) - 1
    return c, g[c, j], u[j], u[np.maximum(j - 1, 0)], u[np.minimum(j + 1, n)]


def zoom(
    values: Callable[[np.ndarray], np.ndarray],
    lo: np.ndarray,
    hi: np.ndarray,
    best: np.ndarray,
    at: np.ndarray,
    steps: int = ZOOM_STEPS,
) -> tuple[np.ndarray, np.ndarray]:
    """Refine maxima by zooming into their brackets, all at once: the peak zoom of the independent check.

    Each bracket is sampled at :data:`ZOOM_POINTS` positions and shrunk to the two intervals about its largest
    sample (tenfold), ``steps`` times; a maximum keeps the largest value seen, from its grid's (``best``) on.

    Parameters
    ----------
    values : callable
        ``values(x)``: the values at the positions ``x`` (shape (m, ZOOM_POINTS), row ``a`` inside maximum
        ``a``'s bracket), the same shape; -inf where undefined (or +inf, where undefined must win), never NaN.
    lo, hi : ndarray, shape (m,)
        The brackets (:func:`grid_peaks`).
    best, at : ndarray, shape (m,)
        The maxima's values and positions on the grid.
    steps : int, optional
        Zoom steps.

    Returns
    -------
    best, at : ndarray, shape (m,)
        The refined values and their positions.
    """
    t = np.linspace(0.0, 1.0, ZOOM_POINTS)
    rows = np.arange(len(lo))
    for _ in range(steps):
        x = lo[:, None] + (hi - lo)[:, None] * t
        gx = values(x)
        jx = np.argmax(gx, axis=1)
        top = gx[rows, jx]
        better = top > best
        best = np.where(better, top, best)
        at = np.where(better, x[rows, jx], at)
        lo, hi = x[rows, np.maximum(jx - 1, 0)], x[rows, np.minimum(jx + 1, ZOOM_POINTS - 1)]
    return best, at


def _angles(design: CamDesign, i: int, ox, oy, s: np.ndarray, ds: np.ndarray) -> np.ndarray:
    """Pressure angle (radians) at the motion ``s, ds`` for the centres ``(ox, oy)`` (broadcast); -inf where undefined.

    -inf lies below every value, so the maxima below skip the undefined positions. ``i`` (the phase) is unused:
    the signature of the values :func:`_phases_max` searches.
    """
    g = _inverted(design, ox, oy, s, ds).angle
    g[np.isnan(g)] = -np.inf
    return g


def _motion(design: CamDesign, i: int, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``s, s'`` of phase ``i`` at the normalized positions ``u`` (any shape)."""
    m = design.program.evaluate_phase(i, u.ravel())
    return m.s.reshape(u.shape), m.ds.reshape(u.shape)


def _phases_max(design: CamDesign, centres: np.ndarray, phases: list[int], grid: int,
                value: Callable[..., np.ndarray] = _angles) -> list[tuple[np.ndarray, np.ndarray]]:
    """Largest pressure angle in each of ``phases`` for each of the centres (shape (k, 2)), and its position.

    Or the largest of another ``value(design, i, ox, oy, s, ds)`` of phase
    ``i``'s motion and the centres (broadcast), -inf where undefined.

    Every local maximum of the sampled angle (the phase ends included: the
    angle may jump at a join between phases, where each side is its own
    one-sided limit) is refined, all at once, by zooming into its bracket of
    two sampling steps; the largest refined value wins. Refining only the
    highest sample would miss a second peak that the sampling lowered. The
    peaks of all phases and centres are zoomed together; each value is
    computed from its own centre and position alone (:func:`invert`), so a
    centre's result does not depend on the other centres checked with it.

    Returns
    -------
    list of (g, u), one per phase, each ndarray of shape (k,)
        Radians (-inf where the angle is undefined throughout) and positions in [0, 1].
    """
    k = len(centres)
    ox, oy = centres[:, 0, None], centres[:, 1, None]
    u = np.linspace(0.0, 1.0, grid + 1)
    peaks = []
    for q, i in enumerate(phases):
        g = value(design, i, ox, oy, *_motion(design, i, u))  # the motion once for every centre
        c, g_at, u_at, lo, hi = grid_peaks(g, u)
        peaks.append((c, np.full(len(c), q), g_at, u_at, lo, hi))
    c, ph, best_g, best_u, lo, hi = (np.concatenate(a) for a in zip(*peaks, strict=True))
    cuts = np.searchsorted(ph, np.arange(len(phases) + 1)).tolist()  # the peaks come grouped by phase
    pox, poy = ox[c], oy[c]
    s, ds = np.empty((len(c), ZOOM_POINTS)), np.empty((len(c), ZOOM_POINTS))

    def values(x: np.ndarray) -> np.ndarray:
        gx = np.empty_like(s)
        for q, i in enumerate(phases):
            a, b = cuts[q], cuts[q + 1]
            if b > a:
                s[a:b], ds[a:b] = _motion(design, i, x[a:b])
                gx[a:b] = value(design, i, pox[a:b], poy[a:b], s[a:b], ds[a:b])
        return gx

    best_g, best_u = zoom(values, lo, hi, best_g, best_u)
    out = []
    for q in range(len(phases)):
        a, b = cuts[q], cuts[q + 1]
        # the best peak of each centre: sort by (centre, value), keep the last of each centre
        out_g, out_u = np.full(k, -np.inf), np.zeros(k)
        order = np.lexsort((best_g[a:b], c[a:b]))
        out_g[c[a:b][order]], out_u[c[a:b][order]] = best_g[a:b][order], best_u[a:b][order]
        out.append((out_g, out_u))
    return out


def _safety(design: CamDesign, i: int, ox, oy, s: np.ndarray, ds: np.ndarray):
    """:func:`cams.verify.safety.safety_terms` of phase ``i`` at the motion ``s, ds`` for the centres ``(ox, oy)``."""
    f = design.follower
    assert isinstance(f, Rocker)
    v = _inverted(design, ox, oy, s, ds)
    _, _, lev = f.frame(s)
    pivot = f.pivot
    return safety_terms(ox - pivot[0], oy - pivot[1], v.nx, v.ny, v.ex, v.ey, lev[..., 0], lev[..., 1], arm=f.arm,
                        factor=design.limits.safety_factor, limit=dict(design.constrained_phases())[i])


def _safety_excess(design: CamDesign, i: int, ox, oy, s: np.ndarray, ds: np.ndarray) -> np.ndarray:
    """The larger of the two moved lines' ``outside / reach`` (:func:`_safety`); -inf where undefined."""
    outside, reach, _ = _safety(design, i, ox, oy, s, ds)
    with np.errstate(divide="ignore", invalid="ignore"):
        v = np.where(reach > 0.0, outside / np.where(reach > 0.0, reach, 1.0), outside).max(axis=-1)
    return np.where(np.isnan(v), -np.inf, v)


def _safety_outside(design: CamDesign, i: int, ox, oy, s: np.ndarray, ds: np.ndarray) -> np.ndarray:
    """The larger of the two moved lines' distances outside (:func:`_safety`, length unit); -inf where undefined."""
    v = _safety(design, i, ox, oy, s, ds)[0].max(axis=-1)
    return np.where(np.isnan(v), -np.inf, v)


def _safety_shortfall(design: CamDesign, i: int, ox, oy, s: np.ndarray, ds: np.ndarray) -> np.ndarray:
    """Minus the smaller of the two lines' largest admitted K_C (:func:`_safety`); -inf where undefined."""
    _, _, admits = _safety(design, i, ox, oy, s, ds)
    v = -admits.min(axis=-1)
    return np.where(np.isnan(v), -np.inf, v)


def _check_safety(design: CamDesign, C: np.ndarray, grid: int, tol: float) -> list[SafetyReport | None]:
    """The :class:`SafetyReport` of each centre of ``C`` (shape (k, 2)); None where K_C does not apply.

    K_C applies to a rocker roller's constrained phases when it is above 1. The moved lines' excess, the
    distance outside them and the K_C met are each searched over every constrained position as the pressure
    angle is (:func:`_phases_max`).
    """
    f = design.follower
    K = design.limits.safety_factor
    phases = [i for i, _ in design.constrained_phases()]
    k = len(C)
    if not isinstance(f, Rocker) or not K > 1.0 or not phases:
        return [None] * k
    block = max(1, CHUNK // (grid + 1))
    excess, met = np.full(k, -np.inf), np.full(k, np.inf)
    outside, out_u, out_q = np.full(k, -np.inf), np.zeros(k), np.zeros(k, dtype=int)
    for a in range(0, k, block):
        cut = slice(a, a + block)
        for g, _ in _phases_max(design, C[cut], phases, grid, _safety_excess):
            excess[cut] = np.maximum(excess[cut], g)
        for g, _ in _phases_max(design, C[cut], phases, grid, _safety_shortfall):
            met[cut] = np.minimum(met[cut], -g)
        for q, (g, u) in enumerate(_phases_max(design, C[cut], phases, grid, _safety_outside)):
            higher = g > outside[cut]
            outside[cut] = np.where(higher, g, outside[cut])
            out_u[cut] = np.where(higher, u, out_u[cut])
            out_q[cut] = np.where(higher, q, out_q[cut])
    # which line is farthest out at each centre's farthest position, phase by phase
    line = np.zeros(k, dtype=int)
    for q, i in enumerate(phases):
        on = np.flatnonzero(out_q == q)
        if len(on):
            line[on] = np.argmax(_safety(design, i, C[on, 0], C[on, 1], *_motion(design, i, out_u[on]))[0], axis=-1)
    # the line leaning outwards (index 0) is t-t when its pressure angle, signed positive in the cam's sense,
    # is +[γ]: when the cam's sense times that of e x lam is positive (e = T / |T|; cams.verify.safety)
    _, T, lam = f.frame(np.float64(0.0))
    names = ("t-t", "t1-t1") if design.cam_sense * (T[0] * lam[1] - T[1] * lam[0]) > 0 else ("t1-t1", "t-t")
    prog = design.program
    out: list[SafetyReport | None] = []
    for a in range(k):
        i = phases[out_q[a]]
        out.append(SafetyReport(factor=float(K), met=float(met[a]), outside=float(outside[a]),
                                at=float(prog.starts[i] + out_u[a] * prog.phases[i].angle), phase=int(i),
                                kind=prog.phases[i].kind, line=names[line[a]], excess=float(excess[a]),
                                ok=bool(excess[a] <= tol)))
    return out


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
        One per centre, in order; each is ``check_pressure(design, centre)``:
        every value is computed from its own centre alone, by the same
        operations however many centres are checked together, so the reports
        are equal to the last digit wherever the motion law's values do not
        depend on how many positions are evaluated at once (the polynomial
        laws of :mod:`laws.standard` are evaluated by a matrix product, whose
        rounding does: there, to a few units in the last place).

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
    phases = [i for i, p in enumerate(prog.phases) if p.kind != "dwell"]
    parts = [_phases_max(design, C[a:a + block], phases, grid) for a in range(0, k, block)] if phases else []
    for q, i in enumerate(phases):
        p = prog.phases[i]
        g = np.concatenate([part[q][0] for part in parts] or [np.empty(0)])
        u = np.concatenate([part[q][1] for part in parts] or [np.empty(0)])
        g = np.where(g >= 0.0, g, np.nan)
        at = prog.starts[i] + u * p.angle
        worst, where = (rise, rise_at) if p.kind == "rise" else (ret, ret_at)
        higher = g > np.where(np.isnan(worst), -np.inf, worst)
        worst[higher], where[higher] = g[higher], at[higher]
    lim = design.limits
    form = lim.closure == "form"
    safety = _check_safety(design, C, grid, tol)
    out = []
    for a in range(k):
        r = None if np.isnan(rise[a]) else float(rise[a])
        b = None if np.isnan(ret[a]) else float(ret[a])
        ok = r is None or r <= lim.pressure_angle + tol
        if form and b is not None:
            ok = ok and b <= lim.return_limit + tol
        sf = safety[a]
        out.append(PressureReport(r, None if r is None else float(rise_at[a]), b,
                                  None if b is None else float(ret_at[a]), lim.pressure_angle,
                                  lim.return_limit if form else None, bool(ok and (sf is None or sf.ok)), sf))
    return out


def check_pressure(design: CamDesign, centre: np.ndarray, *, grid: int = 2000, tol: float = 1e-7) -> PressureReport:
    """Pressure angle over the whole cycle for the centre ``centre``.

    Every rise and return phase is sampled on ``grid + 1`` positions and every
    local maximum of the samples (phase ends included) refined by zooming
    into its bracket of two steps (tenfold a step, :data:`ZOOM_STEPS` steps);
    the largest wins. ``ok`` is True when the constrained phases stay within
    their limits plus ``tol`` radians and, for a rocker with a safety factor
    K_C above 1, the centre lies in the K_C zone: every constrained position's
    two lines moved by seed formula 3.26 (:mod:`cams.verify.safety`, searched
    the same way; its excess, the sine of an angle, within ``tol``). :func:`check_pressure_many` does the
    same for many centres at once, vectorized (this is
    ``check_pressure_many(design, [centre])[0]``).

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
