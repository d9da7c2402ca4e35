"""Kinematic primitives of planar linkages: the input crank and the Assur dyads.

Conventions
-----------
* A point is a complex number ``z = x + i y`` in a fixed right-handed frame; its
  length unit is the caller's (mm in machine files). Angles are radians,
  counter-clockwise positive from +x.
* Every primitive takes and returns *kinematic states* (:class:`Point`,
  :class:`Angle`, :class:`Slide`): a position and its first and second time
  derivatives. With the crank turning at ``omega`` rad/s they are in unit/s and
  unit/s^2; with ``omega = 1`` (the default) they are the analogues d/dphi and
  d^2/dphi^2 with respect to the crank angle.
* Everything is vectorized: the arrays of one call broadcast together, one
  entry per crank angle.
* Velocities and accelerations are analytic. Each dyad's vector loop is
  differentiated once and twice in time; each derivative is one complex
  equation in two real unknowns, solved in closed form (Cramer's rule, see
  :func:`solve_real`). Sliding on a rotating guide brings the Coriolis term
  ``2 i Omega s' u`` (:func:`rrp`, :func:`rpr`).
* A branch (assembly mode) is always an explicit argument, never guessed.

Position-only crossings, named as in pyslvs: :func:`pllp` (two circles) and
:func:`plpp` (a circle and a line). Dyads with kinematics: :func:`rrr`,
:func:`rrp`, :func:`rpr`, :func:`rpp`; the input: :func:`crank`; rigid points:
:func:`on_link`, :func:`ground`.

A position that cannot be assembled raises :class:`AssemblyError` (an
:class:`~laws.errors.InfeasibleError`) carrying the mask of the failing
entries, the field it concerns and what length would fit.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from laws.errors import InfeasibleError

__all__ = [
    "AssemblyError",
    "Point",
    "Angle",
    "Slide",
    "ground",
    "crank",
    "on_link",
    "pllp",
    "plpp",
    "rrr",
    "rrp",
    "rpr",
    "rpp",
    "cross",
    "solve_real",
    "acute_angle",
]


class AssemblyError(InfeasibleError):
    """A dyad cannot be assembled at some input positions.

    Parameters
    ----------
    field : str
        Dotted name of the input to change, e.g. ``"linkage.rod"``.
    message : str
        What fails and what would fit.
    mask : ndarray of bool or None
        True where the dyad cannot be assembled (same shape as the inputs).
    """

    def __init__(self, field: str, message: str, mask: np.ndarray | None = None):
        self.message = message
        self.mask = mask
        super().__init__(field, message)


@dataclass(frozen=True, eq=False)
class Point:
    """Position, velocity and acceleration of a point (complex ``x + i y``).

    Attributes
    ----------
    pos, vel, acc : ndarray of complex
        Position (length), velocity (length/s, or per radian of crank for
        ``omega = 1``) and acceleration (length/s^2, or per radian^2).
    """

    pos: np.ndarray
    vel: np.ndarray
    acc: np.ndarray

    @property
    def x(self) -> np.ndarray:
        """x coordinate (length)."""
        return np.real(self.pos)

    @property
    def y(self) -> np.ndarray:
        """y coordinate (length)."""
        return np.imag(self.pos)

    @property
    def speed(self) -> np.ndarray:
        """Magnitude of the velocity."""
        return np.abs(self.vel)

    @property
    def accel(self) -> np.ndarray:
        """Magnitude of the acceleration."""
        return np.abs(self.acc)

    def relative(self, other: Point) -> Point:
        """This point's state relative to ``other`` (differences of all three)."""
        return Point(self.pos - other.pos, self.vel - other.vel, self.acc - other.acc)


@dataclass(frozen=True, eq=False)
class Angle:
    """Angle of a link and its time derivatives.

    Attributes
    ----------
    angle : ndarray or float
        Radians, counter-clockwise from +x.
    omega : ndarray or float
        Angular velocity, rad/s (counter-clockwise positive).
    alpha : ndarray or float
        Angular acceleration, rad/s^2.

    A fixed direction (a guide) has float members.
    """

    angle: np.ndarray | float
    omega: np.ndarray | float
    alpha: np.ndarray | float

    @property
    def unit(self) -> np.ndarray:
        """Unit vector ``exp(i angle)`` as a complex array."""
        return np.exp(1j * self.angle)


@dataclass(frozen=True, eq=False)
class Slide:
    """A sliding coordinate and its time derivatives.

    Attributes
    ----------
    s : ndarray
        Position along the guide (length), from the guide's origin.
    ds : ndarray
        Velocity of sliding (length/s).
    d2s : ndarray
        Acceleration of sliding (length/s^2), without the Coriolis term.
    """

    s: np.ndarray
    ds: np.ndarray
    d2s: np.ndarray


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """z-component of the cross product of complex vectors, ``Im(conj(a) b)``."""
    return np.imag(np.conj(a) * b)


def solve_real(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real ``u, w`` with ``u a + w b = c`` for complex ``a, b, c`` (Cramer's rule).

    The determinant ``cross(a, b)`` vanishes where ``a`` and ``b`` are parallel:
    a dead (singular) position of the dyad; there the result is inf or nan.

    Examples
    --------
    >>> u, w = solve_real(1 + 0j, 1j, 2 + 3j)
    >>> float(u), float(w)
    (2.0, 3.0)
    """
    det = cross(a, b)
    with np.errstate(divide="ignore", invalid="ignore"):
        return cross(c, b) / det, cross(a, c) / det


def acute_angle(a: np.ndarray | float, b: np.ndarray | float) -> np.ndarray:
    """Acute angle between two lines of directions ``a`` and ``b`` (radians), in [0, pi/2].

    Examples
    --------
    >>> round(float(np.degrees(acute_angle(0.0, np.radians(170.0)))), 9)
    10.0
    """
    return np.arcsin(np.minimum(1.0, np.abs(np.sin(np.asarray(a) - np.asarray(b)))))


def _c(x) -> np.ndarray:
    return np.asarray(x, dtype=complex)


def ground(z: complex | np.ndarray) -> Point:
    """A fixed point (zero velocity and acceleration).

    Examples
    --------
    >>> float(ground(3 + 4j).speed)
    0.0
    """
    z = _c(z)
    zero = np.zeros_like(z)
    return Point(z, zero, zero.copy())


def crank(centre: Point, radius: float, phi: np.ndarray, *, omega: float = 1.0,
          alpha: float = 0.0) -> tuple[Point, Angle]:
    """The input crank: a point at ``radius`` from ``centre`` at angle ``phi``.

    Parameters
    ----------
    centre : Point
        Crank centre (usually fixed, :func:`ground`).
    radius : float
        Crank length, > 0.
    phi : array_like
        Crank angle, radians, counter-clockwise from +x.
    omega : float, optional
        Crank angular velocity dphi/dt, rad/s (signed: negative clockwise).
        The default 1 gives analogues with respect to phi.
    alpha : float, optional
        Crank angular acceleration, rad/s^2 (0: constant speed).

    Returns
    -------
    A : Point
        ``centre + radius exp(i phi)`` with ``v = i omega r`` and
        ``a = (i alpha - omega^2) r`` added to the centre's.
    link : Angle
        The crank's angle, omega and alpha.

    Examples
    --------
    >>> A, _ = crank(ground(0j), 2.0, np.pi / 2, omega=3.0)
    >>> complex(np.round(A.vel, 12)), complex(np.round(A.acc, 12))
    ((-6+0j), (-0-18j))
    """
    phi = np.asarray(phi, dtype=float)
    r = radius * np.exp(1j * phi)
    w = np.full_like(phi, float(omega))
    e = np.full_like(phi, float(alpha))
    pt = Point(centre.pos + r, centre.vel + 1j * w * r, centre.acc + (1j * e - w**2) * r)
    return pt, Angle(phi, w, e)


def on_link(origin: Point, link: Angle, radius: float, *, angle: float = 0.0) -> Point:
    """A point fixed on a link: ``origin + radius exp(i (link.angle + angle))``.

    Parameters
    ----------
    origin : Point
        A point of the link (a joint).
    link : Angle
        The link's angle state.
    radius : float
        Distance from ``origin`` (may be negative: the opposite side).
    angle : float, optional
        Constant angle from the link's direction, radians, counter-clockwise.

    Returns
    -------
    Point
        Rigid-body velocity ``v_O + i omega r`` and acceleration
        ``a_O + (i alpha - omega^2) r``.
    """
    r = radius * np.exp(1j * (link.angle + angle))
    return Point(origin.pos + r, origin.vel + 1j * link.omega * r, origin.acc + (1j * link.alpha - link.omega**2) * r)


def pllp(c1: np.ndarray, d1: float, d2: float, c2: np.ndarray, *, branch: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Crossing of two circles: the point at ``d1`` from ``c1`` and ``d2`` from ``c2``.

    Parameters
    ----------
    c1, c2 : array_like of complex
        Circle centres.
    d1, d2 : float
        Radii, > 0.
    branch : {+1, -1}
        +1: the crossing to the left of the directed line ``c1 -> c2``
        (``cross(c2 - c1, X - c1) > 0``); -1: to the right.

    Returns
    -------
    X : ndarray of complex
        The crossing; nan where the circles do not meet.
    bad : ndarray of bool
        True where the circles do not meet (or are concentric).

    Examples
    --------
    >>> X, bad = pllp(0j, 5.0, 5.0, 8 + 0j, branch=1)
    >>> complex(X), bool(bad)
    ((4+3j), False)
    """
    _check_branch(branch)
    c1, c2 = _c(c1), _c(c2)
    d = c2 - c1
    L = np.abs(d)
    with np.errstate(divide="ignore", invalid="ignore"):
        a = (L**2 + d1**2 - d2**2) / (2 * L)
        h2 = d1**2 - a**2
        bad = ~(h2 >= -1e-12 * max(d1, d2) ** 2) | (L == 0)
        h = np.sqrt(np.maximum(h2, 0.0))
        u = d / L
        X = c1 + (a + 1j * branch * h) * u
    return np.where(bad, np.nan + 0j, X), np.asarray(bad)


def plpp(c: np.ndarray, d: float, p0: np.ndarray, u: np.ndarray, *,
         branch: int = 1) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Crossing of a circle and a line: ``X = p0 + s u`` with ``|X - c| = d``.

    Parameters
    ----------
    c : array_like of complex
        Circle centre.
    d : float
        Radius, > 0.
    p0, u : array_like of complex
        A point of the line and its unit direction.
    branch : {+1, -1}
        +1: the crossing further along ``u`` (larger ``s``); -1: the nearer.

    Returns
    -------
    X : ndarray of complex
    s : ndarray
        Coordinate of ``X`` along the line from ``p0``.
    bad : ndarray of bool
        True where the line misses the circle.

    Examples
    --------
    >>> X, s, bad = plpp(0j, 5.0, 3j, 1 + 0j, branch=-1)
    >>> complex(X), float(s)
    ((-4+3j), -4.0)
    """
    _check_branch(branch)
    c, p0, u = _c(c), _c(p0), _c(u)
    t0 = np.real(np.conj(u) * (c - p0))  # projection of the centre on the line
    h = cross(u, c - p0)  # signed distance of the centre from the line
    disc = d**2 - h**2
    bad = ~(disc >= -1e-12 * d**2)
    s = t0 + branch * np.sqrt(np.maximum(disc, 0.0))
    s = np.where(bad, np.nan, s)
    return p0 + s * u, s, np.asarray(bad)


def _check_branch(branch: int) -> None:
    if branch not in (1, -1):
        raise ValueError(f"branch must be +1 or -1, got {branch!r}")


def rrr(c1: Point, d1: float, d2: float, c2: Point, *, branch: int = 1,
        field: str = "linkage") -> tuple[Point, Angle, Angle]:
    """RRR dyad: two links ``c1-X`` (length ``d1``) and ``c2-X`` (``d2``) joined at X.

    Loop: ``X = c1 + d1 e^{i t1} = c2 + d2 e^{i t2}``. Velocity:
    ``w1 (i r1) - w2 (i r2) = v2 - v1``; acceleration:
    ``e1 (i r1) - e2 (i r2) = a2 - a1 + w1^2 r1 - w2^2 r2`` with
    ``r_k = X - c_k``.

    Parameters
    ----------
    c1, c2 : Point
        The dyad's outer joints.
    d1, d2 : float
        Link lengths, > 0.
    branch : {+1, -1}
        As in :func:`pllp` (X to the left of ``c1 -> c2`` for +1).
    field : str
        Field named in an :class:`AssemblyError`.

    Returns
    -------
    X : Point
    link1, link2 : Angle
        Angles of ``c1 -> X`` and ``c2 -> X``.

    Raises
    ------
    AssemblyError
        Where ``|c1 c2|`` leaves ``[|d1 - d2|, d1 + d2]``.
    """
    X, bad = pllp(c1.pos, d1, d2, c2.pos, branch=branch)
    if np.any(bad):
        dist = np.abs(c2.pos - c1.pos)
        dmax, dmin = float(np.max(np.where(bad, dist, -np.inf))), float(np.min(np.where(bad, dist, np.inf)))
        need = []
        if dmax > d1 + d2:
            need.append(f"d1 + d2 >= {dmax:.6g}")
        if dmin < abs(d1 - d2):
            need.append(f"|d1 - d2| <= {dmin:.6g}")
        raise AssemblyError(
            field,
            f"links of {d1:.6g} and {d2:.6g} cannot join: their ends are up to {dmax:.6g} apart; "
            f"it would fit with {' and '.join(need) or 'other lengths'}",
            bad,
        )
    r1, r2 = X - c1.pos, X - c2.pos
    w1, w2 = solve_real(1j * r1, -1j * r2, c2.vel - c1.vel)
    vel = c1.vel + 1j * w1 * r1
    e1, e2 = solve_real(1j * r1, -1j * r2, c2.acc - c1.acc + w1**2 * r1 - w2**2 * r2)
    acc = c1.acc + (1j * e1 - w1**2) * r1
    return Point(X, vel, acc), Angle(np.angle(r1), w1, e1), Angle(np.angle(r2), w2, e2)


def rrp(c: Point, d: float, origin: Point, guide: Angle, *, branch: int = 1,
        field: str = "linkage") -> tuple[Point, Angle, Slide]:
    """RRP dyad: a link ``c-X`` of length ``d`` whose end X slides on a guide line.

    The guide passes through ``origin`` (a point of the guide's link) with
    direction ``u = e^{i theta}`` (``guide``: angle, Omega, Omega'). Loop:
    ``X = origin + s u = c + d e^{i t}``. Velocity:
    ``s' u - w (i r) = v_c - v_o - i Omega s u``; acceleration:
    ``s'' u - e (i r) = a_c - w^2 r - a_o - 2 i Omega s' u - (i Omega' - Omega^2) s u``
    (``r = X - c``; ``2 i Omega s' u`` is the Coriolis term).

    Parameters
    ----------
    c : Point
        The link's other joint.
    d : float
        Link length, > 0.
    origin : Point
        Origin of the guide coordinate ``s``.
    guide : Angle
        Direction of the guide (constant for a fixed guide).
    branch : {+1, -1}
        As in :func:`plpp` (+1: the crossing further along the guide).
    field : str
        Field named in an :class:`AssemblyError`.

    Returns
    -------
    X : Point
        The slider's joint.
    link : Angle
        Angle of ``c -> X``.
    slide : Slide
        ``s`` along the guide from ``origin`` and its derivatives relative to
        the guide.

    Raises
    ------
    AssemblyError
        Where the guide is further than ``d`` from ``c``.
    """
    u = guide.unit
    X, s, bad = plpp(c.pos, d, origin.pos, u, branch=branch)
    if np.any(bad):
        h = np.abs(cross(u, c.pos - origin.pos))
        need = float(np.max(np.where(bad, h, -np.inf)))
        raise AssemblyError(
            field,
            f"a link of {d:.6g} cannot reach its guide, which lies up to {need:.6g} away; "
            f"it would fit with a length >= {need:.6g}",
            bad,
        )
    r = X - c.pos
    W, We = guide.omega, guide.alpha
    ds, w = solve_real(u, -1j * r, c.vel - origin.vel - 1j * W * s * u)
    d2s, e = solve_real(u, -1j * r, c.acc - w**2 * r - origin.acc - 2j * W * ds * u - (1j * We - W**2) * s * u)
    vel = c.vel + 1j * w * r
    acc = c.acc + (1j * e - w**2) * r
    return Point(X, vel, acc), Angle(np.angle(r), w, e), Slide(s, ds, d2s)


def rpr(block: Point, pivot: Point, *, offset: float = 0.0, field: str = "linkage") -> tuple[Angle, Slide]:
    """RPR dyad: a block pinned at ``block`` slides in a guide bar that turns about ``pivot``.

    The slot's line lies at the perpendicular distance ``offset`` to the left
    of the pivot (0: through it). With ``u = e^{i theta}`` along the slot,
    ``block = pivot + (s + i offset) u`` and ``s > 0`` (``u`` points from the
    pivot toward the block). Velocity:
    ``s' u + Omega i (s + i e) u = v_A - v_P``; acceleration:
    ``s'' u + Omega' i (s + i e) u = a_A - a_P - 2 i Omega s' u + Omega^2 (s + i e) u``,
    where ``2 i Omega s' u`` is the Coriolis acceleration of the block on the
    turning bar.

    Parameters
    ----------
    block : Point
        The block's pin (e.g. the crank pin A of a slotted-lever mechanism).
    pivot : Point
        The guide bar's pivot.
    offset : float, optional
        Offset of the slot's line from the pivot, length.
    field : str
        Field named in an :class:`AssemblyError`.

    Returns
    -------
    bar : Angle
        Angle of the slot direction ``u``, the bar's omega and alpha.
    slide : Slide
        Distance ``s`` of the block along the slot from the foot of the
        perpendicular from the pivot (= ``|PA|`` for zero offset), with the
        relative sliding velocity ``s'`` and acceleration ``s''``.

    Raises
    ------
    AssemblyError
        Where the block comes closer to the pivot than ``|offset|`` (or
        reaches it, for zero offset).
    """
    rel = block.pos - pivot.pos
    dist = np.abs(rel)
    bad = ~(dist > abs(offset)) if offset else ~(dist > 0)
    if np.any(bad):
        raise AssemblyError(
            field,
            f"the block comes within {float(np.min(dist)):.6g} of the bar's pivot; the slot's offset "
            f"{abs(offset):.6g} needs a larger distance; it would fit with |offset| < {float(np.min(dist)):.6g}",
            bad,
        )
    s = np.sqrt(dist**2 - offset**2)
    z = s + 1j * offset
    u = rel / z
    s1, W = solve_real(u, 1j * z * u, block.vel - pivot.vel)
    s2, We = solve_real(u, 1j * z * u, block.acc - pivot.acc - 2j * W * s1 * u + W**2 * z * u)
    return Angle(np.angle(u), W, We), Slide(s, s1, s2)


def rpp(c: Point, origin: complex, guide_angle: float, slot_angle: float, *,
        field: str = "linkage") -> tuple[Slide, Slide]:
    """RPP dyad: a block pinned at ``c`` slides in a slot of a link that translates on a fixed guide.

    The translating link's reference point moves on the fixed line
    ``origin + p g`` (``g = e^{i guide_angle}``); its slot has the fixed
    direction ``h = e^{i slot_angle}`` and passes through that reference
    point. Then ``c = origin + p g + q h`` is linear in ``(p, q)``; velocity
    and acceleration follow from the same map (no rotation, no Coriolis term).
    A Scotch yoke is the case ``slot ⟂ guide``.

    Parameters
    ----------
    c : Point
        The block's pin.
    origin : complex
        Fixed point of the guide line.
    guide_angle, slot_angle : float
        Directions, radians; they must differ (mod pi).
    field : str
        Field named in an error.

    Returns
    -------
    link : Slide
        ``p``: the translating link's position along the guide and its
        velocity and acceleration.
    block : Slide
        ``q``: the block's position in the slot and its derivatives.
    """
    g, h = np.exp(1j * guide_angle), np.exp(1j * slot_angle)
    if abs(cross(g, h)) < 1e-12:
        raise AssemblyError(field, "the slot is parallel to the guide; the link's position is undetermined")
    p, q = solve_real(g, h, c.pos - origin)
    pv, qv = solve_real(g, h, c.vel)
    pa, qa = solve_real(g, h, c.acc)
    return Slide(p, pv, pa), Slide(q, qv, qa)
