"""The one inversion: a roller (or knife-edge) follower's pitch curve and what follows from it.

Frames and signs
----------------
* Fixed frame: the follower's frame of :mod:`cams.model.follower`; the cam centre O
  is given in it (``SolveResult.centre``).
* Cam frame: origin at the cam centre, axes parallel to the fixed frame when
  the cam is at ``phi = 0``, turning with the cam. A point with cam-frame
  coordinates ``X`` is at ``O + R(eps phi) X`` in the fixed frame
  (:func:`to_fixed_frame`), with ``eps = design.cam_sense`` (+1 counter-clockwise).
* Pitch curve (roller-centre path on the cam), by inversion of the motion::

      P(phi) = R(-eps phi) (A(s(phi)) - O)

  It runs round the cam centre in the sense ``-eps`` as ``phi`` grows. With
  ``D v = v' - eps J v`` (a derivative seen from the turning cam, ``J`` the
  rotation by +90 degrees) its derivatives by the cam angle are
  ``P^(k) = R(-eps phi) D^k r``, ``r = A - O``::

      w1 = D r  = r' - eps J r
      w2 = D w1 = r'' - 2 eps J r' - r
      w3 = D w2 = r''' - 3 eps J r'' - 3 r' + eps J r

  where ``r' = s' T``, ``r'' = s'' T + s'^2 T2``,
  ``r''' = s''' T + 3 s' s'' T2 + s'^3 T3`` and ``T, T2, T3`` are ``dA/ds``
  and its derivatives. A rocker's roller centre turns about the pivot, so
  ``T2 = -(A - pivot)`` and ``T3 = -T``; a translating follower's moves on a
  line, ``T2 = T3 = 0``. :class:`Inversion` holds ``r, w1, w2, w3`` in the
  fixed frame's orientation (before the turn ``R(-eps phi)`` into the cam frame).
* Outward normal ``n``: the unit normal of the pitch curve pointing away from
  the cam's material, ``n = eps J w1 / |w1|`` in the fixed frame
  (:func:`contact_normal`: the line of the cam's force on the roller), turned
  into the cam frame by ``R(-eps phi)`` (:func:`outward_normal`).
* Signed curvature ``kappa = -eps (w1 x w2) / |w1|^3`` (:func:`curvature`) and
  radius of curvature ``rho = 1 / kappa``: **positive where the curve is
  convex** (centre of curvature on the cam's side), negative where concave. On
  a dwell the pitch curve is a circle of radius ``|A - O|`` and ``rho = +|A - O|``.
  An offset curve ``P + d n`` has ``rho + d`` (:func:`offset_radius`).
* Pressure angle ``gamma`` (:func:`pressure_angle`): the angle between the
  contact normal and the roller centre's direction of rise ``e = T / |T|``,
  in [0, pi]; above pi/2 the cam would pull, not push.

Angles are radians; lengths are the design's unit (mm). Every function is
vectorized over the cam angles.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import numpy as np

from cams.kinematics.extremum import maximize, phase_positions
from cams.kinematics.vectors import cross, dot, norm, rotate, xy
from cams.model.design import CamDesign
from cams.model.follower import Rocker, Translating
from laws.errors import InputError
from laws.program import Motion

__all__ = [
    "Inversion",
    "invert",
    "invert_phase",
    "invert_at",
    "contact_normal",
    "outward_normal",
    "rise_direction",
    "curvature",
    "curvature_rate",
    "pressure_angle",
    "pressure_rate",
    "PitchGeometry",
    "pitch_geometry",
    "pitch_phase",
    "pitch_curve",
    "offset_radius",
    "offset_curvature",
    "to_fixed_frame",
    "smallest_cam_radius",
    "largest_cam_radius",
]


@dataclass(frozen=True, eq=False)
class Inversion:
    """The follower's motion inverted at cam angles ``phi``: vectors in the fixed frame's orientation.

    Turned by ``R(-eps phi)`` (:meth:`to_cam`) the vectors ``r, w1, w2, w3``
    give the pitch point and its derivatives in the cam frame.

    Attributes
    ----------
    phi : ndarray, shape (n,)
        Cam angles, radians.
    sense : {+1, -1}
        The cam's sense of rotation ``eps`` (+1 counter-clockwise).
    s, ds : ndarray, shape (n,)
        Follower displacement (radians or length) and ``s' = ds/dphi``.
    r : ndarray, shape (n, 2)
        ``A - O``, length unit (turned: the pitch point ``P``).
    w1, w2 : ndarray, shape (n, 2)
        Turned: ``dP/dphi`` (length per radian) and ``d2P/dphi2`` (per radian^2).
    w3 : ndarray, shape (n, 2), or None
        Turned: ``d3P/dphi3`` (per radian^3); ``None`` unless asked for.
    t, t2 : ndarray, shape (n, 2)
        The follower's ``dA/ds`` and ``d2A/ds2``, fixed frame.
    """

    phi: np.ndarray
    sense: int
    s: np.ndarray
    ds: np.ndarray
    r: np.ndarray
    w1: np.ndarray
    w2: np.ndarray
    w3: np.ndarray | None
    t: np.ndarray
    t2: np.ndarray

    def to_cam(self, v: np.ndarray) -> np.ndarray:
        """Vectors at these cam angles turned from the fixed frame's orientation into the cam frame.

        That is ``R(-eps phi) v``.
        """
        return rotate(v, -self.sense * self.phi)

    @property
    def point(self) -> np.ndarray:
        """The pitch point ``P``, cam frame, length unit."""
        return self.to_cam(self.r)

    @property
    def d1(self) -> np.ndarray:
        """``dP/dphi``, cam frame, length per radian."""
        return self.to_cam(self.w1)

    @property
    def d2(self) -> np.ndarray:
        """``d2P/dphi2``, cam frame, length per radian^2."""
        return self.to_cam(self.w2)


def invert(design: CamDesign, centre: np.ndarray, phi: np.ndarray, motion: Motion, *,
           third: bool = False) -> Inversion:
    """The inversion at cam angles ``phi`` of the motion ``motion`` (the one home of the formula).

    Parameters
    ----------
    design : CamDesign
        A roller or knife-edge follower's design.
    centre : array_like, shape (2,)
        Cam centre O, fixed frame, length unit.
    phi : ndarray, shape (n,)
        Cam angles, radians.
    motion : laws.program.Motion
        Follower displacement ``s`` and its derivatives by the cam angle at ``phi``.
    third : bool
        Also compute ``w3`` (from ``motion.d3s``).

    Returns
    -------
    Inversion

    Raises
    ------
    InputError
        The follower is not a roller or knife-edge follower.
    """
    f = design.follower
    eps = design.cam_sense
    centre = np.asarray(centre, dtype=float)
    A, T, _ = f.frame(np.asarray(motion.s, dtype=float))
    tx, ty = T[..., 0], T[..., 1]
    if isinstance(f, Rocker):
        px, py = f.pivot
        bx, by = px - A[..., 0], py - A[..., 1]
        cx, cy = -tx, -ty
    elif isinstance(f, Translating):
        bx = by = cx = cy = np.zeros_like(tx)
    else:
        raise InputError("follower.kind", "the pitch curve is defined for rocker and translating roller followers")
    rx, ry = A[..., 0] - centre[0], A[..., 1] - centre[1]
    s1, s2 = motion.ds, motion.d2s
    r1x, r1y = s1 * tx, s1 * ty
    q = s1**2
    r2x, r2y = s2 * tx + q * bx, s2 * ty + q * by
    w3 = None
    if third:
        k2, k3 = 3 * s1 * s2, s1**3
        r3x, r3y = motion.d3s * tx + k2 * bx + k3 * cx, motion.d3s * ty + k2 * by + k3 * cy
        w3 = xy(r3x + 3 * eps * r2y - 3 * r1x - eps * ry, r3y - 3 * eps * r2x - 3 * r1y + eps * rx)
    return Inversion(
        phi=np.asarray(phi, dtype=float),
        sense=eps,
        s=np.asarray(motion.s, dtype=float),
        ds=np.asarray(s1, dtype=float),
        r=xy(rx, ry),
        w1=xy(r1x + eps * ry, r1y - eps * rx),
        w2=xy(r2x + 2 * eps * r1y - rx, r2y - 2 * eps * r1x - ry),
        w3=w3,
        t=xy(tx, ty),
        t2=xy(bx, by),
    )


def invert_phase(design: CamDesign, centre: np.ndarray, phase: int, u: np.ndarray, *,
                 third: bool = False) -> Inversion:
    """:func:`invert` inside one phase at normalized positions ``u`` in [0, 1].

    Values at the phase ends are the one-sided limits from inside the phase
    (:meth:`laws.program.Program.evaluate_phase`), so a corner or a jump at a
    phase joint is seen from both sides; ``phi = starts[phase] + u * angle``.
    """
    prog = design.program
    u = np.atleast_1d(np.asarray(u, dtype=float))
    phi = prog.starts[phase] + u * prog.phases[phase].angle
    return invert(design, centre, phi, prog.evaluate_phase(phase, u), third=third)


def invert_at(design: CamDesign, centre: np.ndarray, phi: np.ndarray, *, third: bool = False) -> Inversion:
    """:func:`invert` at cam angles ``phi`` (radians, periodic); at a phase joint the later phase's values."""
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    return invert(design, centre, phi, design.program.evaluate(phi), third=third)


def _normal_components(inv: Inversion) -> tuple[np.ndarray, np.ndarray]:
    """The contact normal ``eps J w1 / |w1|`` as components ``(x, y)``, fixed frame."""
    eps = inv.sense
    wx, wy = inv.w1[..., 0], inv.w1[..., 1]
    speed = np.sqrt(wx * wx + wy * wy)
    with np.errstate(divide="ignore", invalid="ignore"):
        return -eps * wy / speed, eps * wx / speed


def contact_normal(inv: Inversion) -> np.ndarray:
    """The pitch curve's outward unit normal in the fixed frame, ``n = eps J w1 / |w1|``.

    The line of the cam's force on the roller (no friction at the roller),
    pointing away from the cam. NaN where ``w1 = 0`` (the roller centre on the
    cam centre with no motion: undefined).

    Returns
    -------
    ndarray, shape (n, 2)
    """
    return xy(*_normal_components(inv))


def outward_normal(inv: Inversion) -> np.ndarray:
    """The pitch curve's outward unit normal in the cam frame, ``R(-eps phi) n``, shape (n, 2)."""
    return inv.to_cam(contact_normal(inv))


def rise_direction(inv: Inversion) -> np.ndarray:
    """Unit direction of the roller centre's rise, ``e = T / |T|``, fixed frame, shape (n, 2)."""
    return inv.t / norm(inv.t)[..., None]


def curvature(inv: Inversion) -> np.ndarray:
    """Signed curvature of the pitch curve, ``kappa = -eps (w1 x w2) / |w1|^3``.

    1/length, positive where the curve is convex (centre of curvature on the
    cam's side), negative where concave; ``rho = 1 / kappa``.
    """
    w1 = inv.w1
    speed = norm(w1)
    with np.errstate(divide="ignore", invalid="ignore"):
        return -inv.sense * cross(w1, inv.w2) / speed**3


def curvature_rate(inv: Inversion) -> tuple[np.ndarray, np.ndarray]:
    """Signed curvature (1/length, positive convex) and its derivative by the cam angle (1/length per radian).

    ``kappa = -eps (w1 x w2) / |w1|^3``, so
    ``dkappa/dphi = -eps ((w1 x w3) / |w1|^3 - 3 (w1 x w2)(w1 . w2) / |w1|^5)``.
    ``inv`` must hold ``w3`` (:func:`invert` with ``third=True``).
    """
    if inv.w3 is None:
        raise ValueError("curvature_rate needs the third derivative: invert(..., third=True)")
    eps = inv.sense
    w1, w2 = inv.w1, inv.w2
    speed = norm(w1)
    cr = cross(w1, w2)
    with np.errstate(divide="ignore", invalid="ignore"):
        kappa = -eps * cr / speed**3
        dkappa = -eps * (cross(w1, inv.w3) / speed**3 - 3 * cr * dot(w1, w2) / speed**5)
    return kappa, dkappa


def _pressure_sin_cos(inv: Inversion) -> tuple[np.ndarray, np.ndarray]:
    """``(eps J w1) x T`` and ``(eps J w1) . T``: ``|n| |T|`` times the sine and cosine of the angle from n to T."""
    eps = inv.sense
    wx, wy = inv.w1[..., 0], inv.w1[..., 1]
    tx, ty = inv.t[..., 0], inv.t[..., 1]
    nx, ny = -eps * wy, eps * wx
    return nx * ty - ny * tx, nx * tx + ny * ty


def pressure_angle(inv: Inversion) -> np.ndarray:
    """Pressure angle, radians in [0, pi]: between the contact normal and the direction of rise.

    ``gamma = arccos(n . e)``, computed as ``atan2(|n x e|, n . e)`` (accurate
    near 0). The force the driving side exerts on the roller is ``n`` on a
    rise and ``-n`` on a return; both give this angle. Above pi/2 the cam
    would pull instead of push.
    """
    sin_, cos_ = _pressure_sin_cos(inv)
    return np.arctan2(np.abs(sin_), cos_)


def pressure_rate(inv: Inversion) -> tuple[np.ndarray, np.ndarray]:
    """Pressure angle (radians, in [0, pi]) and its derivative by the cam angle (per radian).

    Notes
    -----
    With ``alpha`` the signed angle from the contact normal to ``T``,
    ``gamma = |alpha|`` and
    ``d alpha / dphi = s' (T x T2) / |T|^2 - (w1 x w2) / |w1|^2 - eps``
    (the turn of ``T`` less the turn of the normal, ``w1' = w2 + eps J w1``).
    """
    eps = inv.sense
    sin_, cos_ = _pressure_sin_cos(inv)  # both times |n| |T| > 0
    gamma = np.arctan2(np.abs(sin_), cos_)
    (wx, wy), (vx, vy) = (inv.w1[..., 0], inv.w1[..., 1]), (inv.w2[..., 0], inv.w2[..., 1])
    (tx, ty), (bx, by) = (inv.t[..., 0], inv.t[..., 1]), (inv.t2[..., 0], inv.t2[..., 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        dalpha = inv.ds * (tx * by - ty * bx) / (tx * tx + ty * ty) - (wx * vy - wy * vx) / (wx * wx + wy * wy) - eps
    return gamma, np.sign(sin_) * dalpha


@dataclass(frozen=True, eq=False)
class PitchGeometry:
    """Pitch-curve points and derivatives at given cam angles, cam frame.

    Attributes
    ----------
    phi : ndarray, shape (n,)
        Cam angles, radians.
    point : ndarray, shape (n, 2)
        ``P(phi)``, cam frame, length unit.
    d1, d2 : ndarray, shape (n, 2)
        ``dP/dphi`` (length per radian) and ``d2P/dphi2`` (per radian^2).
    normal : ndarray, shape (n, 2)
        Outward unit normal (away from the cam's material), cam frame.
    kappa : ndarray, shape (n,)
        Signed curvature, 1/length, positive where convex.
    s : ndarray, shape (n,)
        Follower displacement (radians or length).
    rise_dir : ndarray, shape (n, 2)
        Unit direction of the roller centre's rise (``dA/ds`` normalized),
        fixed frame.
    """

    phi: np.ndarray
    point: np.ndarray
    d1: np.ndarray
    d2: np.ndarray
    normal: np.ndarray
    kappa: np.ndarray
    s: np.ndarray
    rise_dir: np.ndarray

    @property
    def rho(self) -> np.ndarray:
        """Signed radius of curvature (length, positive convex; ``inf`` where straight)."""
        with np.errstate(divide="ignore"):
            return np.where(self.kappa == 0, np.inf, 1.0 / np.where(self.kappa == 0, 1.0, self.kappa))

    def offset(self, distance: float) -> np.ndarray:
        """Points offset by ``distance`` along the outward normal (negative: toward the cam)."""
        return self.point + distance * self.normal


def pitch_geometry(inv: Inversion) -> PitchGeometry:
    """The cam-frame view of an inversion: points, derivatives, outward normal, curvature."""
    return PitchGeometry(
        phi=inv.phi,
        point=inv.point,
        d1=inv.d1,
        d2=inv.d2,
        normal=outward_normal(inv),
        kappa=curvature(inv),
        s=inv.s,
        rise_dir=rise_direction(inv),
    )


def pitch_phase(design: CamDesign, centre: np.ndarray, phase: int, u: np.ndarray) -> PitchGeometry:
    """Pitch curve inside one phase at normalized positions ``u`` in [0, 1].

    Values at the phase ends are the one-sided limits from inside the phase
    (``laws.program.Program.evaluate_phase``), so a corner or a jump of the
    curvature at a phase joint is seen from both sides.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre O, fixed frame, length unit.
    phase : int
        Phase index in ``design.program.phases``.
    u : array_like, shape (n,)

    Returns
    -------
    PitchGeometry
        In the cam frame, at ``phi = starts[phase] + u * angle``.
    """
    return pitch_geometry(invert_phase(design, centre, phase, u))


def pitch_curve(design: CamDesign, centre: np.ndarray, phi: np.ndarray) -> PitchGeometry:
    """Pitch curve at cam angles ``phi`` (radians, periodic), cam frame.

    At a phase joint the later phase's values are used.

    Examples
    --------
    A centric translating follower, cam centre 30 below the roller's start,
    the cam turning counter-clockwise: at half a turn the roller, risen by 10,
    sits 40 from the centre on the far side of the cam.

    >>> import numpy as np
    >>> from cams.model.design import CamDesign, Limits
    >>> from cams.model.follower import Translating
    >>> from laws.program import Phase, Program
    >>> from laws.registry import get_law
    >>> cyc = get_law("cycloidal")
    >>> prog = Program((Phase("rise", np.pi, cyc), Phase("return", np.pi, cyc)), 10.0)
    >>> d = CamDesign(Translating(roller_radius=5.0), prog, Limits(np.radians(30)))
    >>> g = pitch_curve(d, np.array([0.0, -30.0]), np.array([0.0, np.pi]))
    >>> g.point.round(9).tolist(), g.rho.round(9).tolist()
    ([[0.0, 30.0], [0.0, -40.0]], [30.0, 40.0])
    """
    return pitch_geometry(invert_at(design, centre, phi))


def offset_radius(rho: np.ndarray, distance: float) -> np.ndarray:
    """Radius of curvature of an offset curve (length, positive convex).

    ``distance`` is measured along the outward normal: ``-r_roller`` for the
    working profile (``rho_w = rho - r_roller``), ``+r_roller`` for a
    groove's outer wall (``rho_o = rho + r_roller``).
    """
    return np.asarray(rho, dtype=float) + distance


def offset_curvature(kappa: np.ndarray, distance: float) -> np.ndarray:
    """Signed curvature of an offset curve, ``kappa / (1 + distance kappa)`` (1/length, positive convex).

    The reciprocal of :func:`offset_radius`, written on the curvature so a
    straight piece (``kappa = 0``) stays finite; ``distance`` along the outward
    normal. Infinite (or NaN) where the offset curve has a cusp.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        return kappa / (1.0 + distance * kappa)


def to_fixed_frame(points: np.ndarray, centre: np.ndarray, sense: int, phi: float) -> np.ndarray:
    """Cam-frame points placed in the fixed frame with the cam at angle ``phi``: ``O + R(eps phi) X``.

    Parameters
    ----------
    points : ndarray, shape (..., 2)
        Cam-frame points ``X``, length unit.
    centre : array_like, shape (2,)
        Cam centre O, fixed frame.
    sense : {+1, -1}
        The cam's sense of rotation ``eps``.
    phi : float
        Cam angle, radians.
    """
    return np.asarray(centre, dtype=float) + rotate(np.asarray(points, dtype=float), sense * phi)


def _pitch_radius_extreme(design: CamDesign, centre: np.ndarray, sign: float, grid: int) -> tuple[float, float]:
    """The largest ``sign |P|`` over the cycle (``sign`` +1: the pitch curve's largest radius, -1: its smallest,
    negated) and its cam angle (radians): per phase on ``grid`` steps, refined where the slope
    ``d|P|/dphi = s' (r . T) / |r|`` changes sign; the first such angle in the program's order of phases wins a
    tie within 1e-12 of the design's scale."""
    prog = design.program
    centre = np.asarray(centre, dtype=float)

    def signed_radius(i: int, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        inv = invert_phase(design, centre, i, u)
        d = norm(inv.r)
        with np.errstate(divide="ignore", invalid="ignore"):
            slope = inv.ds * dot(inv.r, inv.t) / d
        return sign * d[None], sign * np.nan_to_num(slope)[None]

    best, best_phi = -np.inf, 0.0
    for i, p in enumerate(prog.phases):
        top, at = maximize(partial(signed_radius, i), phase_positions(prog, i, grid), refine=p.kind != "dwell")
        if top[0] > best + 1e-12 * design.scale:  # a tie within rounding keeps the earlier phase
            best, best_phi = float(top[0]), float(prog.starts[i] + at[0] * p.angle)
    return best, best_phi


def smallest_cam_radius(design: CamDesign, centre: np.ndarray, *, grid: int = 512) -> tuple[float, float]:
    """The cam's own smallest radius: the working profile's nearest point to the cam centre.

    R0 is the pitch curve's base radius (cam centre to roller centre at the
    near dwell); the cam itself is smaller by the roller. The working profile
    is the inner offset ``P - r n`` of the pitch curve, so its distance from
    the centre is ``min |P| - r``, reached where ``|P|`` is smallest (there the
    normal is radial). ``|P| = |A - O|`` is searched per phase on ``grid``
    steps (:func:`cams.kinematics.extremum.phase_positions`) and refined where
    its slope ``d|P|/dphi = s' (r . T) / |r|`` changes sign
    (:func:`cams.kinematics.extremum.maximize` on ``-|P|``).

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre O in the follower's fixed frame, length unit.
    grid : int, optional
        Steps per phase of the search.

    Returns
    -------
    radius, phi : float
        ``min |P| - roller_radius`` (length; <= 0 when the roller reaches the
        centre: no cam) and the cam angle where it is reached (radians; the
        first such angle in the program's order of phases, ties within
        1e-12 of the design's scale included). A knife edge gives the pitch
        curve's smallest radius.
    """
    best, at = _pitch_radius_extreme(design, centre, -1.0, grid)
    return float(-best - design.follower.roller_radius), at


def largest_cam_radius(design: CamDesign, centre: np.ndarray, *, grid: int = 512) -> tuple[float, float]:
    """The cam's largest radius: the least radius of its blank (length), and the cam angle where it is reached.

    The working profile ``P - r n`` reaches ``max |P| - r`` where ``|P|`` is largest (the normal is radial
    there), and no point of a cam body whose roller circles lie inside the pitch curve's region is farther out;
    a groove's outer wall ``P + r n`` reaches ``max |P| + r``, the radius the blank must exceed. ``|P|`` is
    searched as in :func:`smallest_cam_radius`.

    Returns
    -------
    radius, phi : float
        ``max |P| - roller_radius`` (force closure; a knife edge: ``max |P|``) or ``max |P| + roller_radius``
        (a groove, form closure), length; the cam angle, radians.
    """
    best, at = _pitch_radius_extreme(design, centre, 1.0, grid)
    r = design.follower.roller_radius
    return float(best + (r if design.limits.closure == "form" else -r)), at
