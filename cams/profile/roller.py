"""Cam profiles: pitch curve, working profile(s), radius of curvature, sampling.

Frames and signs
----------------
* Fixed frame: the follower's frame of :mod:`cams.model.follower`; the cam centre O
  is given in it (``SolveResult.centre``).
* Cam frame: origin at the cam centre, axes parallel to the fixed frame when
  the cam is at ``phi = 0``, turning with the cam. A point with cam-frame
  coordinates ``X`` is at ``O + R(eps phi) X`` in the fixed frame, with
  ``eps = design.cam_sense`` (+1 counter-clockwise).
* Pitch curve (roller-centre path on the cam), by inversion of the motion::

      P(phi) = R(-eps phi) (A(s(phi)) - O)

  It runs round the cam centre in the sense ``-eps`` as ``phi`` grows.
  Its derivatives with respect to the cam angle are analytic::

      P'   = R(-eps phi) (r' - eps J r)
      P''  = R(-eps phi) (r'' - 2 eps J r' - r)
      P''' = R(-eps phi) (r''' - 3 eps J r'' - 3 r' + eps J r)

  with ``r = A - O``, ``r' = s' dA/ds``, ``r'' = s'' dA/ds + s'^2 d2A/ds2``,
  ``r''' = s''' dA/ds + 3 s' s'' d2A/ds2 + s'^3 d3A/ds3`` and ``J`` the
  rotation by +90 degrees. They are computed on the ``x`` and ``y``
  components (:func:`_inversion`), vectorized over the cam angles.
* Outward normal ``n``: the unit normal of the pitch curve pointing away from
  the cam's material, ``n = R(eps 90 deg) P' / |P'|``.
* Signed curvature ``kappa = -eps (P' x P'') / |P'|^3`` and radius of
  curvature ``rho = 1 / kappa``: **positive where the curve is convex** (centre
  of curvature on the cam's side), negative where concave. On a dwell the
  pitch curve is a circle of radius ``|A - O|`` and ``rho = +|A - O|``.
* Working profile (roller follower): the envelope of the roller circles, the
  inner offset ``W = P - r_roller n`` with ``rho_w = rho - r_roller``. For a
  groove (form closure) the outer wall ``P + r_roller n`` has
  ``rho_o = rho + r_roller`` (same sign convention: positive when its centre
  of curvature lies on the cam centre's side). A knife edge (roller radius 0)
  has working profile = pitch curve.

Angles are radians; lengths are the design's unit (mm).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.model.design import CamDesign
from cams.model.follower import Rocker, Translating
from cams.model.options import ProfileOptions, check_tolerance, profile_options, resolve_tolerance
from laws.errors import InputError
from laws.program import Motion

__all__ = [
    "ProfileSizeError",
    "PitchGeometry",
    "Profile",
    "ProfileOptions",
    "pitch_phase",
    "pitch_curve",
    "offset_radius",
    "build_profile",
    "profile_options",
    "resolve_tolerance",
    "default_bore_radius",
    "smallest_cam_radius",
    "DEFAULT_TOLERANCE",
    "PROFILE_KEYS",
    "MAX_TOLERANCE_FRACTION",
    "cap_tolerance",
    "smallest_radius",
]

#: Default chord tolerance (sagitta), length unit: 1 micrometre for mm.
DEFAULT_TOLERANCE = 1e-3
#: Largest chord tolerance accepted, as a fraction of the cam's smallest radius (:func:`cap_tolerance`).
MAX_TOLERANCE_FRACTION = 0.05
#: The default tolerance is at most this fraction of the cam's smallest radius (below 1 mm: finer than 1 um).
DEFAULT_TOLERANCE_FRACTION = 1e-3
#: Keys the ``[profile]`` table of a design file may hold (:mod:`cams.io.designfile` maps them onto the design).
PROFILE_KEYS = ("tolerance", "min_curvature_radius")
#: Largest number of samples of one profile (guards against endless refinement).
MAX_POINTS = 2_000_000


class ProfileSizeError(InputError):
    """The profile needs more than :data:`MAX_POINTS` points at its chord tolerance.

    An input error where the tolerance was asked for (``cams profile
    --tolerance``); where a command only assesses a sized cam it makes the cam
    not buildable at that tolerance (:func:`cams.assess.assess_cam`).
    """


def _xy(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Vectors of shape ``x.shape + (2,)`` from their components ``x`` and ``y``."""
    out = np.empty(np.shape(x) + (2,))
    out[..., 0] = x
    out[..., 1] = y
    return out


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


@dataclass(frozen=True, eq=False)
class _Inversion:
    """Pitch-curve derivatives by inversion, as components, before the turn into the cam frame.

    Every field is a pair ``(x, y)`` of arrays in the orientation of the fixed
    frame; turned by ``R(-eps phi)`` they give the cam-frame vectors.

    Attributes
    ----------
    r : tuple of ndarray
        ``A - O``, length unit (turned: the pitch point ``P``).
    w1, w2 : tuple of ndarray
        Turned: ``dP/dphi`` (length per radian) and ``d2P/dphi2`` (per radian^2).
    w3 : tuple of ndarray or None
        Turned: ``d3P/dphi3`` (per radian^3); ``None`` unless asked for.
    t, t2 : tuple of ndarray
        The follower's ``dA/ds`` and ``d2A/ds2``, fixed frame.
    """

    r: tuple[np.ndarray, np.ndarray]
    w1: tuple[np.ndarray, np.ndarray]
    w2: tuple[np.ndarray, np.ndarray]
    w3: tuple[np.ndarray, np.ndarray] | None
    t: tuple[np.ndarray, np.ndarray]
    t2: tuple[np.ndarray, np.ndarray]


def _inversion(design: CamDesign, centre: np.ndarray, m, *, third: bool = False) -> _Inversion:
    """Derivatives of the pitch curve ``P = R(-eps phi) r``, ``r = A(s(phi)) - O``, as components.

    With ``D v = v' - eps J v`` (a derivative seen from the turning cam, ``J``
    the rotation by +90 degrees), ``P^(k) = R(-eps phi) D^k r``::

        w1 = D r  = r' - eps J r
        w2 = D w1 = r'' - 2 eps J r' - r
        w3 = D w2 = r''' - 3 eps J r'' - 3 r' + eps J r

    where ``r' = s' T``, ``r'' = s'' T + s'^2 T2``,
    ``r''' = s''' T + 3 s' s'' T2 + s'^3 T3`` and ``T, T2, T3`` are ``dA/ds``
    and its derivatives. A rocker's roller centre turns about the pivot, so
    ``T2 = -(A - pivot)`` and ``T3 = -T``; a translating follower's moves on a
    line, ``T2 = T3 = 0``.

    Parameters
    ----------
    design : CamDesign
    centre : ndarray, shape (2,)
        Cam centre O, fixed frame, length unit.
    m : laws.program.Motion
        Follower displacement ``s`` and its derivatives by the cam angle.
    third : bool
        Also compute ``w3`` (from ``m.d3s``).

    Returns
    -------
    _Inversion
    """
    f = design.follower
    eps = design.cam_sense
    A, T, _ = f.frame(np.asarray(m.s, dtype=float))
    tx, ty = T[..., 0], T[..., 1]
    if isinstance(f, Rocker):
        px, py = f.pivot
        bx, by = px - A[..., 0], py - A[..., 1]
        cx, cy = -tx, -ty
    elif isinstance(f, Translating):
        bx = by = cx = cy = np.zeros_like(tx)
    else:  # pragma: no cover
        raise InputError("follower.kind", "profiles are defined for rocker and translating followers")
    rx, ry = A[..., 0] - centre[0], A[..., 1] - centre[1]
    s1, s2 = m.ds, m.d2s
    r1x, r1y = s1 * tx, s1 * ty
    q = s1**2
    r2x, r2y = s2 * tx + q * bx, s2 * ty + q * by
    w1 = (r1x + eps * ry, r1y - eps * rx)
    w2 = (r2x + 2 * eps * r1y - rx, r2y - 2 * eps * r1x - ry)
    w3 = None
    if third:
        k2, k3 = 3 * s1 * s2, s1**3
        r3x, r3y = m.d3s * tx + k2 * bx + k3 * cx, m.d3s * ty + k2 * by + k3 * cy
        w3 = (r3x + 3 * eps * r2y - 3 * r1x - eps * ry, r3y - 3 * eps * r2x - 3 * r1y + eps * rx)
    return _Inversion((rx, ry), w1, w2, w3, (tx, ty), (bx, by))


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


def _pitch_values(design: CamDesign, centre: np.ndarray, phi: np.ndarray, m):
    """Pitch point and outward unit normal (cam frame, as components), signed curvature.

    Returns ``inv, (c, s), (px, py), (nx, ny), kappa`` with ``inv`` the
    :class:`_Inversion`, ``c, s`` the cosine and sine of the turn ``-eps phi``
    into the cam frame, and ``kappa`` in 1/length (positive convex).
    """
    eps = design.cam_sense
    inv = _inversion(design, np.asarray(centre, dtype=float), m)
    (rx, ry), (wx, wy), (vx, vy) = inv.r, inv.w1, inv.w2
    speed = np.sqrt(wx * wx + wy * wy)
    with np.errstate(divide="ignore", invalid="ignore"):
        kappa = -eps * (wx * vy - wy * vx) / speed**3
        nx, ny = -eps * wy / speed, eps * wx / speed
    c, s = np.cos(-eps * phi), np.sin(-eps * phi)
    return inv, (c, s), (c * rx - s * ry, s * rx + c * ry), (c * nx - s * ny, s * nx + c * ny), kappa


def _geometry(design: CamDesign, centre: np.ndarray, phi: np.ndarray, m) -> PitchGeometry:
    inv, (c, s), (px, py), (nx, ny), kappa = _pitch_values(design, centre, phi, m)
    (wx, wy), (vx, vy), (tx, ty) = inv.w1, inv.w2, inv.t
    tn = np.sqrt(tx * tx + ty * ty)
    return PitchGeometry(
        phi=phi,
        point=_xy(px, py),
        d1=_xy(c * wx - s * wy, s * wx + c * wy),
        d2=_xy(c * vx - s * vy, s * vx + c * vy),
        normal=_xy(nx, ny),
        kappa=kappa,
        s=np.asarray(m.s, dtype=float),
        rise_dir=_xy(tx / tn, ty / tn),
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
    prog = design.program
    u = np.atleast_1d(np.asarray(u, dtype=float))
    phi = prog.starts[phase] + u * prog.phases[phase].angle
    return _geometry(design, centre, phi, prog.evaluate_phase(phase, u))


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
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    return _geometry(design, centre, phi, design.program.evaluate(phi))


def offset_radius(rho: np.ndarray, distance: float) -> np.ndarray:
    """Radius of curvature of an offset curve (length, positive convex).

    ``distance`` is measured along the outward normal: ``-r_roller`` for the
    working profile (``rho_w = rho - r_roller``), ``+r_roller`` for a
    groove's outer wall (``rho_o = rho + r_roller``).
    """
    return np.asarray(rho, dtype=float) + distance


def smallest_radius(R0: float, roller_radius: float = 0.0) -> float:
    """The cam's smallest radius (length): its working profile's least distance from the centre.

    ``R0 - r`` for a roller follower (the base circle of the pitch curve less
    the roller; a lower bound, reached on the base circle), ``R0`` for a knife
    edge or a flat face (their profile's base radius). When ``R0 <= r`` there
    is no working profile (not buildable); the curves drawn then are the size
    of the roller, and ``max(R0, r)`` sets their sampling.
    """
    return R0 - roller_radius if R0 > roller_radius else max(R0, roller_radius)


def cap_tolerance(tolerance: float | None, smallest: float, field: str) -> float:
    """The chord tolerance for a cam whose smallest radius is ``smallest``, refusing one too coarse for it.

    Parameters
    ----------
    tolerance : float or None
        The tolerance given (length); None: ``min(DEFAULT_TOLERANCE,
        DEFAULT_TOLERANCE_FRACTION * smallest)``, so a cam whose smallest
        radius is under a millimetre is sampled as finely for its size.
    smallest : float
        The cam's smallest radius (:func:`smallest_radius`), length.
    field : str
        Where the tolerance was given, for the message.

    Returns
    -------
    float

    Raises
    ------
    InputError
        Naming ``field``: not a number > 0, or above
        ``MAX_TOLERANCE_FRACTION`` (5 %) of ``smallest``; the message gives the
        largest accepted value.
    """
    cap = MAX_TOLERANCE_FRACTION * smallest
    if tolerance is None:
        return float(min(DEFAULT_TOLERANCE, DEFAULT_TOLERANCE_FRACTION * smallest)) if smallest > 0 \
            else DEFAULT_TOLERANCE
    tol = check_tolerance(tolerance, field)
    if cap > 0 and tol > cap:
        raise InputError(field, f"chord tolerance {tol:g} mm is more than {100 * MAX_TOLERANCE_FRACTION:g} % of the "
                         f"cam's smallest radius {smallest:.6g} mm; the largest accepted is {cap:.6g} mm")
    return tol


@dataclass(frozen=True, eq=False)
class Profile:
    """A sampled cam profile in the cam frame (origin at the cam centre, cam at phi = 0).

    Rows are in cam-angle order from ``phi = 0``; the curves are closed (the
    last row joins the first). At a phase joint where the pitch curve has a
    corner, extra rows with the same ``phi`` carry the roller-circle arc that
    fills the gap of an offset curve.

    Attributes
    ----------
    phi : ndarray, shape (n,)
        Cam angle of each row, radians in [0, 2 pi).
    phase : ndarray of int, shape (n,)
        Phase index of each row.
    pitch, work : ndarray, shape (n, 2)
        Pitch curve and working profile, length unit.
    outer : ndarray, shape (n, 2) or None
        Outer wall of a groove (form closure), else ``None``.
    normal : ndarray, shape (n, 2)
        Outward unit normal of the pitch curve.
    rho : ndarray, shape (n,)
        Signed radius of curvature of the pitch curve (positive convex, ``inf``
        where straight; at arc rows the value of the adjacent phase).
    roller_radius, tolerance : float
        Length unit.
    centre : ndarray, shape (2,)
        Cam centre in the fixed frame.
    cam_sense : int
    R0 : float
        Base radius of the pitch curve, ``|P(0)|`` at the near dwell.
    """

    phi: np.ndarray
    phase: np.ndarray
    pitch: np.ndarray
    work: np.ndarray
    outer: np.ndarray | None
    normal: np.ndarray
    rho: np.ndarray
    roller_radius: float
    tolerance: float
    centre: np.ndarray
    cam_sense: int
    R0: float
    name: str = "cam"

    def __post_init__(self):
        for k in ("phi", "phase", "pitch", "work", "outer", "normal", "rho", "centre"):
            a = getattr(self, k)
            if a is not None:
                a.flags.writeable = False

    def __len__(self) -> int:
        return len(self.phi)

    @property
    def groove(self) -> bool:
        """True when the profile has an outer wall (form closure by a groove)."""
        return self.outer is not None

    @property
    def rho_work(self) -> np.ndarray:
        """Radius of curvature of the working profile, ``rho - r_roller`` (positive convex)."""
        return offset_radius(self.rho, -self.roller_radius)

    @property
    def rho_outer(self) -> np.ndarray | None:
        """Radius of curvature of the outer wall, ``rho + r_roller``, or ``None``."""
        return None if self.outer is None else offset_radius(self.rho, self.roller_radius)

    @property
    def min_work_radius(self) -> float:
        """Smallest distance of the sampled working profile from the cam centre (length)."""
        return float(_polyline_min_radius(self.work))


def _polyline_min_radius(pts: np.ndarray) -> float:
    """Distance from the origin to a closed polyline (its segments, not only vertices)."""
    a = pts
    b = np.roll(pts, -1, axis=0)
    d = b - a
    L2 = np.sum(d * d, axis=1)
    t = np.clip(np.divide(-np.sum(a * d, axis=1), L2, out=np.zeros_like(L2), where=L2 > 0), 0.0, 1.0)
    q = a + t[:, None] * d
    return float(np.min(np.linalg.norm(q, axis=1)))


def smallest_cam_radius(design: CamDesign, centre: np.ndarray, *, grid: int = 512) -> tuple[float, float]:
    """The cam's own smallest radius: the working profile's nearest point to the cam centre.

    R0 is the pitch curve's base radius (cam centre to roller centre at the
    near dwell); the cam itself is smaller by the roller. The working profile
    is the inner offset ``P - r n`` of the pitch curve, so its distance from
    the centre is ``min |P| - r``, reached where ``|P|`` is smallest (there the
    normal is radial); ``|P| = |A - O|`` is scanned on ``grid`` steps per phase
    and the minimum of each phase that can hold the smallest (within twice its
    largest step of the scan's lowest) refined by six tenfold zooms.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre O in the follower's fixed frame, length unit.
    grid : int, optional
        Steps per phase of the scan.

    Returns
    -------
    radius, phi : float
        ``min |P| - roller_radius`` (length; <= 0 when the roller reaches the
        centre: no cam) and the cam angle where it is reached (radians). A
        knife edge gives the pitch curve's smallest radius.
    """
    u = np.linspace(0.0, 1.0, grid + 1)
    scans = [np.linalg.norm(pitch_phase(design, centre, i, u).point, axis=1) for i in range(len(design.program.phases))]
    lowest = min(float(d.min()) for d in scans)
    best, best_phi = np.inf, 0.0
    for i, d in enumerate(scans):
        # between two samples |P| falls below the lower one by less than the largest step of the scan (twice
        # that, to be safe): only the phases that can hold the minimum are refined
        if d.min() > lowest + 2.0 * float(np.max(np.abs(np.diff(d)))):
            continue
        k = int(np.argmin(d))
        bu, bd = u[k], d[k]
        lo, hi = u[max(k - 1, 0)], u[min(k + 1, grid)]
        for _ in range(6):
            x = np.linspace(lo, hi, 21)
            dx = np.linalg.norm(pitch_phase(design, centre, i, x).point, axis=1)
            j = int(np.argmin(dx))
            if dx[j] < bd:
                bu, bd = float(x[j]), float(dx[j])
            lo, hi = x[max(j - 1, 0)], x[min(j + 1, 20)]
        if bd < best:
            best = bd
            best_phi = float(design.program.starts[i] + bu * design.program.phases[i].angle)
    return float(best - design.follower.roller_radius), best_phi


def default_bore_radius(profile: Profile) -> float:
    """Default bore radius: ``0.3 R0``, capped at 0.8 of the working profile's smallest radius.

    Lengths in the design's unit; the cap keeps a wall between bore and profile.
    """
    return float(min(0.3 * profile.R0, 0.8 * profile.min_work_radius))


def _motion(prog, ph: np.ndarray, u: np.ndarray) -> Motion:
    """Motion at positions ``u`` of phases ``ph`` (sorted by phase), one-sided at the phase ends."""
    cut = np.searchsorted(ph, np.arange(len(prog.phases) + 1))
    parts = [prog.evaluate_phase(i, u[a:b]) for i, (a, b) in enumerate(zip(cut[:-1], cut[1:])) if b > a]
    return Motion(*(np.concatenate([getattr(m, k) for m in parts]) for k in ("s", "ds", "d2s", "d3s")))


def _curves(design: CamDesign, centre, ph: np.ndarray, u: np.ndarray, r: float, groove: bool):
    """The exported curves at positions ``u`` of phases ``ph``: pitch, work (``r > 0``), outer (groove).

    Returns ``x, y, k``, arrays of shape ``(curves, len(u))``: the points'
    components in the cam frame (length) and the curves' absolute curvature
    (1/length; an offset ``d`` along the normal has ``kappa / (1 + d kappa)``).
    """
    prog = design.program
    angles = np.array([p.angle for p in prog.phases])
    phi = prog.starts[ph] + u * angles[ph]
    _, _, (px, py), (nx, ny), kappa = _pitch_values(design, centre, phi, _motion(prog, ph, u))
    xs, ys, ks = [px], [py], [np.abs(kappa)]
    with np.errstate(divide="ignore", invalid="ignore"):
        for d in ([-r] if r > 0 else []) + ([r] if groove else []):
            xs.append(px + d * nx)
            ys.append(py + d * ny)
            ks.append(np.abs(kappa / (1.0 + d * kappa)))
    return np.array(xs), np.array(ys), np.array(ks)


def _merge(a: np.ndarray, b: np.ndarray, kept: np.ndarray) -> np.ndarray:
    """``a`` and ``b`` interleaved along the last axis: ``a`` where ``kept``, ``b`` elsewhere."""
    out = np.empty(a.shape[:-1] + kept.shape, dtype=a.dtype)
    out[..., kept] = a
    out[..., ~kept] = b
    return out


def _sample(design: CamDesign, centre, tol: float, r: float, groove: bool) -> list[np.ndarray]:
    """Adaptive normalized positions ``u`` of every phase (0 and 1 included), one array per phase.

    Each chord is split at its middle while the sagitta of any exported curve,
    estimated as ``max(L^2 |kappa|_max / 8, distance of the mid-point from the
    chord)``, exceeds ``tol``; chords shorter than ``tol`` are accepted (the
    curve then stays within ``tol`` of them up to a cusp of an undercut
    profile). All phases are refined together and every position is
    evaluated once: a round evaluates the mid-points of the fresh chords of
    every phase, and a mid-point that splits its chord keeps its values as an
    end of two of the next round's fresh chords.
    """
    prog = design.program
    us = []
    for p in prog.phases:
        n0 = 2 if p.kind == "dwell" else 16
        bps = tuple(getattr(p.law, "breakpoints", ())) if p.law is not None else ()
        us.append(np.unique(np.concatenate([np.linspace(0.0, 1.0, n0 + 1), np.asarray(bps, float)])))
    # all phases' positions in one array, in phase order; a chord joins neighbours of the same phase
    ph = np.concatenate([np.full(len(u), i) for i, u in enumerate(us)])
    u = np.concatenate(us)
    du_min = 1e-12
    x, y, kk = _curves(design, centre, ph, u, r, groove)  # every curve at every position
    fresh = ph[1:] == ph[:-1]
    for _ in range(64):
        idx = np.nonzero(fresh)[0]
        if len(idx) == 0:
            break
        ua, ub = u[idx], u[idx + 1]
        um = 0.5 * (ua + ub)
        xm, ym, km = _curves(design, centre, ph[idx], um, r, groove)
        # chord a-b and mid-point m of every fresh chord, on every curve (rows)
        ax, ay, ka, kb = x[:, idx], y[:, idx], kk[:, idx], kk[:, idx + 1]
        dx, dy = x[:, idx + 1] - ax, y[:, idx + 1] - ay
        mx, my = xm - ax, ym - ay
        L = np.sqrt(dx * dx + dy * dy)
        with np.errstate(divide="ignore", invalid="ignore"):
            dev = np.where(L > 0, np.abs(dx * my - dy * mx) / np.where(L > 0, L, 1.0), np.sqrt(mx * mx + my * my))
            k = np.fmax(np.fmax(ka, kb), km)
            k = np.where(np.isnan(k), np.inf, k)
            est = np.where(k > 0, L * L * k / 8.0, 0.0)
        sag = np.fmax(dev, np.where(np.isnan(est), np.inf, est))
        split = np.any((sag > tol) & (L > tol), axis=0) & ((ub - ua) > du_min)
        if not np.any(split):
            break
        if len(u) + int(split.sum()) > MAX_POINTS:
            raise ProfileSizeError("profile.tolerance",
                                   f"{tol:g} needs more than {MAX_POINTS} points; choose a larger tolerance")
        # the mid-points of the split chords go between their ends (the k-th split one to idx + 1 + k);
        # the two halves of each split chord are the next round's fresh chords
        new = idx[split] + 1 + np.arange(int(split.sum()))
        kept = np.ones(len(u) + len(new), dtype=bool)
        kept[new] = False
        u, ph = _merge(u, um[split], kept), _merge(ph, ph[idx[split]], kept)
        x, y, kk = _merge(x, xm[:, split], kept), _merge(y, ym[:, split], kept), _merge(kk, km[:, split], kept)
        fresh = np.zeros(len(u) - 1, dtype=bool)
        fresh[new - 1] = fresh[new] = True
    return [u[ph == i] for i in range(len(prog.phases))]


def _corner_arc(P: np.ndarray, n1: np.ndarray, n2: np.ndarray, dist: float, tol: float) -> np.ndarray:
    """Points of the circle of radius ``|dist|`` about ``P`` from ``dist n1`` to ``dist n2`` (short way), ends excluded."""
    a1, a2 = np.arctan2(n1[1], n1[0]), np.arctan2(n2[1], n2[0])
    da = (a2 - a1 + np.pi) % (2 * np.pi) - np.pi
    rr = abs(dist)
    step = 2 * np.arccos(max(1.0 - tol / rr, -1.0)) if rr > tol else np.pi
    k = int(np.ceil(abs(da) / step))
    if k <= 1:
        return np.empty((0, 2))
    t = a1 + da * np.arange(1, k) / k
    return P + dist * _xy(np.cos(t), np.sin(t))


def build_profile(
    design: CamDesign,
    centre: np.ndarray,
    *,
    tolerance: float | None = None,
    groove: bool | None = None,
    field: str = "tolerance",
) -> Profile:
    """Sample the pitch curve and working profile(s) of a sized cam.

    Every phase start is a sample (and every breakpoint of a piecewise law);
    between them the chords are halved until their sagitta on every exported
    curve is within ``tolerance`` (vectorized adaptive subdivision), so the
    samples are dense where the curvature is high.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre O in the fixed frame (``SolveResult.centre``), length unit.
    tolerance : float, optional
        Chord tolerance, length unit, at most 5 % of the cam's smallest radius
        (:func:`cap_tolerance`); default 1e-3 (1 micrometre in mm), 0.1 % of
        the smallest radius when that is under 1 mm.
    groove : bool, optional
        Add the outer wall of a groove; default: ``True`` for form closure.
    field : str, optional
        Where the tolerance was given, for the messages.

    Returns
    -------
    Profile

    Raises
    ------
    InputError
        ``tolerance <= 0`` or above 5 % of the cam's smallest radius; a groove
        with a knife edge (roller radius 0).
    """
    f = design.follower
    r = float(f.roller_radius)
    centre = np.asarray(centre, dtype=float)
    R0 = float(np.linalg.norm(f.position(0.0) - centre))
    tol = cap_tolerance(tolerance, smallest_radius(R0, r), field)
    if groove is None:
        groove = design.limits.closure == "form"
    if groove and r <= 0:
        raise InputError("follower.roller_radius", "a groove cam (form closure) needs a roller radius > 0")
    prog = design.program
    nph = len(prog.phases)
    blocks: list[dict] = []
    closing = None
    for i, u in enumerate(_sample(design, centre, tol, r, groove)):
        g = pitch_phase(design, centre, i, u[:-1])
        blocks.append(_rows(g, i, g.offset(-r), g.offset(r) if groove else None))
        if r > 0:
            joint = _joint_rows(design, centre, i, r, groove, tol)
            if joint is not None and i == nph - 1:
                closing = joint  # phi = 2 pi is phi = 0: these rows come first
            elif joint is not None:
                blocks.append(joint)
    if closing is not None:
        blocks.insert(0, closing)
    cat = {k: np.concatenate([b[k] for b in blocks]) for k in ("phi", "phase", "pitch", "work", "normal", "rho")}
    return Profile(
        **cat,
        outer=np.concatenate([b["outer"] for b in blocks]) if groove else None,
        roller_radius=r,
        tolerance=tol,
        centre=centre.copy(),
        cam_sense=design.cam_sense,
        R0=R0,
        name=design.name,
    )


def _rows(g: PitchGeometry, i: int, work: np.ndarray, outer: np.ndarray | None, phi=None) -> dict:
    n = len(g.phi)
    return {
        "phi": g.phi if phi is None else np.full(n, phi),
        "phase": np.full(n, i),
        "pitch": g.point,
        "work": work,
        "outer": outer,
        "normal": g.normal,
        "rho": g.rho,
    }


def _joint_rows(design: CamDesign, centre, i: int, r: float, groove: bool, tol: float) -> dict | None:
    """Roller-circle arc rows filling an offset curve's gap at a pitch-curve corner.

    At the joint of phase ``i`` with the next one the pitch curve has a corner
    when the follower's velocity jumps (e.g. a constant-velocity law). A
    concave corner opens a gap in the working profile (filled by the roller
    circle about the corner), a convex one in a groove's outer wall; the other
    offset crosses itself there (a sharp point, reported by the checks).
    """
    prog = design.program
    nph = len(prog.phases)
    j = (i + 1) % nph
    end = pitch_phase(design, centre, i, np.array([1.0]))
    start = pitch_phase(design, centre, j, np.array([0.0]))
    n1, n2 = end.normal[0], start.normal[0]
    if not np.linalg.norm(n1 - n2) > 1e-12:
        return None
    convex = np.sign(_cross(end.d1[0], start.d1[0])) == -design.cam_sense
    P = start.point[0]
    arc_w = np.empty((0, 2)) if convex else _corner_arc(P, n1, n2, -r, tol)
    arc_o = _corner_arc(P, n1, n2, r, tol) if (groove and convex) else np.empty((0, 2))
    k = max(len(arc_w), len(arc_o))
    if k == 0:
        return None
    # one row per arc point; the curve without an arc repeats its end point
    wk = arc_w if len(arc_w) == k else np.repeat((P - r * n1)[None], k, 0)
    ok = arc_o if len(arc_o) == k else np.repeat((P + r * n1)[None], k, 0)
    rep = lambda a: np.repeat(a, k, 0)  # noqa: E731
    g = PitchGeometry(phi=rep(end.phi), point=np.repeat(P[None], k, 0), d1=rep(end.d1), d2=rep(end.d2),
                      normal=rep(end.normal), kappa=rep(end.kappa), s=rep(end.s), rise_dir=rep(end.rise_dir))
    return _rows(g, j, wk, ok if groove else None, phi=prog.starts[j])
