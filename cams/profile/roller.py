"""Cam profiles of roller and knife-edge followers: working profile(s), sampling, options.

The geometry (the inversion: pitch curve, its derivatives, outward normal,
signed curvature) is the kernel's, :mod:`cams.kinematics.inversion`, whose
frames and signs hold here:

* Cam frame: origin at the cam centre, axes parallel to the fixed frame when
  the cam is at ``phi = 0``, turning with the cam (``eps = design.cam_sense``).
* Pitch curve ``P(phi) = R(-eps phi) (A(s(phi)) - O)``; outward normal ``n``
  (away from the cam's material); signed curvature ``kappa`` and radius
  ``rho = 1 / kappa``, **positive where the curve is convex**.
* Working profile (roller follower): the envelope of the roller circles, the
  inner offset ``W = P - r_roller n`` with ``rho_w = rho - r_roller``. For a
  groove (form closure) the outer wall ``P + r_roller n`` has
  ``rho_o = rho + r_roller`` (same sign convention: positive when its centre
  of curvature lies on the cam centre's side). A knife edge (roller radius 0)
  has working profile = pitch curve.

The pitch curve and its geometry are the kernel's (:mod:`cams.kinematics.inversion`);
the options are the model's (:mod:`cams.model.options`).

Angles are radians; lengths are the design's unit (mm).
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import pairwise
from typing import Protocol

import numpy as np

from cams.kinematics.inversion import (
    PitchGeometry,
    curvature,
    invert,
    offset_curvature,
    offset_radius,
    outward_normal,
    pitch_phase,
    smallest_cam_radius,
)
from cams.kinematics.vectors import cross, xy
from cams.model.design import CamDesign
from cams.model.options import (
    check_tolerance,
)
from laws.errors import InputError
from laws.program import Motion
from laws.units import TWO_PI

__all__ = [
    "ProfileSizeError",
    "Profile",
    "build_profile",
    "default_bore_radius",
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
#: The default tolerance is at most this fraction of the cam's size (below 1 mm: finer than 1 um).
DEFAULT_TOLERANCE_FRACTION = 1e-3
#: Keys the ``[profile]`` table of a design file may hold (:mod:`cams.io.designfile` maps them onto the design).
PROFILE_KEYS = ("tolerance", "min_curvature_radius")
#: Largest number of samples of one profile (guards against endless refinement).
MAX_POINTS = 2_000_000


class ProfileSizeError(InputError):
    """The profile needs more than :data:`MAX_POINTS` points at its chord tolerance.

    Raised once, where the points are counted (:func:`build_profile`), naming
    the field the tolerance was given in (``--tolerance`` on the command line:
    bad input, which :func:`cams.assess.assess_cam` re-raises; the design
    file's ``profile.tolerance``: the cam is not buildable at it).
    """




def smallest_radius(R0: float, roller_radius: float = 0.0) -> float:
    """The cam's smallest radius (length): its working profile's least distance from the centre.

    ``R0 - r`` for a roller follower (the base circle of the pitch curve less
    the roller; a lower bound, reached on the base circle), ``R0`` for a knife
    edge or a flat face (their profile's base radius). When ``R0 <= r`` there
    is no working profile (not buildable); the curves drawn then are the size
    of the roller, and ``max(R0, r)`` sets their sampling.
    """
    return R0 - roller_radius if R0 > roller_radius else max(R0, roller_radius)


def cap_tolerance(tolerance: float | None, smallest: float, field: str, *, size: float | None = None) -> float:
    """The chord tolerance for a cam whose smallest radius is ``smallest``, refusing one too coarse for it.

    Parameters
    ----------
    tolerance : float or None
        The tolerance given (length); None: ``min(DEFAULT_TOLERANCE,
        DEFAULT_TOLERANCE_FRACTION * size)``, so a cam under a millimetre is
        sampled as finely for its size.
    smallest : float
        The cam's smallest radius (:func:`smallest_radius`), length.
    field : str
        Where the tolerance was given, for the message.
    size : float, optional
        The cam's size for the default (length): a roller's R0 (the pitch curve's base radius: a cam whose own
        smallest radius tends to 0, sized just clear of its roller, is not sampled ever finer for it); default
        ``smallest``.

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
        scale = smallest if size is None else size
        return float(min(DEFAULT_TOLERANCE, DEFAULT_TOLERANCE_FRACTION * scale)) if scale > 0 \
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
    min_work_radius : float
        The working profile's smallest distance from the cam centre (length): the exact one of the kernel
        (:func:`cams.kinematics.inversion.smallest_cam_radius`, ``min |P| - r``), not the sampled polyline's, so
        that the cam's smallest radius is one number in every report, check and drawing; NaN when not given.
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
    min_work_radius: float = float("nan")

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



class _Radii(Protocol):
    """What the default bore needs of a profile (a roller's or a flat face's)."""

    @property
    def R0(self) -> float: ...

    @property
    def min_work_radius(self) -> float: ...


def default_bore_radius(profile: Profile | _Radii) -> float:
    """Default bore radius: ``0.3 R0``, capped at 0.8 of the working profile's smallest radius.

    Lengths in the design's unit; the cap keeps a wall between bore and profile.
    """
    return float(min(0.3 * profile.R0, 0.8 * profile.min_work_radius))


def _motion(prog, ph: np.ndarray, u: np.ndarray) -> Motion:
    """Motion at positions ``u`` of phases ``ph`` (sorted by phase), one-sided at the phase ends."""
    cut = np.searchsorted(ph, np.arange(len(prog.phases) + 1))
    parts = [prog.evaluate_phase(i, u[a:b]) for i, (a, b) in enumerate(pairwise(cut)) if b > a]
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
    inv = invert(design, centre, phi, _motion(prog, ph, u))
    P, n, kappa = inv.point, outward_normal(inv), curvature(inv)
    xs, ys, ks = [P[:, 0]], [P[:, 1]], [np.abs(kappa)]
    for d in ([-r] if r > 0 else []) + ([r] if groove else []):
        xs.append(P[:, 0] + d * n[:, 0])
        ys.append(P[:, 1] + d * n[:, 1])
        ks.append(np.abs(offset_curvature(kappa, d)))
    return np.array(xs), np.array(ys), np.array(ks)


def _merge(a: np.ndarray, b: np.ndarray, kept: np.ndarray) -> np.ndarray:
    """``a`` and ``b`` interleaved along the last axis: ``a`` where ``kept``, ``b`` elsewhere."""
    out = np.empty(a.shape[:-1] + kept.shape, dtype=a.dtype)
    out[..., kept] = a
    out[..., ~kept] = b
    return out


def _sample(design: CamDesign, centre, tol: float, r: float, groove: bool, field: str) -> list[np.ndarray]:
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
            raise ProfileSizeError(field, f"{tol:g} needs more than {MAX_POINTS} points; choose a larger tolerance")
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
    """Points of the circle of radius ``|dist|`` about ``P`` from ``dist n1`` to ``dist n2``.

    The short way round, ends excluded.
    """
    a1, a2 = np.arctan2(n1[1], n1[0]), np.arctan2(n2[1], n2[0])
    da = (a2 - a1 + np.pi) % TWO_PI - np.pi
    rr = abs(dist)
    step = 2 * np.arccos(max(1.0 - tol / rr, -1.0)) if rr > tol else np.pi
    k = int(np.ceil(abs(da) / step))
    if k <= 1:
        return np.empty((0, 2))
    t = a1 + da * np.arange(1, k) / k
    return P + dist * xy(np.cos(t), np.sin(t))


def build_profile(
    design: CamDesign,
    centre: np.ndarray,
    *,
    tolerance: float | None = None,
    groove: bool | None = None,
    field: str = "profile.tolerance",
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
        R0 when that is under 1 mm.
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
    ProfileSizeError
        Naming ``field``: the profile needs more than :data:`MAX_POINTS`
        points at ``tolerance``.
    """
    f = design.follower
    r = float(f.roller_radius)
    centre = np.asarray(centre, dtype=float)
    R0 = float(np.linalg.norm(f.position(0.0) - centre))
    smallest = smallest_cam_radius(design, centre)[0]
    tol = cap_tolerance(tolerance, smallest if smallest > 0 else smallest_radius(R0, r), field, size=R0)
    if groove is None:
        groove = design.limits.closure == "form"
    if groove and r <= 0:
        raise InputError("follower.roller_radius", "a groove cam (form closure) needs a roller radius > 0")
    prog = design.program
    nph = len(prog.phases)
    blocks: list[dict] = []
    closing = None
    for i, u in enumerate(_sample(design, centre, tol, r, groove, field)):
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
        min_work_radius=float(smallest),
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
    convex = np.sign(cross(end.d1[0], start.d1[0])) == -design.cam_sense
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
