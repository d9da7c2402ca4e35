"""Curves that keep the motion: biarcs and a cubic spline fitted to the cam's exact curves, each certified.

A polyline's vertices make a roller's path alternate between straight and round, so the exported profile does
not give the designed accelerations however fine the chords; a curve with continuous tangents does much better
(issue 25). This module fits, to every exact curve of a cam (:class:`cams.profile.exact.ExactCam`: the working
profile, a groove's outer wall, the pitch curve), one of

* **arcs** (:func:`fit_arcs`): a chain of circular arcs with a continuous tangent (G1), two arcs (a biarc) per
  span of the exact curve. The span's ends are exact points with their exact tangents; the joint of the two arcs
  follows the **equal-distance rule** (the two arcs' tangent lines from the span's ends to the joint's tangent
  have the same length ``d``: ``Q0 = P0 + d T0``, ``Q1 = P1 - d T1``, ``|Q1 - Q0| = 2 d``, the joint the middle of
  ``Q0 Q1``; Meek and Walton, "Approximating smooth planar curves by arc splines", J. Comput. Appl. Math. 59
  (1995); Bolton, "Biarc curves", Computer-Aided Design 7 (1975)). A span whose certified distance exceeds the
  tolerance is halved in its curve's parameter, and its halves fitted again; so is a span whose arcs' curvature
  strays from the curve's by more than ``CURVATURE_SHARE (tolerance / size)^(1/3)`` of ``|curvature| + 1/size``
  (the curve's turn between samples over their arc length; a rule of the fit, not part of the certificate): the
  follower's acceleration follows the path's curvature, which biarcs fitted by distance alone leave in steps that
  fall only as their length (:mod:`cams.kinematics.exported` measures what the written curve gives);
* **spline** (:func:`fit_spline`): one periodic cubic B-spline interpolating exact points of the curve
  (chord-length parameter, C2 everywhere including the seam at cam angle 0), with a point added in the middle
  of every span whose certified distance exceeds the tolerance, and fitted again.

The certificate
---------------
Every element is certified against the exact curve it replaces: the largest distance from a point of the exact
curve to the element, bounded by sampling with a stated bound. On each span the exact curve is evaluated at
``SAMPLES + 1`` uniform steps of its parameter. For an arc, ``e(u)`` is the exact signed distance of the curve's
point to the arc's circle (a line's: to its line), ``(kappa |w|^2 - 2 w . n) / (1 + |kappa w - n|)`` with ``w``
the point less the arc's start, ``n`` the unit normal there towards the centre and ``kappa`` the signed
curvature (stable for nearly straight arcs); for the spline, ``e(u)`` is ``|C(u) - S(x)|`` signed by the side, at the
foot ``x`` of the perpendicular from the point found by Newton's method from the span mapped linearly (a point
of the spline, so an upper bound of the distance). Between
samples ``delta`` apart, ``|e| <= max(|e_j|, |e_j+1|) + delta^2 M / 8`` (the error of linear interpolation),
where ``M`` bounds ``|e''|``; ``M`` is taken as twice the largest second divided difference of ``e`` over the
span (each equals ``e''`` somewhere between its three samples; the factor 2 is the stated allowance for the
variation of ``e''`` between them). A curve's point is measured against the arc on its side of the joint's
common normal (both, where two neighbouring samples lie on different sides), and to the arc's full circle: its
nearest point lies on the arc while the point lies between the normals at the arc's ends, as every sample does on
a certified span. The comparison is with the exact curve evaluated by the kernel, never with a denser polyline.

Frames and units: the cam frame of :mod:`cams.manufacture.drawing`, lengths in mm; signed curvature positive
turning left (counter-clockwise).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.kinematics.vectors import cross, dot, perp
from cams.profile.exact import ExactCam, ExactCurve
from laws.errors import InputError

__all__ = [
    "CURVES",
    "ArcChain",
    "CubicSpline",
    "FittedCurves",
    "fit_arcs",
    "fit_spline",
    "fit_curves",
    "SAMPLES",
    "MAX_ELEMENTS",
]

#: The curve kinds ``cams profile --curve`` writes.
CURVES = ("arcs", "spline", "polyline")
#: Steps of the exact curve per span in the certificate.
SAMPLES = 32
#: The most elements of one curve (arcs, spline spans): guards against endless refinement at a cusp or a corner.
MAX_ELEMENTS = 200_000
#: The arcs' curvature follows the curve's within ``CURVATURE_SHARE (tolerance / size)^(1/3)`` of it (relative to
#: ``|curvature| + 1/size``): the follower's acceleration is the path's curvature, which a fit by distance alone
#: leaves piecewise constant with steps that fall only as the arcs' length (module notes).
CURVATURE_SHARE = 0.3


@dataclass(frozen=True, eq=False)
class ArcChain:
    """A closed chain of circular arcs (and straight lines), G1 inside each fitted piece of the exact curve.

    Attributes
    ----------
    start : ndarray, shape (n, 2)
        Each element's start point (the previous one's end; the last ends at the first's start), mm.
    tangent : ndarray, shape (n, 2)
        Unit tangent at each element's start.
    bulge : ndarray, shape (n,)
        ``tan(sweep / 4)``, positive counter-clockwise (the DXF's LWPOLYLINE bulge); 0 a straight line.
    distance : float
        The certified largest distance from the exact curve to the chain (mm).
    """

    start: np.ndarray
    tangent: np.ndarray
    bulge: np.ndarray
    distance: float

    @property
    def end(self) -> np.ndarray:
        """Each element's end point: the next one's start (mm)."""
        return np.roll(self.start, -1, axis=0)

    @property
    def elements(self) -> int:
        return len(self.bulge)

    @property
    def sweep(self) -> np.ndarray:
        """Each element's signed sweep angle (radians, counter-clockwise positive)."""
        return 4.0 * np.arctan(self.bulge)

    @property
    def curvature(self) -> np.ndarray:
        """Each element's signed curvature (1/mm, counter-clockwise positive; 0 a line): ``2 sin(sweep/2) / chord``."""
        chord = np.hypot(*(self.end - self.start).T)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(chord > 0, 2.0 * np.sin(self.sweep / 2) / chord, 0.0)


@dataclass(frozen=True, eq=False)
class CubicSpline:
    """A closed cubic B-spline, clamped at its ends (which coincide, C2 there as inside).

    Attributes
    ----------
    knots : ndarray, shape (m + 4,)
        The knot vector: the first and last knots four times, the interior ones once (the chord-length parameter,
        mm).
    control : ndarray, shape (m, 2)
        Control points, mm.
    distance : float
        The certified largest distance from the exact curve to the spline (mm).
    """

    knots: np.ndarray
    control: np.ndarray
    distance: float

    @property
    def elements(self) -> int:
        """The spline's polynomial spans."""
        return int(len(np.unique(self.knots)) - 1)

    def bspline(self):
        """The spline as a :class:`scipy.interpolate.BSpline` (vector-valued)."""
        from scipy.interpolate import BSpline

        return BSpline(self.knots, self.control, 3)

    def bezier(self) -> np.ndarray:
        """The spline's spans as cubic Bezier segments, shape ``(spans, 4, 2)`` (for an SVG path's ``C``)."""
        s = self.bspline()
        x = np.unique(self.knots)
        p, dp = s(x), s.derivative()(x)
        h = np.diff(x)[:, None]
        return np.stack([p[:-1], p[:-1] + dp[:-1] * h / 3, p[1:] - dp[1:] * h / 3, p[1:]], axis=1)


@dataclass(frozen=True, eq=False)
class FittedCurves:
    """The fitted curves of a cam by drawing layer, their kind and tolerance (mm)."""

    kind: str
    tolerance: float
    curves: dict[str, ArcChain | CubicSpline]

    def to_dict(self) -> dict:
        """``curve`` (kind), ``tolerance`` (mm), and per layer ``elements`` (count) and ``distance`` (mm, certified)."""
        return {
            "curve": self.kind,
            "tolerance": self.tolerance,
            "layers": {k: {"elements": c.elements, "distance": c.distance} for k, c in self.curves.items()},
        }


def check_curve(kind: object, field: str = "--curve") -> str:
    """``kind`` if it is one of :data:`CURVES`, else :class:`InputError` naming ``field``."""
    if kind not in CURVES:
        raise InputError(field, f"must be one of {', '.join(CURVES)}, got {kind!r}")
    return str(kind)


# -- evaluation of the exact curve on spans --------------------------------------------------------


def _evaluate(curve: ExactCurve, piece: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Points and unit tangents of ``curve`` at parameters ``u`` of pieces ``piece`` (arrays of one shape)."""
    shape = u.shape
    piece, u = piece.ravel(), u.ravel()
    pts, tan = np.empty((len(u), 2)), np.empty((len(u), 2))
    for k in np.unique(piece):
        sel = piece == k
        pts[sel], tan[sel] = curve.pieces[int(k)].evaluate(u[sel])
    return pts.reshape((*shape, 2)), tan.reshape((*shape, 2))


def _margin(e: np.ndarray, h: float) -> np.ndarray:
    """``h^2 M / 8`` per row (last axis: samples ``h`` apart), ``M`` twice the largest second divided difference
    of ``e`` over the row: what ``|e|`` may exceed its samples by between them (the module's certificate)."""
    d2 = np.abs(e[..., :-2] - 2 * e[..., 1:-1] + e[..., 2:]) / h**2
    return h * h * 2.0 * np.max(d2, axis=-1, keepdims=True) / 8.0


def _bound(e: np.ndarray, h: float) -> np.ndarray:
    """Per interval between the samples (last axis), ``max(|e_j|, |e_j+1|) + h^2 M / 8`` (:func:`_margin`)."""
    a = np.abs(e)
    return np.maximum(a[..., :-1], a[..., 1:]) + _margin(e, h)


# -- biarcs ----------------------------------------------------------------------------------------


def _biarc(P0, T0, P1, T1):
    """The equal-distance biarc's joint ``J`` and its tangent ``TJ`` for spans ``P0, T0 -> P1, T1`` (rows)."""
    v = P1 - P0
    t = T0 + T1
    vt, vv = dot(v, t), dot(v, v)
    den = 2.0 * (1.0 - dot(T0, T1))
    with np.errstate(divide="ignore", invalid="ignore"):
        d_gen = (-vt + np.sqrt(vt * vt + den * vv)) / den
        d_par = vv / (4.0 * dot(v, T1))
    d = np.where(den > 1e-12, d_gen, d_par)
    Q0, Q1 = P0 + d[:, None] * T0, P1 - d[:, None] * T1
    J = 0.5 * (Q0 + Q1)
    TJ = Q1 - Q0
    nj = np.hypot(TJ[:, 0], TJ[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        TJ = np.where(nj[:, None] > 0, TJ / nj[:, None], T0)
    straight = (
        (np.abs(cross(T0, v)) <= 1e-15 * np.sqrt(vv)) & (np.abs(cross(T1, v)) <= 1e-15 * np.sqrt(vv)) & (dot(T0, v) > 0)
    )
    J = np.where(straight[:, None], 0.5 * (P0 + P1), J)
    TJ = np.where(straight[:, None], T0, TJ)
    return J, TJ


def _bulge_curvature(A, T, B):
    """Bulge and signed curvature of the arc from ``A`` with tangent ``T`` to ``B`` (rows)."""
    c = B - A
    half = np.arctan2(cross(T, c), dot(T, c))  # the angle from the tangent to the chord: half the sweep
    L = np.hypot(c[:, 0], c[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        kappa = np.where(L > 0, 2.0 * np.sin(half) / L, 0.0)
    return np.tan(half / 2.0), kappa


def _circle_distance(X, A, T, kappa):
    """Signed distance of points ``X`` (..., 2) to the circle through ``A`` with tangent ``T`` and curvature
    ``kappa`` (a line when 0): positive on the side away from the centre."""
    n = perp(T)  # the left normal: towards the centre when kappa > 0
    w = X - A
    k = kappa[..., None] if np.ndim(kappa) else kappa
    num = kappa * dot(w, w) - 2.0 * dot(w, n)
    den = 1.0 + np.hypot(*np.moveaxis(k * w - n, -1, 0))
    return num / den


def _certify_biarcs(curve, piece, ua, ub, P0, T0, J, TJ, P1):
    """The certified distance of each span's biarc, and its arcs' bulges and curvatures."""
    b1, k1 = _bulge_curvature(P0, T0, J)
    b2, k2 = _bulge_curvature(J, TJ, P1)
    s = np.linspace(0.0, 1.0, SAMPLES + 1)
    uu = ua[:, None] + (ub - ua)[:, None] * s[None]
    X, _ = _evaluate(curve, np.repeat(piece[:, None], SAMPLES + 1, 1), uu)
    e1 = _circle_distance(X, P0[:, None], T0[:, None], k1[:, None])
    e2 = _circle_distance(X, J[:, None], TJ[:, None], k2[:, None])
    h = 1.0 / SAMPLES
    B1, B2 = _bound(e1, h), _bound(e2, h)  # per interval, as if the curve were on arc 1 or on arc 2
    side2 = dot(X - J[:, None], TJ[:, None]) > 0  # past the joint's common normal: the second arc's
    on1 = ~side2[:, :-1] | ~side2[:, 1:]
    on2 = side2[:, :-1] | side2[:, 1:]
    worst = np.max(np.maximum(np.where(on1, B1, 0.0), np.where(on2, B2, 0.0)), axis=1)
    return worst, b1, k1, b2, k2


def _size(curve: ExactCurve) -> float:
    """The curve's size (mm): its largest distance from the cam centre, on a coarse sampling of its pieces."""
    u = np.linspace(0.0, 1.0, 9)
    pts = [p.evaluate(u)[0] for p in curve.pieces]
    return float(max(np.max(np.hypot(q[:, 0], q[:, 1])) for q in pts)) or 1.0


def _curvature_error(curve, piece, ua, ub, J, TJ, k1, k2, size: float) -> np.ndarray:
    """Per span, the largest difference between the curve's curvature (the turn of its exact tangent over the arc
    length between samples) and the curvature of the biarc's arc on that side of the joint, relative to
    ``|curvature| + 1 / size``."""
    s = np.linspace(0.0, 1.0, SAMPLES + 1)
    uu = ua[:, None] + (ub - ua)[:, None] * s[None]
    X, T = _evaluate(curve, np.repeat(piece[:, None], SAMPLES + 1, 1), uu)
    theta = np.unwrap(np.arctan2(T[..., 1], T[..., 0]), axis=1)
    ds = np.hypot(*np.moveaxis(np.diff(X, axis=1), -1, 0))
    with np.errstate(divide="ignore", invalid="ignore"):
        kap = np.where(ds > 0, np.diff(theta, axis=1) / ds, 0.0)
    mid = 0.5 * (X[:, 1:] + X[:, :-1])
    second = dot(mid - J[:, None], TJ[:, None]) > 0
    k_arc = np.where(second, k2[:, None], k1[:, None])
    return np.max(np.abs(kap - k_arc) / (np.abs(kap) + 1.0 / size), axis=1)


def fit_arcs(curve: ExactCurve, tolerance: float, *, field: str = "--curve") -> ArcChain:
    """Fit a closed chain of biarcs to ``curve`` within ``tolerance`` (mm), certified (the module's notes).

    Raises
    ------
    InputError
        Naming ``field``: the tolerance needs more than :data:`MAX_ELEMENTS` arcs, or a span cannot be brought
        within it (a cusp of an undercut profile).
    """
    n0 = [8 if p.kind == "curve" else 1 for p in curve.pieces]
    size = _size(curve)
    share = CURVATURE_SHARE * (tolerance / size) ** (1.0 / 3.0)
    piece = np.concatenate([np.full(n, k) for k, n in enumerate(n0)])
    ua = np.concatenate([np.arange(n) / n for n in n0])
    ub = np.concatenate([np.arange(1, n + 1) / n for n in n0])
    done: list[tuple] = []
    for _ in range(60):
        if len(ua) == 0:
            break
        (P0, T0), (P1, T1) = _evaluate(curve, piece, ua), _evaluate(curve, piece, ub)
        J, TJ = _biarc(P0, T0, P1, T1)
        worst, b1, k1, b2, k2 = _certify_biarcs(curve, piece, ua, ub, P0, T0, J, TJ, P1)
        bad = ~(worst <= tolerance)
        stuck = bad & ((ub - ua) < 1e-9)
        # the motion: a span is halved too while its arcs' curvature strays from the curve's (module notes)
        bad |= (_curvature_error(curve, piece, ua, ub, J, TJ, k1, k2, size) > share) & ((ub - ua) > 1e-6)
        if np.any(stuck):
            raise InputError(
                field,
                f"arcs cannot follow the curve within {tolerance:g} mm near "
                f"({P0[stuck][0][0]:.6g}, {P0[stuck][0][1]:.6g}) mm (a cusp or corner); use "
                "--curve polyline or a larger --tolerance",
            )
        ok = ~bad
        done.append((piece[ok], ua[ok], P0[ok], T0[ok], J[ok], TJ[ok], b1[ok], b2[ok], worst[ok]))
        if sum(len(d[0]) for d in done) * 2 + 4 * int(bad.sum()) > MAX_ELEMENTS:
            raise InputError(
                field, f"arcs within {tolerance:g} mm need more than {MAX_ELEMENTS} elements; use a larger --tolerance"
            )
        um = 0.5 * (ua[bad] + ub[bad])
        piece = np.concatenate([piece[bad], piece[bad]])
        ua, ub = np.concatenate([ua[bad], um]), np.concatenate([um, ub[bad]])
    else:  # pragma: no cover - 60 halvings reach the 1e-9 floor first
        raise InputError(field, "arcs did not converge")
    cat = [np.concatenate([d[k] for d in done]) for k in range(9)]
    pc, u0, P0, T0, J, TJ, b1, b2, worst = cat
    order = np.lexsort((u0, pc))
    P0, T0, J, TJ, b1, b2 = P0[order], T0[order], J[order], TJ[order], b1[order], b2[order]
    start = np.stack([P0, J], axis=1).reshape(-1, 2)
    tangent = np.stack([T0, TJ], axis=1).reshape(-1, 2)
    bulge = np.stack([b1, b2], axis=1).reshape(-1)
    return ArcChain(start, tangent, bulge, float(np.max(worst)))


# -- the spline ------------------------------------------------------------------------------------


def _interpolate(points: np.ndarray):
    """The periodic cubic interpolating ``points`` (closed: the first is not repeated) at their cumulative chord
    lengths: ``(BSpline, parameters of the points and of the closing one)``."""
    from scipy.interpolate import make_interp_spline

    closed = np.vstack([points, points[:1]])
    x = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(closed, axis=0).T))])
    return make_interp_spline(x, closed, k=3, bc_type="periodic"), x


def _clamped(spl, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The periodic spline on ``[x0, xn]`` as a clamped cubic B-spline with the interior knots ``x``: knots,
    control points (the same curve: it lies in that spline space; found by least squares on its own points)."""
    from scipy.interpolate import make_lsq_spline

    knots = np.concatenate([[x[0]] * 4, x[1:-1], [x[-1]] * 4])
    s = np.linspace(0.0, 1.0, 5)[:-1]
    xs = np.concatenate([(x[:-1, None] + np.diff(x)[:, None] * s[None]).ravel(), [x[-1]]])
    lsq = make_lsq_spline(xs, spl(xs), knots, k=3)
    return knots, np.asarray(lsq.c)


def _spline_distance(spl, period: float, C: np.ndarray, t: np.ndarray) -> np.ndarray:
    """Signed distance of the points ``C`` (..., 2) to the periodic spline ``spl`` (of parameter period ``period``):
    from the parameters ``t`` (the span mapped linearly), Newton's steps to the foot of the perpendicular, then
    ``(C - S(t)) . n`` with ``n`` the spline's left unit normal there (its length ``|C - S(t)|``, a point of the
    spline: an upper bound of the distance; a smooth function of the curve's parameter where the foot is unique,
    which the certificate's second differences need)."""
    d1, d2 = spl.derivative(), spl.derivative(2)
    for _ in range(6):
        tt = np.mod(t, period)
        g, v, a = spl(tt) - C, d1(tt), d2(tt)
        step = np.sum(g * v, -1) / (np.sum(v * v, -1) + np.sum(g * a, -1))
        t = t - np.where(np.isfinite(step), step, 0.0)
    tt = np.mod(t, period)
    g, v = C - spl(tt), d1(tt)
    n = perp(v) / np.hypot(v[..., 0], v[..., 1])[..., None]
    return np.sign(np.sum(g * n, -1)) * np.hypot(g[..., 0], g[..., 1])


def fit_spline(curve: ExactCurve, tolerance: float, *, field: str = "--curve") -> CubicSpline:
    """Fit a closed cubic spline through exact points of ``curve`` within ``tolerance`` (mm), certified.

    Raises
    ------
    InputError
        Naming ``field``: the tolerance needs more than :data:`MAX_ELEMENTS` spans (a corner, which a C2 curve
        cannot turn).
    """
    n0 = [16 if p.kind == "curve" else 2 for p in curve.pieces]
    piece = np.concatenate([np.full(n, k) for k, n in enumerate(n0)])
    u = np.concatenate([np.arange(n) / n for n in n0])
    s = np.linspace(0.0, 1.0, SAMPLES + 1)
    for _ in range(60):
        pts, _t = _evaluate(curve, piece, u)
        keep = np.ones(len(u), bool)  # a piece's start equal to the previous piece's end is one point
        gap = np.hypot(*(pts - np.roll(pts, 1, axis=0)).T)
        keep &= gap > 1e-12 * max(1.0, float(np.max(np.abs(pts))))
        piece, u, pts = piece[keep], u[keep], pts[keep]
        spl, x = _interpolate(pts)
        # the span from point j to j + 1: the exact curve from (piece_j, u_j) to the next point's position
        nxt_piece, nxt_u = np.roll(piece, -1), np.roll(u, -1)
        same = nxt_piece == piece
        ue = np.where(same & (nxt_u > u), nxt_u, 1.0)  # the last span runs to its piece's end
        # a span that ends at the next piece's start runs to the end of its own piece (the same point)
        uu = u[:, None] + (ue - u)[:, None] * s[None]
        C, _t = _evaluate(curve, np.repeat(piece[:, None], SAMPLES + 1, 1), uu)
        xx = x[:-1, None] + np.diff(x)[:, None] * s[None]
        e = _spline_distance(spl, x[-1], C, xx)
        worst = np.max(_bound(e, 1.0 / SAMPLES), axis=1)
        bad = ~(worst <= tolerance)
        if not np.any(bad):
            knots, ctrl = _clamped(spl, x)
            return CubicSpline(knots, ctrl, float(np.max(worst)))
        if len(u) + int(bad.sum()) > MAX_ELEMENTS or np.any(bad & ((ue - u) < 1e-9)):
            where = pts[bad][0]
            raise InputError(
                field,
                f"a spline cannot follow the curve within {tolerance:g} mm near "
                f"({where[0]:.6g}, {where[1]:.6g}) mm (a corner); use --curve arcs",
            )
        um = 0.5 * (u[bad] + ue[bad])
        piece = np.concatenate([piece, piece[bad]])
        u = np.concatenate([u, um])
        order = np.lexsort((u, piece))
        piece, u = piece[order], u[order]
    raise InputError(field, f"a spline did not reach {tolerance:g} mm; use --curve arcs")  # pragma: no cover


def fit_curves(exact: ExactCam, tolerance: float, kind: str, *, field: str = "--curve") -> FittedCurves | None:
    """Every curve of ``exact`` fitted as ``kind`` (``"arcs"`` or ``"spline"``) within ``tolerance`` (mm);
    None for ``"polyline"`` (the sampled profile is written as it is)."""
    check_curve(kind, field)
    if kind == "polyline":
        return None
    fit = fit_arcs if kind == "arcs" else fit_spline
    return FittedCurves(kind, float(tolerance), {k: fit(c, tolerance, field=field) for k, c in exact.curves.items()})
