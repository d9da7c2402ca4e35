"""Checks of a finished cam profile: jamming, undercut and sharp points, validity, bore.

Every check is recomputed from the profile (the pitch curve of
:mod:`cams.profile.roller`), independently of the solver's zone formulas:

* ``jamming_rise`` / ``jamming_return``: the pressure angle over the whole of
  every constrained phase (the rise; the return too under form closure),
  from the pitch curve's tangent. The contact normal is the pitch curve's
  outward normal turned into the fixed frame, ``n = R(eps phi) n_cam``; the
  pressure angle is ``gamma = arccos(n . e)`` with ``e`` the unit direction of
  the roller centre's rise (degrees in the report). Values above 90 degrees
  mean the cam would pull instead of push.
* ``undercut``: the pitch curve's smallest convex radius of curvature
  ``rho_min`` must exceed the roller radius, else the working profile has
  cusps (a knife edge: ``rho_min > 0``, no sharp point). A convex corner of
  the pitch curve at a phase joint (velocity jump) counts as ``rho = 0``.
  ``rho_min`` is the largest roller radius that avoids undercut; the usual
  recommendation is ``0.8 rho_min``.
* ``undercut_outer`` (groove): the same for the outer wall, with the pitch
  curve's smallest concave radius ``|rho|``.
* ``min_curvature_radius`` (when ``[profile] min_curvature_radius`` is set):
  the working profile's smallest convex radius ``rho - r_roller`` (and the
  outer wall's ``|rho| - r_roller``) against the user minimum.
* ``profile_polygon`` / ``outer_polygon``: the closed sampled curve is a valid,
  simple polygon (no self-intersection) around the cam centre (shapely).
* ``bore`` (when ``[cam] bore_radius`` is given): the working profile's
  smallest distance from the cam centre exceeds the bore radius.

Extremes are located on a dense grid per phase (``grid + 1`` positions, and
both sides of a piecewise law's breakpoints) and refined between grid points
where their analytic derivative by the cam angle changes sign: all brackets
together, one array evaluation a step (:func:`_maximize`). They do not depend
on the profile's sampling.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from cams.model.design import CamDesign
from cams.profile.roller import (
    Profile,
    ProfileOptions,
    _cross,
    _inversion,
    build_profile,
    default_bore_radius,
    pitch_phase,
    profile_options,
    smallest_cam_radius,
)

__all__ = [
    "Check",
    "CheckReport",
    "pressure_from_profile",
    "curvature_extremes",
    "CurvatureExtremes",
    "check_profile",
    "check_solution",
    "check_design",
    "RECOMMENDED_ROLLER_FRACTION",
]

#: Usual rule: roller radius at most this fraction of the smallest convex rho.
RECOMMENDED_ROLLER_FRACTION = 0.8


@dataclass(frozen=True)
class Check:
    """One check's outcome.

    Attributes
    ----------
    name : str
    passed : bool
    worst : float or None
        Worst value found (unit ``unit``); ``None`` where it does not apply.
    at_deg : float or None
        Cam angle of the worst value, degrees in [0, 360).
    limit : float or None
        The value ``worst`` is compared with (unit ``unit``).
    unit : str
        ``"deg"``, ``"mm"`` (the design's length unit) or ``""``.
    message : str
        One readable line.
    """

    name: str
    passed: bool
    worst: float | None
    at_deg: float | None
    limit: float | None
    unit: str
    message: str = ""

    def to_dict(self) -> dict:
        """JSON-ready ``{name, passed, worst, at_deg, limit, unit}`` (non-finite values as ``None``)."""
        return {
            "name": self.name,
            "passed": bool(self.passed),
            "worst": _finite(self.worst),
            "at_deg": _finite(self.at_deg),
            "limit": _finite(self.limit),
            "unit": self.unit,
        }


def _finite(x):
    return None if x is None or not np.isfinite(x) else float(x)


class ChecksMixin:
    """``passed`` and lookup by name for a report holding ``checks`` (a tuple of :class:`Check`)."""

    checks: tuple

    @property
    def passed(self) -> bool:
        """True when every check passed."""
        return all(c.passed for c in self.checks)

    def __getitem__(self, name: str) -> Check:
        for c in self.checks:
            if c.name == name:
                return c
        raise KeyError(name)


@dataclass(frozen=True, eq=False)
class CheckReport(ChecksMixin):
    """The checks of one profile.

    Attributes
    ----------
    name : str
        Design name.
    checks : tuple of Check
    profile : Profile
        The checked profile (its sampling is what the polygon checks used).
    largest_roller_radius : float
        Smallest convex radius of curvature of the pitch curve (length): the
        largest roller that avoids undercut (for a groove also bounded by the
        smallest concave radius).
    recommended_roller_radius : float
        ``0.8 * largest_roller_radius``.
    bore_radius : float
        Bore radius used (length).
    """

    name: str
    checks: tuple[Check, ...]
    profile: Profile
    largest_roller_radius: float
    recommended_roller_radius: float
    bore_radius: float
    extra: dict = field(default_factory=dict, compare=False)

    def to_dict(self) -> dict:
        """JSON-ready report: lengths in the design's unit, angles in degrees."""
        return {
            "name": self.name,
            "passed": bool(self.passed),
            "checks": [c.to_dict() for c in self.checks],
            "roller_radius": float(self.profile.roller_radius),
            "largest_roller_radius": _finite(self.largest_roller_radius),
            "recommended_roller_radius": _finite(self.recommended_roller_radius),
            "bore_radius": float(self.bore_radius),
            "R0": float(self.profile.R0),
            "points": len(self.profile),
            "tolerance": float(self.profile.tolerance),
            **self.extra,
        }


# -- pressure angle and curvature with their slopes -------------------------------------------


def _pressure_rates(inv, eps: int, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Pressure angle (radians, in [0, pi]) and its derivative by the cam angle (per radian).

    Parameters
    ----------
    inv : cams.profile.roller._Inversion
        The inverted motion at the positions.
    eps : {+1, -1}
        The cam's sense of rotation.
    ds : ndarray
        ``s'``, the follower's displacement per radian of cam angle.

    Notes
    -----
    The contact normal in the fixed frame is along ``eps J w1`` (the pitch
    curve's outward normal turned back by ``R(eps phi)``), the follower's
    velocity along ``T = dA/ds``. With ``alpha`` the signed angle from the
    normal to ``T``, ``gamma = |alpha|`` and
    ``d alpha / dphi = s' (T x T2) / |T|^2 - (w1 x w2) / |w1|^2 - eps``
    (the turn of ``T`` less the turn of the normal, ``w1' = w2 + eps J w1``).
    """
    (wx, wy), (vx, vy), (tx, ty), (bx, by) = inv.w1, inv.w2, inv.t, inv.t2
    nx, ny = -eps * wy, eps * wx
    sin_, cos_ = nx * ty - ny * tx, nx * tx + ny * ty  # both times |n| |T| > 0
    gamma = np.arctan2(np.abs(sin_), cos_)
    with np.errstate(divide="ignore", invalid="ignore"):
        dalpha = ds * (tx * by - ty * bx) / (tx * tx + ty * ty) - (wx * vy - wy * vx) / (wx * wx + wy * wy) - eps
    return gamma, np.sign(sin_) * dalpha


def _curvature_rates(inv, eps: int) -> tuple[np.ndarray, np.ndarray]:
    """Signed curvature (1/length, positive convex) and its derivative by the cam angle (1/length per radian).

    ``kappa = -eps (w1 x w2) / |w1|^3``, so
    ``dkappa/dphi = -eps ((w1 x w3) / |w1|^3 - 3 (w1 x w2)(w1 . w2) / |w1|^5)``
    (``inv`` computed with ``third=True``).
    """
    (wx, wy), (vx, vy), (zx, zy) = inv.w1, inv.w2, inv.w3
    speed = np.sqrt(wx * wx + wy * wy)
    cr = wx * vy - wy * vx
    with np.errstate(divide="ignore", invalid="ignore"):
        kappa = -eps * cr / speed**3
        dkappa = -eps * ((wx * zy - wy * zx) / speed**3 - 3 * cr * (wx * vx + wy * vy) / speed**5)
    return kappa, dkappa


def pressure_from_profile(design: CamDesign, centre: np.ndarray, phase: int, u: np.ndarray) -> np.ndarray:
    """Pressure angle (radians, in [0, pi]) from the pitch curve's tangent.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre, fixed frame.
    phase : int
    u : array_like
        Normalized positions in the phase, [0, 1].

    Notes
    -----
    The contact normal is the pitch curve's outward normal (cam frame) turned
    into the fixed frame by ``R(eps phi)``; the follower's velocity is along
    ``e = dA/ds / |dA/ds|``. ``gamma = arccos(n . e)``, computed as
    ``atan2(|n x e|, n . e)`` (accurate near 0), on the components in the
    fixed frame (:func:`_pressure_rates`).
    """
    u = np.atleast_1d(np.asarray(u, dtype=float))
    m = design.program.evaluate_phase(phase, u)
    inv = _inversion(design, np.asarray(centre, dtype=float), m)
    return _pressure_rates(inv, design.cam_sense, m.ds)[0]


def _phase_rates(design: CamDesign, centre: np.ndarray, i: int, u: np.ndarray, what: tuple[str, ...]):
    """Functions of phase ``i`` at positions ``u`` and their derivatives by the cam angle.

    ``what`` names the rows: ``"convex"`` (kappa, 1/length), ``"concave"``
    (-kappa) and ``"pressure"`` (radians). Returns ``values, slopes``, arrays
    of shape ``(len(what), len(u))``.
    """
    m = design.program.evaluate_phase(i, u)
    eps = design.cam_sense
    inv = _inversion(design, centre, m, third="convex" in what or "concave" in what)
    rows = {}
    if "convex" in what or "concave" in what:
        k, dk = _curvature_rates(inv, eps)
        rows["convex"], rows["concave"] = (k, dk), (-k, -dk)
    if "pressure" in what:
        rows["pressure"] = _pressure_rates(inv, eps, m.ds)
    return np.array([rows[w][0] for w in what]), np.array([rows[w][1] for w in what])


# -- the largest values over a phase -----------------------------------------------------------

#: Largest number of refinement steps (one array evaluation each) of :func:`_maximize`.
MAX_STEPS = 60
#: Width of a bracket (normalized position u) at which its refinement stops.
U_TOL = 1e-12


def _grid(design: CamDesign, i: int, grid: int) -> np.ndarray:
    """Positions ``u`` searched over phase ``i``.

    ``grid + 1`` even positions, and both sides of each breakpoint of the
    phase's law: a piecewise law's derivatives may jump there, and with the
    positions one rounding step either side of it each piece is smooth between
    neighbouring positions and its one-sided ends are on the grid. A dwell's
    functions are constant (the pitch curve is a circle): its two ends only.
    """
    p = design.program.phases[i]
    if p.kind == "dwell":
        return np.array([0.0, 1.0])
    u = np.linspace(0.0, 1.0, grid + 1)
    bps = np.asarray(getattr(p.law, "breakpoints", ()), dtype=float)
    bps = bps[(bps > 0) & (bps < 1)]
    if len(bps) == 0:
        return u
    return np.unique(np.concatenate([u, bps, np.nextafter(bps, 0.0), np.nextafter(bps, 1.0)]))


def _maximize(fun, u: np.ndarray, *, refine: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Largest values of ``q`` smooth functions over sorted positions, refined between them.

    Parameters
    ----------
    fun : callable
        ``fun(x) -> (values, slopes)``, arrays of shape ``(q, len(x))``: the
        functions at positions ``x`` and their derivatives (any positive
        multiple of ``d/dx``).
    u : ndarray, shape (n,)
        Increasing positions covering the interval; the functions are smooth
        between neighbouring positions.
    refine : bool
        Refine the local maxima between positions (else the grid's best).

    Returns
    -------
    best, at : ndarray, shape (q,)
        Largest value of each function and its position.

    Notes
    -----
    Every pair of neighbouring positions where a function's slope turns from
    positive to non-positive brackets a local maximum. All brackets of all
    functions are refined together: each step evaluates ``fun`` once, at the
    regula-falsi point on the slopes of every open bracket (the Illinois
    variant: the slope of an end kept twice in a row is halved, so both ends
    converge), at least ``U_TOL / 2`` inside it, and keeps the part where the
    slope changes sign. A bracket closes at width ``U_TOL`` (or where the
    slope is 0); there are at most ``MAX_STEPS`` steps. The best value
    evaluated in a bracket replaces the grid's best if it is larger.
    """
    v, dv = fun(u)
    rows = np.arange(len(v))
    k = np.nanargmax(v, axis=1)
    best, at = v[rows, k], u[k]
    if not refine:
        return best, at
    row, j = np.nonzero((dv[:, :-1] > 0) & (dv[:, 1:] <= 0))
    a, b = u[j], u[j + 1]
    fa, fb = dv[row, j], dv[row, j + 1]
    a = np.where(fb == 0, b, a)  # the slope vanishes at the right end: that is the maximum
    top, top_u = np.full(len(j), -np.inf), a.copy()
    kept = np.zeros(len(j), dtype=int)  # +1: a moved last, -1: b moved last
    for _ in range(MAX_STEPS):
        act = np.nonzero(b - a > U_TOL)[0]
        if len(act) == 0:
            break
        A, B, FA, FB = a[act], b[act], fa[act], fb[act]
        x = B - FB * (B - A) / (FB - FA)  # FA > 0 > FB
        # at least U_TOL / 2 inside: a root within that of an end closes the bracket next step
        x = np.clip(np.where(np.isfinite(x), x, 0.5 * (A + B)), A + U_TOL / 2, B - U_TOL / 2)
        vx, dx = fun(x)
        n = np.arange(len(act))
        vx, dx = vx[row[act], n], dx[row[act], n]
        better = vx > top[act]
        top[act[better]], top_u[act[better]] = vx[better], x[better]
        up, down = dx > 0, dx < 0
        ia, ib, done = act[up], act[down], act[~(up | down)]  # slope 0 (or not a number): stop there
        fb[ia[kept[ia] == 1]] *= 0.5
        fa[ib[kept[ib] == -1]] *= 0.5
        a[ia], fa[ia], kept[ia] = x[up], dx[up], 1
        b[ib], fb[ib], kept[ib] = x[down], dx[down], -1
        a[done] = b[done] = x[~(up | down)]
    for q in rows:
        mine = np.nonzero(row == q)[0]
        if len(mine) and top[mine].max() > best[q]:
            w = mine[np.argmax(top[mine])]
            best[q], at[q] = top[w], top_u[w]
    return best, at


def _phase_maxima(design: CamDesign, centre: np.ndarray, grid: int, pressure=()) -> list[dict]:
    """Largest curvature, negative curvature and pressure angle of every phase.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre, fixed frame, length unit.
    grid : int
        Even positions per phase of the search, ``grid + 1``.
    pressure : collection of int
        Phases whose largest pressure angle is wanted too.

    Returns
    -------
    list of dict
        Per phase, ``{"convex": (kappa, phi), "concave": (-kappa, phi)}`` and
        ``"pressure": (gamma, phi)`` for the phases in ``pressure``: the
        largest value (1/length; radians) and the cam angle where it is
        (radians). A dwell is not refined (its values are constant).
    """
    prog = design.program
    centre = np.asarray(centre, dtype=float)
    out = []
    for i, p in enumerate(prog.phases):
        what = ("convex", "concave") + (("pressure",) if i in pressure else ())
        best, at = _maximize(lambda x: _phase_rates(design, centre, i, x, what), _grid(design, i, grid),
                             refine=p.kind != "dwell")
        out.append({w: (float(b), float(prog.starts[i] + a * p.angle)) for w, b, a in zip(what, best, at)})
    return out


# -- curvature --------------------------------------------------------------------------------


@dataclass(frozen=True)
class CurvatureExtremes:
    """Smallest convex and concave radii of curvature of the pitch curve.

    ``convex`` and ``concave`` are lengths (``concave`` as ``|rho|``; ``inf``
    when the curve has no such part); ``*_at`` cam angles in radians. A corner
    at a phase joint counts as radius 0.
    """

    convex: float
    convex_at: float
    concave: float
    concave_at: float | None


def curvature_extremes(design: CamDesign, centre: np.ndarray, *, grid: int = 2000) -> CurvatureExtremes:
    """Smallest convex and concave radius of curvature of the pitch curve.

    The largest signed curvature ``kappa`` (and the largest ``-kappa``) is
    found per phase on ``grid + 1`` positions and refined where its analytic
    derivative changes sign (:func:`_maximize`); ``rho = 1 / kappa``. Phase
    joints where the pitch curve has a corner give radius 0 on their side.
    """
    return _curvature(design, centre, _phase_maxima(design, centre, grid))


def _curvature(design: CamDesign, centre: np.ndarray, maxima: list[dict]) -> CurvatureExtremes:
    """:class:`CurvatureExtremes` from the phases' maxima (:func:`_phase_maxima`) and the joints' corners."""
    kmax, kat = -np.inf, 0.0
    cmax, cat = -np.inf, None
    prog = design.program
    nph = len(prog.phases)
    for i in range(nph):
        (k, at), (c, c_at) = maxima[i]["convex"], maxima[i]["concave"]
        if k > kmax:
            kmax, kat = k, at
        if c > cmax:
            cmax, cat = c, c_at
        end = pitch_phase(design, centre, i, np.array([1.0]))
        start = pitch_phase(design, centre, (i + 1) % nph, np.array([0.0]))
        t1, t2 = end.d1[0], start.d1[0]
        cosang = np.dot(t1, t2) / (np.linalg.norm(t1) * np.linalg.norm(t2))
        if cosang < 1 - 1e-12:
            at = float(prog.starts[i + 1] % (2 * np.pi))
            if np.sign(_cross(t1, t2)) == -design.cam_sense:
                kmax, kat = np.inf, at
            elif cmax < np.inf:
                cmax, cat = np.inf, at
    convex = 1.0 / kmax if kmax > 0 else np.inf
    concave = 1.0 / cmax if cmax > 0 else np.inf
    return CurvatureExtremes(float(convex), float(kat), float(concave), None if cmax <= 0 else cat)


# -- the checks ------------------------------------------------------------------------------


def _deg(phi: float | None) -> float | None:
    return None if phi is None else float(np.degrees(phi) % 360.0)


def _polygon_check(name: str, pts: np.ndarray, phi: np.ndarray) -> Check:
    """The closed polyline ``pts`` is a valid simple polygon round the origin.

    ``worst`` is the number of self-crossings (limit 0); ``at_deg`` the cam
    angle of the sample nearest the first crossing (or shapely's reported
    location of another defect).
    """
    import shapely
    from shapely.geometry import LinearRing, Point, Polygon

    ring = LinearRing(pts)
    poly = Polygon(ring)
    valid = bool(poly.is_valid and ring.is_simple)
    around = bool(poly.contains(Point(0.0, 0.0)))
    at = None
    crossings = 0
    msg = f"{len(pts)} points, a simple closed curve round the cam centre"
    if not valid:
        loc = None
        reason = shapely.is_valid_reason(poly)
        if not ring.is_simple:
            # noding the ring adds its crossings as new vertices
            nodes = shapely.get_coordinates(shapely.unary_union(ring))
            known = {tuple(p) for p in np.round(pts, 9)}
            extra = {tuple(p) for p in np.round(nodes, 9)} - known
            crossings = len(extra)
            loc = np.array(sorted(extra)[0]) if extra else None
        if loc is None and "[" in reason:
            try:
                loc = np.array([float(x) for x in reason[reason.index("[") + 1:reason.index("]")].split()[:2]])
            except ValueError:  # pragma: no cover - shapely's message format
                loc = None
        if loc is not None:
            at = _deg(phi[int(np.argmin(np.linalg.norm(pts - np.asarray(loc), axis=1)))])
        where = "" if at is None else f", the first near cam angle {at:.4f} deg"
        msg = f"{crossings} self-crossing(s){where}" if crossings else f"not a valid closed curve ({reason}){where}"
    elif not around:
        msg = "the closed curve does not surround the cam centre"
    return Check(name, valid and around, float(crossings), at, 0.0, "", msg)


def check_profile(
    design: CamDesign,
    centre: np.ndarray,
    *,
    options: ProfileOptions | None = None,
    profile: Profile | None = None,
    grid: int = 2000,
) -> CheckReport:
    """Run every check on the cam of ``design`` with its centre at ``centre``.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre in the fixed frame (``SolveResult.centre``), length unit.
    options : ProfileOptions, optional
        Tolerance, user minimum radius of curvature, bore radius; default from
        the design file (:func:`cams.profile.roller.profile_options`).
    profile : Profile, optional
        An already built profile of the same design and centre.
    grid : int
        Positions per phase of the dense search for extremes.

    Returns
    -------
    CheckReport
    """
    opts = options if options is not None else profile_options(design)
    centre = np.asarray(centre, dtype=float)
    prof = profile if profile is not None else build_profile(design, centre, tolerance=opts.tolerance,
                                                             field=opts.tolerance_field)
    r = prof.roller_radius
    checks: list[Check] = []

    # jamming
    constrained = design.constrained_phases()
    maxima = _phase_maxima(design, centre, grid, pressure={i for i, _ in constrained})
    by_kind: dict[str, tuple[float, float, float]] = {}
    for i, lim in constrained:
        kind = design.program.phases[i].kind
        g, at = maxima[i]["pressure"]
        if kind not in by_kind or g - lim > by_kind[kind][0] - by_kind[kind][2]:
            by_kind[kind] = (g, at, lim)
    for kind in ("rise", "return"):
        if kind in by_kind:
            g, at, lim = by_kind[kind]
            ok = g <= lim + 1e-7
            checks.append(Check(f"jamming_{kind}", bool(ok), float(np.degrees(g)), _deg(at), float(np.degrees(lim)),
                                "deg", f"largest pressure angle on the {kind} {np.degrees(g):.4f} deg "
                                f"(limit {np.degrees(lim):.4f} deg)"))

    # undercut and sharp points
    ext = _curvature(design, centre, maxima)
    checks.append(Check("undercut", bool(ext.convex > r), ext.convex, _deg(ext.convex_at), r, "mm",
                        f"smallest convex radius of curvature of the pitch curve {ext.convex:.6g} mm "
                        f"vs roller radius {r:g} mm"))
    largest = ext.convex
    if prof.groove:
        checks.append(Check("undercut_outer", bool(ext.concave > r), ext.concave, _deg(ext.concave_at), r, "mm",
                            f"smallest concave radius of curvature of the pitch curve {ext.concave:.6g} mm "
                            f"vs roller radius {r:g} mm (outer wall of the groove)"))
        largest = min(largest, ext.concave)
    if opts.min_curvature_radius is not None:
        worst, at = ext.convex - r, ext.convex_at
        if prof.groove and ext.concave - r < worst:
            worst, at = ext.concave - r, ext.concave_at
        checks.append(Check("min_curvature_radius", bool(worst >= opts.min_curvature_radius), worst, _deg(at),
                            float(opts.min_curvature_radius), "mm",
                            f"smallest convex radius of curvature of the working profile {worst:.6g}"))

    # polygons
    checks.append(_polygon_check("profile_polygon", prof.work, prof.phi))
    if prof.groove:
        checks.append(_polygon_check("outer_polygon", prof.outer, prof.phi))

    # bore: checked only against a bore the user gave ([cam] bore_radius); the default bore
    # is derived from the profile to fit inside it, so a check against it could not fail
    bore = opts.bore_radius if opts.bore_radius is not None else default_bore_radius(prof)
    if opts.bore_radius is not None:
        rad = np.linalg.norm(prof.work, axis=1)
        k = int(np.argmin(rad))
        rmin = prof.min_work_radius
        checks.append(Check("bore", bool(rmin > bore), rmin, _deg(prof.phi[k]), float(bore), "mm",
                            f"working profile's smallest radius {rmin:.6g} mm vs bore radius {bore:.6g} mm"))
    return CheckReport(
        name=design.name,
        checks=tuple(checks),
        profile=prof,
        largest_roller_radius=float(largest),
        recommended_roller_radius=float(RECOMMENDED_ROLLER_FRACTION * largest),
        bore_radius=float(bore),
        extra={"smallest_cam_radius": float(smallest_cam_radius(design, centre)[0])},
    )


def check_solution(result, *, tolerance: float | None = None, options: ProfileOptions | None = None) -> CheckReport:
    """Check the profile of a solved design (an ``optimize.solve.SolveResult``).

    ``tolerance`` overrides the design file's ``[profile] tolerance``.
    """
    opts = options if options is not None else profile_options(result.design, tolerance=tolerance)
    return check_profile(result.design, result.centre, options=opts)


def check_design(design: CamDesign, *, tolerance: float | None = None, method: str | None = None) -> CheckReport:
    """Solve ``design`` (:func:`optimize.solve.solve`) and check the profile of the solved centre.

    A flat-faced follower's design (:class:`cams.model.design.FlatFaceDesign`) is
    sized by convexity and checked by :func:`cams.profile.flat.check_flat_face`
    (a :class:`cams.profile.flat.FlatCheckReport`); it takes no ``method``.
    """
    from optimize.solve import solve

    if getattr(design, "face", "roller") == "flat":
        from cams.profile.flat import check_flat_face, flat_face_profile
        from cams.profile.roller import resolve_tolerance

        tol, field = resolve_tolerance(design.tolerance, tolerance)  # bad options fail before sizing
        solution = solve(design, method=method)
        return check_flat_face(design, solution, flat_face_profile(design, solution.R0, tolerance=tol, field=field))

    opts = profile_options(design, tolerance=tolerance)  # bad options fail before solving
    result = solve(design, method=method, objective=design.objective)
    return check_profile(result.design, result.centre, options=opts)

