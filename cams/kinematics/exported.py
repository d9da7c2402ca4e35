"""The motion an exported curve really gives: the follower in contact with the drawn profile, inverted exactly.

An export (:mod:`cams.manufacture`) draws the working profile as elements -- line segments, circle arcs, B-spline
pieces. This module shares no formula with the exporters: it takes the elements as the shop would cut them and
finds, for each cam angle, where the design's follower sits in contact with them, then the motion's derivatives
by implicit differentiation of the contact condition on the element in contact.

Frames and signs
----------------
* The elements are in the cam frame of :mod:`cams.kinematics.inversion` (origin at the cam centre, axes parallel
  to the fixed frame at ``phi = 0``; a flat rocker's: its line-of-centres frame, :mod:`cams.kinematics.flat`). A
  point ``X`` of the cam frame is at ``O + R(eps phi) X`` in the fixed frame (``eps`` the cam's sense).
* Roller (or knife edge) of radius ``r``: its centre's path at cam angle ``phi`` seen from the cam is
  ``Q(s) = R(-eps phi) (A(s) - O)`` -- a line (translating) or a circle about the turned pivot (rocker). The
  follower sits at the **outermost** ``s`` at which the roller touches the curve: the largest ``s`` with
  ``dist(Q(s), curve) = r``. That ``s`` is a boundary point of ``{s: dist(Q(s), curve) <= r}``, where the
  nearest point of the curve is an element's end point (the roller rounds it: ``|Q - V| = r``) or an interior
  foot (a segment: ``Q`` on a line offset by ``r``; an arc of centre ``C``, radius ``R``: ``|Q - C| = R + r`` or
  ``R - r`` with the radial foot on the arc; a spline piece: ``Q = B(t) +- r N(t)``). Every such candidate is a
  true touch and the largest is the answer: closed forms (line or circle against line or circle) for the first
  three, a bracketed root-finding to machine precision in ``t`` for a spline piece.
* Flat face: the face's distance from the cam centre is the curve's support function ``h(theta) = max X . m``
  over its points (``m`` the face normal at angle ``theta`` in the cam frame): exact per element (an end point,
  an arc's ``C . m + R`` where ``m`` points into its span, a spline piece's interior critical points
  ``B'(t) . m = 0``). A translating face: ``theta = pi/2 - eps phi``, ``s = h - R0``; a rocker:
  ``f - L cos a = h(a - eps phi)`` solved for the face angle ``a`` (``s = sigma (a - a0)``).
* Derivatives: with ``g(Q)`` the distance to the element in contact less ``r`` (gradient ``n``, the unit vector
  from the foot to ``Q``; Hessian ``k t t^T``, ``k`` the curvature of the offset curve through ``Q``:
  ``1/r`` at an end point, ``1/(R + r)`` or ``-1/(R - r)`` on an arc, 0 on a segment, ``kappa/(1 + kappa r)``
  on a spline piece), ``F(s, phi) = g(Q(s, phi)) = 0`` gives ``s' = -F_phi / F_s`` and
  ``s'' = -(F_ss s'^2 + 2 F_sphi s' + F_phiphi) / F_s``: exact between the switches from one element to the next.
  A flat face: ``h_theta = X* . m_theta`` and ``h_thetatheta = rho* - h`` at the support point ``X*``.

Angles radians, lengths the design's unit (mm); a rocker's swing in radians (reported in degrees by
:meth:`ExportMotion.to_dict`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, cast

import numpy as np

from cams.kinematics.vectors import perp, rotate
from cams.model.design import CamDesign, FlatFaceDesign
from cams.model.follower import FlatRocker, FlatTranslating, Rocker, Translating
from laws.errors import InputError
from laws.search import bracketed_root  # plain numpy: importing scipy.optimize costs 0.3 s

__all__ = [
    "Line",
    "Arc",
    "SplinePiece",
    "Element",
    "Contact",
    "ExportMotion",
    "check_closed",
    "corners",
    "roller_contact",
    "flat_contact",
    "export_motion",
    "CLOSURE_TOLERANCE",
]

#: A curve is closed when each element's end meets the next one's start within this share of its size.
CLOSURE_TOLERANCE = 1e-7
#: A joint of the curve turning its tangent by at most this (radians) is smooth: the written digits' rounding of
#: tangent arcs (an SVG's 12 significant digits leave kinks of about 1e-10 rad). The roller would rest on such a
#: corner for a cam angle of the same order and move by about r * angle**2 / 2 off the neighbours' touch; taken as
#: a corner, the angles checked that fall on it (a phase start at a joint) would read the vertex's curvature 1/r.
SMOOTH_JOINT = 1e-7


def _in_span(angle, start, sense, span):
    """Whether the direction ``angle`` (radians) points into arcs' spans, ends included (to 1e-13 rad): the arcs
    from ``start`` turning by ``span`` (radians, in (0, 2 pi]) in the ``sense`` (+1 counter-clockwise, -1
    clockwise); numpy broadcasting over all four."""
    d = (sense * (angle - start)) % (2 * np.pi)
    return (d <= span + 1e-13) | (d >= 2 * np.pi - 1e-13)


@dataclass(frozen=True)
class Line:
    """A straight segment from ``start`` to ``end`` (cam frame, length unit)."""

    start: tuple[float, float]
    end: tuple[float, float]

    @property
    def ends(self) -> tuple[np.ndarray, np.ndarray]:
        return np.asarray(self.start, float), np.asarray(self.end, float)


@dataclass(frozen=True)
class Arc:
    """A circle arc: ``centre``, ``radius`` (length), from angle ``start`` to ``end`` (radians) turning in
    ``sense`` (+1 counter-clockwise, -1 clockwise). Its span is the angle swept from ``start`` to ``end`` in
    ``sense``, in (0, 2 pi]."""

    centre: tuple[float, float]
    radius: float
    start: float
    end: float
    sense: int = 1

    @property
    def span(self) -> float:
        sw = (self.sense * (self.end - self.start)) % (2 * np.pi)
        return 2 * np.pi if sw == 0 else float(sw)

    def point(self, angle: float) -> np.ndarray:
        return np.asarray(self.centre, float) + self.radius * np.array([np.cos(angle), np.sin(angle)])

    @property
    def ends(self) -> tuple[np.ndarray, np.ndarray]:
        return self.point(self.start), self.point(self.start + self.sense * self.span)

    def contains(self, angle: float) -> bool:
        """Whether the direction ``angle`` (radians) points into the arc's span (its ends included)."""
        return bool(_in_span(angle, self.start, self.sense, self.span))


@dataclass(frozen=True, eq=False)
class SplinePiece:
    """One polynomial piece of a (possibly rational) B-spline, ``t`` in ``[0, 1]``.

    ``coeffs`` has shape ``(degree + 1, 3)``: the power-basis coefficients (highest first) of the homogeneous
    coordinates ``(w x, w y, w)``; a non-rational piece has ``w = 1``. Built by
    :func:`cams.manufacture.readback.spline_pieces` (or by hand in tests).
    """

    coeffs: np.ndarray
    _d: Any = field(init=False, repr=False, compare=False, default=None)
    _rows: Any = field(init=False, repr=False, compare=False, default=None)
    _grid: Any = field(init=False, repr=False, compare=False, default=None)

    def __post_init__(self) -> None:
        c = np.asarray(self.coeffs, float)
        deg = len(c) - 1
        p = np.arange(deg, -1, -1)[:, None]
        c1 = (c * p)[:-1]  # the power basis differentiated, highest power first
        c2 = (c1 * p[1:])[:-1] if deg > 1 else np.zeros((1, 3))
        object.__setattr__(self, "coeffs", c)
        d = (c, c1 if deg > 0 else np.zeros((1, 3)), c2)
        object.__setattr__(self, "_d", d)
        # the same coefficients as Python floats: one number t is evaluated without numpy's per-call overhead
        object.__setattr__(self, "_rows", tuple(tuple(tuple(float(x) for x in row) for row in k) for k in d))

    def derivatives(self, t):
        """``B(t), B'(t), B''(t)`` (cam frame, length unit per unit of ``t``), the rational quotient rule; ``t`` a
        number (arrays of shape (2,)) or an array (shape ``t.shape + (2,)``)."""
        t = np.asarray(t, float)
        if t.ndim == 0:
            return self._derivatives_at(float(t))
        h = []
        for c in self._d:  # Horner's scheme on the three homogeneous coordinates at once
            y = np.broadcast_to(c[0], (*t.shape, 3)).copy()
            for row in c[1:]:
                y = y * t[..., None] + row
            h.append(y)
        w, w1, w2 = h[0][..., 2:], h[1][..., 2:], h[2][..., 2:]
        b = h[0][..., :2] / w
        b1 = (h[1][..., :2] - w1 * b) / w
        b2 = (h[2][..., :2] - 2 * w1 * b1 - w2 * b) / w
        return b, b1, b2

    def _derivatives_at(self, t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """:meth:`derivatives` at one number ``t``: the same operations in the same order on Python floats (the
        same IEEE double results), for the root searches that call it one ``t`` at a time."""
        h = []
        for rows in self._rows:
            x, y, z = rows[0]
            for rx, ry, rz in rows[1:]:
                x, y, z = x * t + rx, y * t + ry, z * t + rz
            h.append((x, y, z))
        (X, Y, w), (X1, Y1, w1), (X2, Y2, w2) = h
        bx, by = X / w, Y / w
        b1x, b1y = (X1 - w1 * bx) / w, (Y1 - w1 * by) / w
        b2x, b2y = (X2 - 2 * w1 * b1x - w2 * bx) / w, (Y2 - 2 * w1 * b1y - w2 * by) / w
        return np.array([bx, by]), np.array([b1x, b1y]), np.array([b2x, b2y])

    def grid(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``t`` at 17 points evenly over ``[0, 1]``, ``B(t)`` and the unit left normal there: the grid on which
        the roots along the piece are bracketed, computed once per piece (it depends on nothing else)."""
        if self._grid is None:
            ts = np.linspace(0.0, 1.0, 17)
            b, b1, _ = self.derivatives(ts)
            object.__setattr__(self, "_grid", (ts, b, _unit_normal(b1)))
        return self._grid

    @property
    def ends(self) -> tuple[np.ndarray, np.ndarray]:
        return self.derivatives(0.0)[0], self.derivatives(1.0)[0]

    def bound(self) -> tuple[np.ndarray, float]:
        """A circle holding the piece (centre, radius), from a dense look plus a margin of its chord."""
        pts = self.derivatives(np.linspace(0.0, 1.0, 33))[0]
        c = 0.5 * (pts.min(axis=0) + pts.max(axis=0))
        step = float(np.max(np.linalg.norm(np.diff(pts, axis=0), axis=1)))
        return c, float(np.max(np.linalg.norm(pts - c, axis=1))) + step


Element = Line | Arc | SplinePiece


def _unit_normal(b1: np.ndarray) -> np.ndarray:
    """The unit left normal ``(-y', x') / |B'|`` of tangents ``b1`` (..., 2)."""
    return perp(b1) / np.hypot(b1[..., 0], b1[..., 1])[..., None]


def check_closed(elements: list[Element], field: str = "PROFILE") -> None:
    """Raise :class:`InputError` (``field``) unless the elements form one closed chain, in order.

    Each element's end must meet the next one's start (the last the first's) within :data:`CLOSURE_TOLERANCE`
    of the curve's size.
    """
    if not elements:
        raise InputError(field, "holds no curve: give a closed profile of lines, arcs or spline pieces")
    ends = [e.ends for e in elements]
    size = max(float(np.max(np.abs(np.concatenate([a, b])))) for a, b in ends)
    tol = CLOSURE_TOLERANCE * max(size, 1.0)
    for i, (_, b) in enumerate(ends):
        a = ends[(i + 1) % len(ends)][0]
        gap = float(np.hypot(*(a - b)))
        if gap > tol:
            raise InputError(
                field,
                f"is not a closed curve: element {i}'s end ({b[0]:.6g}, {b[1]:.6g}) is "
                f"{gap:.3g} mm from the next one's start; export the profile as one closed curve",
            )


# -- the path at one cam angle: a line (translating) or a circle (rocker), for the spline pieces' roots ----------


@dataclass(frozen=True)
class _Path:
    """The roller centre's path seen from the cam at one cam angle (the spline pieces' root-finding's; the
    block of angles of the end points, segments and arcs is :class:`_Paths`)."""

    kind: str  # "line" or "circle"
    base: np.ndarray  # line: Q(0); circle: its centre (the pivot, turned)
    axis: np.ndarray  # line: dQ/ds; circle: the turned fixed frame's x axis
    yaxis: np.ndarray  # circle: the turned y axis
    radius: float  # circle: the arm
    sense: int  # circle: the rocker's sense
    window: float  # circle: the swing about which the answer is sought (radians)

    def param(self, q: np.ndarray) -> np.ndarray:
        """The ``s`` of points ``q`` (k, 2) on the path (a rocker's within pi of the window's swing)."""
        d = q - self.base
        if self.kind == "line":
            return d @ self.axis
        s = self.sense * np.arctan2(d @ self.yaxis, d @ self.axis)
        return s + 2 * np.pi * np.round((self.window - s) / (2 * np.pi))

    def off(self, q: np.ndarray) -> np.ndarray:
        """A signed measure of points ``q`` (..., 2) off the path (zero on it): for root-finding along a spline."""
        w = q - self.base
        if self.kind == "line":
            return self.axis[0] * w[..., 1] - self.axis[1] * w[..., 0]
        return np.hypot(w[..., 0], w[..., 1]) - self.radius

    def near(self, c: np.ndarray, reach: np.ndarray) -> np.ndarray:
        """Which of the points ``c`` (n, 2) lie within ``reach`` (n,) of the path."""
        if self.kind == "line":
            w = c - self.base
            return np.abs(self.axis[0] * w[:, 1] - self.axis[1] * w[:, 0]) <= reach
        return np.abs(np.hypot(*(c - self.base).T) - self.radius) <= reach


# -- the contact ------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Contact:
    """The follower in contact with an exported curve at cam angles ``phi``.

    Attributes
    ----------
    phi : ndarray, shape (n,)
        Cam angles, radians.
    s, ds, d2s : ndarray, shape (n,)
        The follower's displacement (length, or a rocker's swing in radians) and its first two derivatives by the
        cam angle (per radian, per radian^2), exact on the element in contact.
    element : ndarray of int, shape (n,)
        Index of the element in contact (an end point counts as its element's).
    """

    phi: np.ndarray
    s: np.ndarray
    ds: np.ndarray
    d2s: np.ndarray
    element: np.ndarray


class _Elements:
    """The elements sorted by kind, with bounds for a quick choice of those near the path."""

    def __init__(self, elements: list[Element]):
        self.items = list(elements)
        # the chain is closed (check_closed): each element's start is the previous one's end, one vertex each; a
        # joint that turns the tangent by at most SMOOTH_JOINT is smooth: no vertex for the roller to rest on
        self.joints = np.array([e.ends[0] for e in self.items]).reshape(-1, 2)  # every element's start
        self.verts, self.vert_owner = self.joints, np.arange(len(self.items))
        # a smooth joint (a rounding kink): a roller resting on it moves as on the element after it, whose signed
        # curvature (positive turning left) and tangent at its start are kept
        self.smooth = _joint_turns(self.items) <= SMOOTH_JOINT
        self.kappa = np.array([_start_curvature(e) for e in self.items])
        with np.errstate(divide="ignore", invalid="ignore"):  # a zero-length line: no tangent (a corner)
            self.tangent = np.array([_end_tangents(e)[0] for e in self.items]).reshape(-1, 2)
        kinds = np.array([0 if isinstance(e, Line) else 1 if isinstance(e, Arc) else 2 for e in self.items])
        self.lines, self.arcs, self.splines = (np.flatnonzero(kinds == k) for k in range(3))
        self.la = np.zeros((len(self.items), 2))
        self.ld = np.zeros((len(self.items), 2))
        self.ll = np.zeros(len(self.items))
        for i in self.lines:
            a, b = self.items[i].ends
            ln = float(np.hypot(*(b - a)))
            self.la[i], self.ll[i] = a, ln
            self.ld[i] = (b - a) / ln if ln > 0 else (1.0, 0.0)
        bounds = []
        for e in self.items:
            if isinstance(e, SplinePiece):
                bounds.append(e.bound())
            else:
                a, b = e.ends
                c = 0.5 * (a + b)
                rad = 0.5 * float(np.hypot(*(b - a)))
                if isinstance(e, Arc) and e.span > np.pi:
                    c, rad = np.asarray(e.centre, float), e.radius  # the whole circle holds the arc
                elif isinstance(e, Arc):  # up to a half circle, within half its chord of the chord's midpoint
                    rad *= 1.0 + 1e-12
                bounds.append((c, rad))
        self.bc = np.array([b[0] for b in bounds]).reshape(-1, 2)
        self.br = np.array([b[1] for b in bounds])
        self.size = float(np.max(np.abs(self.joints)))
        # the arcs' start, sense and span as arrays: the arcs whose span holds a direction found at once
        # (arcs_containing, Arc.contains's arithmetic element by element)
        arcs = [cast(Arc, self.items[i]) for i in self.arcs]
        self.arc_start = np.array([float(a.start) for a in arcs])
        self.arc_sense = np.array([float(a.sense) for a in arcs])
        self.arc_span = np.array([a.span for a in arcs])

    def arcs_containing(self, angle: float) -> np.ndarray:
        """The indices (into ``items``, in order) of the arcs whose span holds the direction ``angle``
        (radians), ends included: :meth:`Arc.contains` of every arc."""
        return self.arcs[_in_span(angle, self.arc_start, self.arc_sense, self.arc_span)]


class _Paths:
    """The roller centre's paths at a block of cam angles seen from the cam (vectorized :class:`_Path`).

    Translating: ``Q(s) = base + s axis``; rocker: ``Q(s) = base + arm (cos(sigma s) ax + sin(sigma s) ay)``.
    """

    def __init__(self, design: CamDesign, centre: np.ndarray, phi: np.ndarray, s_design: np.ndarray):
        f = design.follower
        turn = -design.cam_sense * phi
        c, sn = np.cos(turn), np.sin(turn)

        def rot(v: np.ndarray) -> np.ndarray:
            return np.column_stack([c * v[0] - sn * v[1], sn * v[0] + c * v[1]])

        self.line = isinstance(f, Translating)
        if not self.line and not isinstance(f, Rocker):
            raise InputError("follower.kind", "the roller contact is defined for rocker and translating followers")
        pivot = np.zeros(2) if self.line else np.asarray(f.pivot, float)
        self.base = rot(pivot - np.asarray(centre, float))
        self.axis = np.column_stack([-sn, c])  # (0, 1) turned: a translating follower's rise
        self.ax = np.column_stack([c, sn])
        self.arm = float(f.arm) if isinstance(f, Rocker) else 0.0
        self.sigma = int(f.sense) if isinstance(f, Rocker) else 1
        self.window = s_design

    def param(self, q: np.ndarray) -> np.ndarray:
        """``s`` of points ``q`` (B, m, 2) on the paths (a rocker's within pi of the design's swing)."""
        d = q - self.base[:, None, :]
        if self.line:
            return np.einsum("bmk,bk->bm", d, self.axis)
        s = self.sigma * np.arctan2(np.einsum("bmk,bk->bm", d, self.axis), np.einsum("bmk,bk->bm", d, self.ax))
        w = self.window[:, None]
        return s + 2 * np.pi * np.round((w - s) / (2 * np.pi))

    def circles(self, c: np.ndarray, rad: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
        """Points (B, m, 2) of the paths at distance ``rad`` (m,) from ``c`` (m, 2), both roots, and validity."""
        w = c[None, :, :] - self.base[:, None, :]
        if self.line:
            ax = self.axis[:, None, :]
            t0 = np.einsum("bmk,bmk->bm", w, np.broadcast_to(ax, w.shape))
            perp = ax[..., 0] * w[..., 1] - ax[..., 1] * w[..., 0]
            h2 = rad[None, :] ** 2 - perp**2
            ok = h2 >= 0
            h = np.sqrt(np.where(ok, h2, 0.0))
            return [(self.base[:, None, :] + (t0 + sg * h)[..., None] * ax, ok) for sg in (1.0, -1.0)]
        dist = np.hypot(w[..., 0], w[..., 1])
        R1 = self.arm
        ok = (dist > 0) & (dist <= R1 + rad) & (dist >= np.abs(R1 - rad))
        dist = np.where(ok, dist, 1.0)
        a = (R1 * R1 - rad * rad + dist * dist) / (2 * dist)
        h = np.sqrt(np.maximum(R1 * R1 - a * a, 0.0))
        e = w / dist[..., None]
        je = np.stack([-e[..., 1], e[..., 0]], axis=-1)
        m = self.base[:, None, :] + a[..., None] * e
        return [(m + sg * h[..., None] * je, ok) for sg in (1.0, -1.0)]

    def lines(self, p: np.ndarray, d: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
        """Points (B, m, 2) of the paths on the lines through ``p`` (m, 2) along ``d`` (m, 2), and validity."""
        w = p[None, :, :] - self.base[:, None, :]
        if self.line:
            ax = self.axis[:, None, :]
            den = ax[..., 0] * d[None, :, 1] - ax[..., 1] * d[None, :, 0]
            ok = np.abs(den) > 1e-15
            t = (w[..., 0] * d[None, :, 1] - w[..., 1] * d[None, :, 0]) / np.where(ok, den, 1.0)
            return [(self.base[:, None, :] + t[..., None] * ax, ok)]
        t0 = -np.einsum("bmk,mk->bm", w, d)
        foot = p[None, :, :] + t0[..., None] * d[None, :, :]
        g = self.base[:, None, :] - foot
        h2 = self.arm**2 - np.einsum("bmk,bmk->bm", g, g)
        ok = h2 >= 0
        h = np.sqrt(np.where(ok, h2, 0.0))[..., None]
        return [(foot + sg * h * d[None, :, :], ok) for sg in (1.0, -1.0)]

    def near(self, c: np.ndarray, reach: np.ndarray) -> np.ndarray:
        """Which of the points ``c`` (m, 2) lie within ``reach`` (m,) of the path at some angle of the block."""
        w = c[None, :, :] - self.base[:, None, :]
        if self.line:
            off = np.abs(self.axis[:, None, 0] * w[..., 1] - self.axis[:, None, 1] * w[..., 0])
        else:
            off = np.abs(np.hypot(w[..., 0], w[..., 1]) - self.arm)
        return np.any(off <= reach[None, :], axis=0)

    def point(self, s: np.ndarray) -> np.ndarray:
        if self.line:
            return self.base + s[:, None] * self.axis
        th = self.sigma * s
        return self.base + self.arm * (np.cos(th)[:, None] * self.ax + np.sin(th)[:, None] * self.axis)

    def d1(self, s: np.ndarray) -> np.ndarray:
        if self.line:
            return self.axis.copy()
        th = self.sigma * s
        return self.sigma * self.arm * (-np.sin(th)[:, None] * self.ax + np.cos(th)[:, None] * self.axis)

    def d2(self, s: np.ndarray) -> np.ndarray:
        if self.line:
            return np.zeros_like(self.axis)
        return self.base - self.point(s)


class _Best:
    """The best touch per cam angle of a block: largest ``s``, its element, foot and offset curvature ``k``."""

    def __init__(self, n: int):
        self.s = np.full(n, -np.inf)
        self.own = np.full(n, -1)
        self.foot = np.zeros((n, 2))
        self.k = np.zeros(n)

    def offer(self, s: np.ndarray, ok: np.ndarray, own: np.ndarray, foot: np.ndarray, k: np.ndarray) -> None:
        """Candidates ``s`` (B, m) where ``ok``, of elements ``own`` (m,), feet (B, m, 2) or (m, 2), ``k`` (m,) or
        (B, m)."""
        if s.shape[1] == 0:
            return
        s = np.where(ok, s, -np.inf)
        j = np.argmax(s, axis=1)
        rows = np.arange(len(j))
        sj = s[rows, j]
        better = sj > self.s
        self.s = np.where(better, sj, self.s)
        self.own = np.where(better, own[j], self.own)
        fj = foot[rows, j] if foot.ndim == 3 else foot[j]
        self.foot = np.where(better[:, None], fj, self.foot)
        self.k = np.where(better, k[rows, j] if k.ndim == 2 else k[j], self.k)


def _block(els: _Elements, paths: _Paths, r: float, n: int) -> tuple[_Best, _Best]:
    """The best end-point touch and the best interior touch (segments, arcs) of a block of ``n`` cam angles."""
    vert, inner = _Best(n), _Best(n)
    k_vertex = 1.0 / r if r > 0 else np.inf
    slack = 1e-9 * max(els.size, 1.0)
    vj = np.flatnonzero(paths.near(els.verts, np.full(len(els.verts), r + slack)))
    for q, ok in paths.circles(els.verts[vj], np.full(len(vj), r)):
        # the path's curvature at the touch: 1/r about a corner; at a smooth joint the offset's of the element after
        # it, kappa / (1 - side kappa r) turned to this module's sign (side +1: the roller on the element's left)
        t = els.tangent[vj]
        w = q - els.verts[vj][None, :, :]
        left = np.where(t[None, :, 0] * w[..., 1] - t[None, :, 1] * w[..., 0] >= 0, 1.0, -1.0)
        kap = els.kappa[vj][None, :]
        with np.errstate(divide="ignore", invalid="ignore"):
            k_smooth = -left * kap / (1.0 - left * kap * r)
        k = np.where(els.smooth[vj][None, :], k_smooth, k_vertex)
        vert.offer(paths.param(q), ok, els.vert_owner[vj], els.verts[vj], k)
    near = paths.near(els.bc, els.br + r + slack)
    li = els.lines[near[els.lines]]
    if len(li):
        a, d, ln = els.la[li], els.ld[li], els.ll[li]
        jd = np.stack([-d[:, 1], d[:, 0]], axis=1)
        for side in (1.0, -1.0):
            for q, ok in paths.lines(a + side * r * jd, d):
                u = np.einsum("bmk,mk->bm", q - a[None, :, :], d)
                good = ok & (u >= 0) & (u <= ln[None, :])
                inner.offer(paths.param(q), good, li, a[None, :, :] + u[..., None] * d[None, :, :], np.zeros(len(li)))
    ai = els.arcs[near[els.arcs]]
    if len(ai):
        arcs = [cast(Arc, els.items[i]) for i in ai]
        c = np.array([a.centre for a in arcs], float).reshape(-1, 2)
        R = np.array([a.radius for a in arcs])
        start = np.array([a.start for a in arcs])
        sense = np.array([a.sense for a in arcs])
        span = np.array([a.span for a in arcs])
        for rad, k in ((R + r, 1.0 / (R + r)), (R - r, np.where(R > r, -1.0 / np.where(R > r, R - r, 1.0), 0.0))):
            live = rad > 0
            for q, ok in paths.circles(c, np.where(live, rad, 1.0)):
                w = q - c[None, :, :]
                ang = np.arctan2(w[..., 1], w[..., 0])
                inside = _in_span(ang, start[None, :], sense[None, :], span[None, :])
                foot = c[None, :, :] + R[None, :, None] * np.stack([np.cos(ang), np.sin(ang)], axis=-1)
                inner.offer(paths.param(q), ok & inside & live[None, :], ai, foot, k)
    return vert, inner


def _spline_best(els: _Elements, path: _Path, r: float) -> tuple[float, int, np.ndarray, float] | None:
    """The outermost touch of the roller with the spline pieces near its path at one cam angle, or None."""
    slack = 1e-9 * max(els.size, 1.0)
    sp = els.splines
    near = sp[path.near(els.bc[sp], els.br[sp] + r + slack)]
    best = None
    for i in near:
        for cand in _spline_touches(cast(SplinePiece, els.items[i]), int(i), path, r):
            if best is None or cand[0] > best[0]:
                best = cand
    return best


def _spline_touches(piece: SplinePiece, i: int, path: _Path, r: float) -> list[tuple[float, int, np.ndarray, float]]:
    """The touches of the roller with a spline piece's interior: roots in ``t`` of the offset point's distance off
    the path, bracketed on a grid of the piece and refined by Brent's method to machine precision."""

    out = []
    ts, grid_b, grid_n = piece.grid()
    for side in (1.0, -1.0):

        def offset(t, side: float = side) -> np.ndarray:
            b, b1, _ = piece.derivatives(t)
            return b + side * r * _unit_normal(b1)

        def f(t: float, offset=offset) -> float:
            return float(path.off(offset(t)))

        fs = path.off(grid_b + side * r * grid_n)  # offset(ts), its grid kept by the piece
        for t0, t1, f0, f1 in zip(ts[:-1], ts[1:], fs[:-1], fs[1:], strict=True):
            if f0 == 0:
                roots = [t0]
            elif f0 * f1 < 0:
                roots = [bracketed_root(f, t0, t1, xtol=1e-15, rtol=4 * np.finfo(float).eps, max_steps=200)]
            else:
                continue
            for t in roots:
                b, b1, b2 = piece.derivatives(t)
                kc = (b1[0] * b2[1] - b1[1] * b2[0]) / np.hypot(*b1) ** 3
                kap = -side * kc
                out.append((float(path.param(offset(t)[None, :])[0]), i, b, kap / (1.0 + kap * r) if r > 0 else kap))
    return out


def _roller_path(design: CamDesign, centre: np.ndarray, phi: float, s_design: float) -> _Path:
    f, eps = design.follower, design.cam_sense
    turn = -eps * phi
    base = rotate(-np.asarray(centre, float), turn)
    if isinstance(f, Translating):
        return _Path("line", base, rotate(np.array([0.0, 1.0]), turn), np.zeros(2), 0.0, 1, 0.0)
    if isinstance(f, Rocker):
        return _Path(
            "circle",
            base + rotate(f.pivot, turn),
            rotate(np.array([1.0, 0.0]), turn),
            rotate(np.array([0.0, 1.0]), turn),
            f.arm,
            f.sense,
            s_design,
        )
    raise InputError("follower.kind", "the roller contact is defined for rocker and translating roller followers")


def roller_contact(design: CamDesign, centre: np.ndarray, elements: list[Element], phi: np.ndarray) -> Contact:
    """The roller (or knife edge) in contact with the exported curve ``elements`` at cam angles ``phi``.

    Parameters
    ----------
    design : CamDesign
        The roller follower's design (follower, roller radius, cam sense).
    centre : array_like, shape (2,)
        Cam centre in the fixed frame (``SolveResult.centre``), length unit.
    elements : list of Line, Arc, SplinePiece
        The working profile, cam frame, a closed chain.
    phi : ndarray
        Cam angles, radians.

    Returns
    -------
    Contact
        Exact position on the element in contact (module notes), its derivatives by implicit differentiation.

    Raises
    ------
    InputError
        The curve is not closed; the roller's path does not touch it at some angle.
    """
    check_closed(elements)
    els = _Elements(elements)
    r = design.follower.roller_radius
    eps = design.cam_sense
    phi = np.atleast_1d(np.asarray(phi, float))
    s_all = design.program.evaluate(phi).s
    out = np.empty((3, len(phi)))
    which = np.empty(len(phi), int)
    block = 32  # contiguous angles: the elements near their paths are few
    tie = 1e-12 * max(els.size, 1.0)
    for b0 in range(0, len(phi), block):
        ph, s_d = phi[b0 : b0 + block], s_all[b0 : b0 + block]
        paths = _Paths(design, centre, ph, s_d)
        vert, inner = _block(els, paths, r, len(ph))
        if len(els.splines):
            for k in range(len(ph)):
                best = _spline_best(els, _roller_path(design, centre, float(ph[k]), float(s_d[k])), r)
                if best is not None and best[0] > inner.s[k]:
                    inner.s[k], inner.own[k], inner.foot[k], inner.k[k] = best
        # a tie with an interior touch (an end point joining two elements smoothly): the element's side wins
        take = inner.s >= np.maximum(vert.s, inner.s) - tie
        s = np.where(take, inner.s, vert.s)
        if not np.all(np.isfinite(s)):
            at = float(ph[np.flatnonzero(~np.isfinite(s))[0]])
            raise InputError(
                "PROFILE",
                f"the follower does not touch the curve at cam angle {np.degrees(at):.6g} "
                "deg: is it this design's profile, in its cam frame?",
            )
        own = np.where(take, inner.own, vert.own)
        foot = np.where(take[:, None], inner.foot, vert.foot)
        kk = np.where(take, inner.k, vert.k)
        q, qs, qss = paths.point(s), paths.d1(s), paths.d2(s)
        qp = -eps * perp(q)  # dQ/dphi: the cam frame turns by -eps phi
        qpp = -q
        qsp = -eps * perp(qs)
        if r > 0:
            n = (q - foot) / r
        else:
            n = np.array([_knife_normal(els.items[i], foot[k], q[k], qs[k]) for k, i in enumerate(own)])
        t = perp(n)

        def dot(u: np.ndarray, v: np.ndarray) -> np.ndarray:
            return np.einsum("bk,bk->b", u, v)

        Fs, Fp = dot(n, qs), dot(n, qp)
        ts, tp = dot(t, qs), dot(t, qp)
        with np.errstate(invalid="ignore"):  # a knife edge on a vertex: k infinite, its acceleration too
            Fss = kk * ts * ts + dot(n, qss)
            Fsp = kk * ts * tp + dot(n, qsp)
            Fpp = kk * tp * tp + dot(n, qpp)
        d1 = -Fp / Fs
        d2 = -(Fss * d1 * d1 + 2 * Fsp * d1 + Fpp) / Fs
        d2[~np.isfinite(kk)] = np.inf  # a knife edge on a corner: its velocity jumps, the acceleration is unbounded
        out[:, b0 : b0 + block] = (s, d1, d2)
        which[b0 : b0 + block] = own
    return Contact(phi, out[0], out[1], out[2], which)


def _knife_normal(e: Element, foot: np.ndarray, q: np.ndarray, qs: np.ndarray) -> np.ndarray:
    """A knife edge's contact normal: the element's normal at the contact, on the side the path leaves by."""
    if isinstance(e, Line):
        a, b = e.ends
        n = perp((b - a) / np.hypot(*(b - a)))
    elif isinstance(e, Arc):
        d = foot - np.asarray(e.centre, float)
        n = d / np.hypot(*d)
    else:
        # the foot's parameter is not kept: the normal of the nearest of a few points is enough for its side
        ts = np.linspace(0, 1, 65)
        j = int(np.argmin([np.hypot(*(e.derivatives(t)[0] - foot)) for t in ts]))
        b1 = e.derivatives(ts[j])[1]
        n = _unit_normal(b1)
    return n if float(n @ qs) > 0 else -n


# -- a flat face --------------------------------------------------------------------------------------------------


def _support(els: _Elements, theta: float) -> tuple[float, float, float, int]:
    """The curve's support function at the normal angle ``theta``: ``h, h_theta, h_thetatheta`` and the element."""

    m = np.array([np.cos(theta), np.sin(theta)])
    mt = perp(m)
    best: tuple[float, np.ndarray, float, int] | None = None

    tie = 1e-12 * max(els.size, 1.0)

    def take(h: float, x: np.ndarray, rho: float, i: int) -> None:
        # an element's interior wins a tie with an end point (a smooth joint): its curvature is the one
        nonlocal best
        if best is None or h > best[0] + (-tie if rho != 0 else 0.0):
            best = (h, x, rho, i)

    hv = els.joints @ m  # every joint: between two arcs that a rounding kink leaves apart, a joint is the support
    j = int(np.argmax(hv))
    take(float(hv[j]), els.joints[j], 0.0, j)
    for i in els.arcs_containing(theta):
        arc = cast(Arc, els.items[i])
        c = np.asarray(arc.centre, float)
        take(float(c @ m) + arc.radius, c + arc.radius * m, arc.radius, int(i))
    for i in els.splines:
        piece = cast(SplinePiece, els.items[i])
        c, rad = els.bc[i], els.br[i]
        if best is not None and float(c @ m) + rad < best[0]:
            continue

        def g(t, piece=piece):
            return piece.derivatives(t)[1] @ m

        ts = np.linspace(0.0, 1.0, 17)
        gs = g(ts)
        for t0, t1, g0, g1 in zip(ts[:-1], ts[1:], gs[:-1], gs[1:], strict=True):
            if g0 > 0 >= g1:  # a maximum of B . m
                t = bracketed_root(g, t0, t1, xtol=1e-15, rtol=4 * np.finfo(float).eps, max_steps=200)
                b, b1, b2 = piece.derivatives(t)
                kc = abs(b1[0] * b2[1] - b1[1] * b2[0]) / np.hypot(*b1) ** 3
                take(float(b @ m), b, 1.0 / kc if kc > 0 else np.inf, int(i))
    assert best is not None
    h, x, rho, owner = best
    return h, float(x @ mt), rho - h, owner


def flat_contact(design: FlatFaceDesign, R0: float, elements: list[Element], phi: np.ndarray) -> Contact:
    """A flat face in contact with the exported curve ``elements`` at cam angles ``phi`` (module notes).

    Parameters
    ----------
    design : FlatFaceDesign
    R0 : float
        The base radius the cam was sized to (length): a translating face's distance from the cam centre at
        ``s = 0``; a rocker's sets its face angle at the near dwell.
    elements : list of Line, Arc, SplinePiece
        The profile in the flat profile's cam frame (a rocker's: the line-of-centres frame).
    phi : ndarray
        Cam angles, radians.
    """

    from cams.kinematics.flat import oscillating_setup

    check_closed(elements)
    els = _Elements(elements)
    fo, eps, prog = design.follower, design.cam_sense, design.program
    phi = np.atleast_1d(np.asarray(phi, float))
    s_d = prog.evaluate(phi).s
    out = np.empty((3, len(phi)))
    which = np.empty(len(phi), int)
    if isinstance(fo, FlatTranslating):
        for k, ph in enumerate(phi):
            h, ht, htt, i = _support(els, np.pi / 2 - eps * ph)
            out[:, k] = (h - R0, -eps * ht, htt)
            which[k] = i
        return Contact(phi, out[0], out[1], out[2], which)
    if not isinstance(fo, FlatRocker):
        raise InputError("follower.kind", "a flat face is a translating or rocker follower")
    L, f, sg = fo.centre_distance, fo.face_offset, fo.sense
    a0 = oscillating_setup(prog, L, R0, f, sg)
    for k, ph in enumerate(phi):

        def G(a: float, ph=ph) -> float:
            return f - L * np.cos(a) - _support(els, a - eps * ph)[0]

        ad = a0 + sg * s_d[k]
        lo, hi, step = ad, ad, 1e-3
        while G(lo) * G(hi) > 0:
            lo, hi, step = ad - step, ad + step, 2 * step
            if step > 1.0:
                raise InputError(
                    "PROFILE",
                    f"the face does not touch the curve near cam angle {np.degrees(ph):.6g} "
                    "deg: is it this design's profile, in its cam frame?",
                )
        a = bracketed_root(G, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps, max_steps=200) if lo != hi else ad
        _, ht, htt, i = _support(els, a - eps * ph)
        Ga, Gp = L * np.sin(a) - ht, eps * ht
        Gaa, Gap, Gpp = L * np.cos(a) - htt, eps * htt, -htt
        a1 = -Gp / Ga
        a2 = -(Gaa * a1 * a1 + 2 * Gap * a1 + Gpp) / Ga
        out[:, k] = (sg * (a - a0), sg * a1, sg * a2)
        which[k] = i
    return Contact(phi, out[0], out[1], out[2], which)


# -- the errors against the design --------------------------------------------------------------------------------


@dataclass(frozen=True)
class ExportMotion:
    """The largest errors of the motion an exported curve gives against the design's law.

    Attributes
    ----------
    max_ds, max_dv, max_da : float
        Largest ``|s - s_design|``, ``|s' - s'_design|``, ``|s'' - s''_design|`` over the angles checked (length,
        length/rad, length/rad^2; a rocker's rad, rad/rad, rad/rad^2).
    lift, peak_velocity, peak_acceleration : float
        The law's lift and peaks (same units), the shares' denominators.
    rocker : bool
        The displacement is a swing (radians).
    elements : int
        Number of elements of the curve.
    contact : Contact
        The contact at the angles checked.
    """

    max_ds: float
    max_dv: float
    max_da: float
    lift: float
    peak_velocity: float
    peak_acceleration: float
    rocker: bool
    elements: int
    contact: Contact = field(repr=False)

    @property
    def ds_ratio(self) -> float:
        return self.max_ds / self.lift

    @property
    def dv_ratio(self) -> float:
        return self.max_dv / self.peak_velocity if self.peak_velocity > 0 else float("inf")

    @property
    def da_ratio(self) -> float:
        return self.max_da / self.peak_acceleration if self.peak_acceleration > 0 else float("inf")

    def to_dict(self) -> dict:
        """JSON-ready errors: ``max_ds`` (mm, a rocker's deg), ``max_dv`` (mm/rad or deg/rad), ``max_da``
        (mm/rad^2 or deg/rad^2), ``max_da_ratio`` (share of the law's peak acceleration) and ``elements``; None
        where unbounded (a knife edge on a corner of the curve)."""
        k = float(np.degrees(1.0)) if self.rocker else 1.0

        def finite(v: float) -> float | None:
            return float(v) if np.isfinite(v) else None

        return {
            "elements": self.elements,
            "max_ds": finite(k * self.max_ds),
            "max_dv": finite(k * self.max_dv),
            "max_da": finite(k * self.max_da),
            "max_da_ratio": finite(self.da_ratio),
        }


def _end_tangents(e: Element) -> tuple[np.ndarray, np.ndarray]:
    """Unit tangents of an element at its start and its end, in its direction of travel."""
    if isinstance(e, Line):
        a, b = e.ends
        t = (b - a) / np.hypot(*(b - a))
        return t, t
    if isinstance(e, Arc):
        out = []
        for ang in (e.start, e.start + e.sense * e.span):
            out.append(e.sense * np.array([-np.sin(ang), np.cos(ang)]))
        return out[0], out[1]
    t0, t1 = e.derivatives(0.0)[1], e.derivatives(1.0)[1]
    return t0 / np.hypot(*t0), t1 / np.hypot(*t1)


def _start_curvature(e: Element) -> float:
    """An element's signed curvature at its start (1/length, positive where it turns left, counter-clockwise)."""
    if isinstance(e, Line):
        return 0.0
    if isinstance(e, Arc):
        return e.sense / e.radius
    _, b1, b2 = e.derivatives(0.0)
    return float((b1[0] * b2[1] - b1[1] * b2[0]) / np.hypot(*b1) ** 3)


def _joint_turns(elements: list[Element]) -> np.ndarray:
    """The angle (radians, >= 0) by which the closed chain's tangent turns at each element's start (the joint with
    the element before it)."""
    with np.errstate(divide="ignore", invalid="ignore"):  # a zero-length line: no tangent, NaN, a corner
        tangents = [_end_tangents(e) for e in elements]
    out = np.zeros(len(tangents))
    for i, (t_start, _) in enumerate(tangents):
        t_prev = tangents[i - 1][1]
        out[i] = np.arctan2(abs(t_prev[0] * t_start[1] - t_prev[1] * t_start[0]), t_prev @ t_start)
    return out


def corners(elements: list[Element], angle: float = 1e-9) -> int:
    """How many joints of the closed chain turn its tangent by more than ``angle`` (radians): its corners."""
    return int(np.count_nonzero(_joint_turns(elements) > angle))


def check_angles(
    design: CamDesign | FlatFaceDesign, elements: int, per_element: int = 4, least: int = 3600
) -> np.ndarray:
    """The cam angles the errors are checked at: uniform, ``max(least, per_element * elements)`` a turn, with the
    phase starts (radians)."""
    n = int(min(max(least, per_element * elements), 200_000))
    phi = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    return np.unique(np.concatenate([phi, np.asarray(design.program.starts, float) % (2 * np.pi)]))


def _law_errors(design: CamDesign | FlatFaceDesign, c: Contact) -> np.ndarray:
    """``|s - s_law|``, ``|s' - s'_law|``, ``|s'' - s''_law|`` at the contact's angles, shape (3, n); at a phase
    joint the smaller of the errors against the law's two one-sided values."""
    prog = design.program
    m = prog.evaluate(c.phi)
    got = (c.s, c.ds, c.d2s)
    err = np.array([np.abs(g - w) for g, w in zip(got, (m.s, m.ds, m.d2s), strict=True)])
    starts = np.asarray(prog.starts, float) % (2 * np.pi)
    n = len(prog.phases)
    for j, a in enumerate(starts):
        at = np.flatnonzero(np.abs((c.phi - a + np.pi) % (2 * np.pi) - np.pi) < 1e-12)
        if len(at) == 0:
            continue
        left = prog.evaluate_phase((j - 1) % n, np.ones(1))
        for k, (g, w) in enumerate(zip(got, (left.s, left.ds, left.d2s), strict=True)):
            err[k, at] = np.minimum(err[k, at], np.abs(g[at] - w[0]))
    return err


def export_motion(
    design: CamDesign | FlatFaceDesign,
    elements: list[Element],
    *,
    centre: np.ndarray | None = None,
    R0: float | None = None,
    phi: np.ndarray | None = None,
) -> ExportMotion:
    """The largest errors in displacement, velocity and acceleration of the motion the curve gives.

    A knife edge (roller radius 0) on a curve with corners (:func:`corners`) has an unbounded acceleration error:
    its velocity jumps where it crosses each corner, whichever angles are checked.

    The contact (:func:`roller_contact` with ``centre``, :func:`flat_contact` with ``R0``) is compared with the
    design's law at the angles ``phi`` (default :func:`check_angles`: the maximum is over these angles; on each
    element the motion is exact). At a phase joint the law's nearer one-sided value is taken (a law whose
    acceleration jumps there has both).
    """
    from cams.kinematics.peaks import motion_peaks

    phi = check_angles(design, len(elements)) if phi is None else np.atleast_1d(np.asarray(phi, float))
    if isinstance(design.follower, FlatTranslating | FlatRocker):
        if R0 is None:
            raise InputError("R0", "a flat face's contact needs the base radius")
        c = flat_contact(design, R0, elements, phi)
    else:
        if centre is None:
            raise InputError("centre", "a roller's contact needs the cam centre")
        c = roller_contact(design, centre, elements, phi)
    err = _law_errors(design, c)
    rocker = design.follower.kind == "rocker"
    max_da = float(np.max(err[2]))
    f = design.follower
    if isinstance(f, Rocker | Translating) and f.roller_radius == 0 and corners(elements):
        max_da = float("inf")  # a knife edge crosses each corner with a jump of its velocity: unbounded
    pk = motion_peaks(design.program, rocker=rocker)
    vel = pk.velocity.value
    acc = pk.acceleration.value
    return ExportMotion(
        max_ds=float(np.max(err[0])),
        max_dv=float(np.max(err[1])),
        max_da=max_da,
        lift=float(design.program.lift),
        peak_velocity=float("inf") if vel is None else float(vel),
        peak_acceleration=float("inf") if acc is None else float(acc),
        rocker=rocker,
        elements=len(elements),
        contact=c,
    )
