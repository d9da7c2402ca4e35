"""The cam's exported curves as exact functions: what the arcs and the spline of the exports are fitted to.

A sampled profile (:class:`cams.profile.roller.Profile`, :class:`cams.profile.flat.FlatFaceProfile`) is a
polyline; the curve fits of :mod:`cams.manufacture.curves` need the curve itself, at any point. An
:class:`ExactCurve` is a closed curve in the cam frame (origin at the cam centre, the cam at ``phi = 0``;
:mod:`cams.kinematics.inversion`) cut into smooth :class:`ExactPiece` s, each a function of ``u`` in [0, 1]
giving points (length) and unit tangents in the direction of travel (the direction of growing cam angle). The
pieces follow one another round the curve from cam angle 0: one per ``[[motion]]`` phase, and where the sampled
profile has one at a phase joint a circular arc (a roller's circle filling the gap of an offset curve at a
corner of the pitch curve) or a straight join (the two ends of an offset curve that crosses itself at a corner,
as the polyline joins them; a flat face's straight edge where the follower's velocity jumps up).

:class:`ExactCam` holds a cam's curves by the drawing layer they go to (``PROFILE`` the working profile,
``OUTER`` a groove's outer wall, ``PITCH`` the pitch curve) and the timing datum: the unit direction, cam frame,
from the cam centre to the roller centre at cam angle 0 (a flat face: the contact normal there), where the first
``[[motion]]`` row starts.

Angles in radians; lengths in the design's unit (mm).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

__all__ = ["ExactPiece", "ExactCurve", "ExactCam", "roller_exact", "flat_exact"]

#: A piece's evaluation: ``u`` (n,) -> points (n, 2) and unit tangents (n, 2), cam frame.
Evaluate = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]


@dataclass(frozen=True, eq=False)
class ExactPiece:
    """One smooth piece of an exact curve, ``u`` in [0, 1].

    Attributes
    ----------
    evaluate : callable
        ``u -> (points, tangents)``: points (length) and unit tangents, cam frame, shape ``(n, 2)`` each.
    kind : {"curve", "arc", "line"}
        A phase's curve, a circular arc at a joint (exact: one arc element), a straight join (one line).
    phase : int
        The ``[[motion]]`` phase (a joint's piece: the phase it leads into).
    """

    evaluate: Evaluate
    kind: str
    phase: int


@dataclass(frozen=True, eq=False)
class ExactCurve:
    """A closed curve of the cam: its pieces in order round the curve from cam angle 0."""

    pieces: tuple[ExactPiece, ...]


@dataclass(frozen=True, eq=False)
class ExactCam:
    """A cam's exact curves by drawing layer and its timing datum.

    Attributes
    ----------
    curves : dict
        Layer name (``"PROFILE"``, ``"OUTER"``, ``"PITCH"``) to :class:`ExactCurve`, in drawing order.
    datum : ndarray, shape (2,)
        Unit vector, cam frame: from the cam centre to the roller centre at cam angle 0 (a flat face: the contact
        normal at cam angle 0).
    """

    curves: dict[str, ExactCurve]
    datum: np.ndarray


def _unit(v: np.ndarray) -> np.ndarray:
    n = np.hypot(v[..., 0], v[..., 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        return v / n[..., None]


def _line(a: np.ndarray, b: np.ndarray, phase: int) -> ExactPiece:
    """The straight piece from ``a`` to ``b``."""
    t = _unit(b - a)

    def ev(u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        u = np.asarray(u, float)
        return a + u[:, None] * (b - a), np.repeat(t[None], len(u), 0)

    return ExactPiece(ev, "line", phase)


def _arc(c: np.ndarray, radius: float, a1: float, a2: float, phase: int) -> ExactPiece:
    """The arc of the circle about ``c`` of ``radius`` from polar angle ``a1`` to ``a2`` (radians, the short way
    round)."""
    da = (a2 - a1 + np.pi) % (2 * np.pi) - np.pi

    def ev(u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        t = a1 + np.asarray(u, float) * da
        cs = np.stack([np.cos(t), np.sin(t)], axis=-1)
        tan = np.sign(da) * np.stack([-np.sin(t), np.cos(t)], axis=-1)
        return c + radius * cs, tan

    return ExactPiece(ev, "arc", phase)


def _close(pieces: list[ExactPiece], gap: float) -> ExactCurve:
    """The pieces with a straight join wherever one ends more than ``gap`` from where the next begins."""
    out: list[ExactPiece] = []
    for k, p in enumerate(pieces):
        out.append(p)
        q = pieces[(k + 1) % len(pieces)]
        end, start = p.evaluate(np.array([1.0]))[0][0], q.evaluate(np.array([0.0]))[0][0]
        if np.hypot(*(start - end)) > gap:
            out.append(_line(end, start, q.phase))
    return ExactCurve(tuple(out))


def roller_exact(design, centre: np.ndarray) -> ExactCam:
    """The exact curves of a roller (or knife-edge) follower's cam about ``centre`` (fixed frame, length).

    ``PROFILE`` the working profile ``P - r n``, ``PITCH`` the pitch curve ``P``, ``OUTER`` (form closure) the
    outer wall ``P + r n`` (:mod:`cams.profile.roller`'s conventions). An offset's tangent is the pitch curve's,
    reversed where the offset has passed its cusp (``1 + d kappa < 0``). At a phase joint where the pitch curve
    has a corner the offset on its concave side gets the roller's circle about the corner (as
    :func:`cams.profile.roller.build_profile`), the other a straight join of its two ends.
    """
    from cams.kinematics.inversion import pitch_phase

    centre = np.asarray(centre, dtype=float)
    r = float(design.follower.roller_radius)
    eps = design.cam_sense
    nph = len(design.program.phases)
    groove = design.limits.closure == "form" and r > 0
    offsets = {"PROFILE": -r, "PITCH": 0.0}
    if groove:
        offsets = {"PROFILE": -r, "OUTER": r, "PITCH": 0.0}
    scale = float(np.linalg.norm(design.follower.position(0.0) - centre))
    curves: dict[str, ExactCurve] = {}
    for layer, d in offsets.items():
        pieces: list[ExactPiece] = []
        for i in range(nph):

            def ev(u: np.ndarray, i: int = i, d: float = d) -> tuple[np.ndarray, np.ndarray]:
                g = pitch_phase(design, centre, i, np.asarray(u, float))
                t = _unit(g.d1)
                if d != 0:
                    t = t * np.where(1.0 + d * g.kappa < 0, -1.0, 1.0)[:, None]
                return g.offset(d), t

            pieces.append(ExactPiece(ev, "curve", i))
            if d == 0:
                continue
            j = (i + 1) % nph
            end = pitch_phase(design, centre, i, np.array([1.0]))
            start = pitch_phase(design, centre, j, np.array([0.0]))
            n1, n2 = end.normal[0], start.normal[0]
            if not np.linalg.norm(n1 - n2) > 1e-12:
                continue
            cr = end.d1[0][0] * start.d1[0][1] - end.d1[0][1] * start.d1[0][0]
            convex = np.sign(cr) == -eps
            if (d < 0) != convex:  # the concave side's offset: the roller's circle about the corner
                a1, a2 = np.arctan2(*(np.sign(d) * n1)[::-1]), np.arctan2(*(np.sign(d) * n2)[::-1])
                arc = _arc(start.point[0], abs(d), float(a1), float(a2), j)
                if j == 0:
                    pieces.insert(0, arc)  # phi = 2 pi is phi = 0: the closing joint's arc comes first
                else:
                    pieces.append(arc)
        curves[layer] = _close(pieces, 1e-12 * max(scale, 1.0))
    datum = _unit(design.follower.position(0.0) - centre)
    return ExactCam(curves, datum)


def flat_exact(design, R0: float) -> ExactCam:
    """The exact profile of a flat-faced follower's cam of base radius ``R0`` (length): the envelope of the face
    lines (:func:`cams.kinematics.flat.envelope`), one piece per phase, a straight edge where the follower's
    velocity jumps up. The envelope's tangent is ``t(theta)`` turned by the sign of ``rho theta'`` (its point
    moves as ``dX/dphi = rho theta' t``); the datum is the face's normal at cam angle 0."""
    from cams.kinematics.flat import envelope, oscillating_setup, oscillating_terms
    from cams.model.follower import FlatTranslating

    fo, prog, eps = design.follower, design.program, design.cam_sense

    def terms(i: int, u: np.ndarray):
        if isinstance(fo, FlatTranslating):
            m = prog.evaluate_phase(i, u)
            phi = prog.starts[i] + u * prog.phases[i].angle
            one = np.ones_like(u)
            return np.pi / 2 - eps * phi, -eps * one, 0.0 * one, R0 + m.s, m.ds, m.d2s
        a0 = oscillating_setup(prog, fo.centre_distance, R0, fo.face_offset, fo.sense)
        return oscillating_terms(prog, fo.centre_distance, fo.face_offset, fo.sense, eps, a0, phase=i, u=u)[2:]

    pieces = []
    for i in range(len(prog.phases)):

        def ev(u: np.ndarray, i: int = i) -> tuple[np.ndarray, np.ndarray]:
            th, dth, d2th, p, dp, d2p = terms(i, np.asarray(u, float))
            X, rho, _ = envelope(th, dth, d2th, p, dp, d2p)
            t = np.stack([-np.sin(th), np.cos(th)], axis=-1)
            return X, t * np.where(rho * dth < 0, -1.0, 1.0)[:, None]

        pieces.append(ExactPiece(ev, "curve", i))
    th0 = terms(0, np.array([0.0]))[0][0]
    datum = np.array([np.cos(th0), np.sin(th0)])
    return ExactCam({"PROFILE": _close(pieces, 1e-12 * max(R0, 1.0))}, datum)
