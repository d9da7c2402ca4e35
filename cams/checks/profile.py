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
  smallest distance from the cam centre (exact, not the sampled polyline's:
  :func:`cams.kinematics.inversion.smallest_cam_radius`) is at least the bore
  radius plus the hub wall (``[cam] hub_wall``, default 0).

Extremes are located on a dense grid per phase (``grid + 1`` positions, and
both sides of a piecewise law's breakpoints) and refined between grid points
where their analytic derivative by the cam angle changes sign: all brackets
together, one array evaluation a step (the kernel's search,
:func:`cams.kinematics.extremum.maximize`, on the kernel's curvature and
pressure angle and their rates, :mod:`cams.kinematics.inversion`). They do not
depend on the profile's sampling.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import partial

import numpy as np

from cams.checks.base import (
    Check,
    ChecksMixin,
    bore_check,
    finite_or_none,
    polygon_check,
)
from cams.kinematics.extremum import maximize, phase_positions
from cams.kinematics.inversion import (
    curvature_rate,
    invert_phase,
    pitch_phase,
    pressure_angle,
    pressure_rate,
    smallest_cam_radius,
)
from cams.kinematics.vectors import cross
from cams.model.design import CamDesign
from cams.model.options import ProfileOptions, profile_options
from cams.profile.roller import Profile, build_profile, default_bore_radius
from laws.units import TWO_PI

__all__ = [
    "CheckReport",
    "pressure_from_profile",
    "curvature_extremes",
    "CurvatureExtremes",
    "check_profile",
    "part_checks",
    "check_solution",
    "RECOMMENDED_ROLLER_FRACTION",
]

#: Usual rule: roller radius at most this fraction of the smallest convex rho.
RECOMMENDED_ROLLER_FRACTION = 0.8


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
            "largest_roller_radius": finite_or_none(self.largest_roller_radius),
            "recommended_roller_radius": finite_or_none(self.recommended_roller_radius),
            "bore_radius": float(self.bore_radius),
            "R0": float(self.profile.R0),
            "points": len(self.profile),
            "tolerance": float(self.profile.tolerance),
            **self.extra,
        }


# -- pressure angle and curvature with their slopes (the kernel's) ------------------------------


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
    fixed frame (:func:`cams.kinematics.inversion.pressure_angle`).
    """
    return pressure_angle(invert_phase(design, centre, phase, u))


def _phase_rates(design: CamDesign, centre: np.ndarray, i: int, u: np.ndarray, what: tuple[str, ...]):
    """Functions of phase ``i`` at positions ``u`` and their derivatives by the cam angle.

    ``what`` names the rows: ``"convex"`` (kappa, 1/length), ``"concave"``
    (-kappa) and ``"pressure"`` (radians). Returns ``values, slopes``, arrays
    of shape ``(len(what), len(u))``.
    """
    inv = invert_phase(design, centre, i, u, third="convex" in what or "concave" in what)
    rows = {}
    if "convex" in what or "concave" in what:
        k, dk = curvature_rate(inv)
        rows["convex"], rows["concave"] = (k, dk), (-k, -dk)
    if "pressure" in what:
        rows["pressure"] = pressure_rate(inv)
    return np.array([rows[w][0] for w in what]), np.array([rows[w][1] for w in what])


# -- the largest values over a phase -----------------------------------------------------------


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
        best, at = maximize(partial(_phase_rates, design, centre, i, what=what),
                            phase_positions(prog, i, grid), refine=p.kind != "dwell")
        out.append({w: (float(b), float(prog.starts[i] + a * p.angle))
                    for w, b, a in zip(what, best, at, strict=True)})
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
    derivative changes sign (:func:`cams.kinematics.extremum.maximize`); ``rho = 1 / kappa``. Phase
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
            at = float(prog.starts[i + 1] % TWO_PI)
            if np.sign(cross(t1, t2)) == -design.cam_sense:
                kmax, kat = np.inf, at
            elif cmax < np.inf:
                cmax, cat = np.inf, at
    convex = 1.0 / kmax if kmax > 0 else np.inf
    concave = 1.0 / cmax if cmax > 0 else np.inf
    return CurvatureExtremes(float(convex), float(kat), float(concave), None if cmax <= 0 else cat)


# -- the checks ------------------------------------------------------------------------------


def part_checks(design: CamDesign, centre: np.ndarray, options: ProfileOptions | None = None, *,
                grid: int = 2000) -> tuple[list[Check], CurvatureExtremes]:
    """The checks of the cam that need no sampled profile: every one but the polygons', on exact extrema.

    The pressure angle over each limited phase (``jamming_rise``, ``jamming_return``), ``undercut`` (and
    ``undercut_outer`` for a groove), ``min_curvature_radius`` (when asked for) and ``bore`` (when a bore is
    given): the extrema are refined on the kernel's analytic rates (:func:`_phase_maxima`), the smallest radius
    is :func:`cams.kinematics.inversion.smallest_cam_radius`'s, so the checks do not depend on a sampling. The
    sizing to the part (:mod:`cams.faces.part`) judges its candidates by these.

    Returns
    -------
    checks : list of Check
        In the order of :func:`check_profile`'s report (the bore last).
    extremes : CurvatureExtremes
        The pitch curve's smallest convex and concave radii of curvature.
    """
    opts = options if options is not None else profile_options(design)
    centre = np.asarray(centre, dtype=float)
    r = float(design.follower.roller_radius)
    groove = design.limits.closure == "form"
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
            checks.append(Check(f"jamming_{kind}", bool(ok), float(np.degrees(g)), at, float(np.degrees(lim)),
                                "deg", f"largest pressure angle on the {kind} {np.degrees(g):.4f} deg "
                                f"(limit {np.degrees(lim):.4f} deg)"))

    # undercut and sharp points
    ext = _curvature(design, centre, maxima)
    checks.append(Check("undercut", bool(ext.convex > r), ext.convex, ext.convex_at, r, "mm",
                        f"smallest convex radius of curvature of the pitch curve {ext.convex:.6g} mm "
                        f"vs roller radius {r:g} mm"))
    if groove:
        checks.append(Check("undercut_outer", bool(ext.concave > r), ext.concave, ext.concave_at, r, "mm",
                            f"smallest concave radius of curvature of the pitch curve {ext.concave:.6g} mm "
                            f"vs roller radius {r:g} mm (outer wall of the groove)"))
    if opts.min_curvature_radius is not None:
        worst, at = ext.convex - r, ext.convex_at
        if groove and ext.concave - r < worst:
            worst, at = ext.concave - r, ext.concave_at
        checks.append(Check("min_curvature_radius", bool(worst >= opts.min_curvature_radius), worst, at,
                            float(opts.min_curvature_radius), "mm",
                            f"smallest convex radius of curvature of the working profile {worst:.6g}"))

    # bore: checked only against a bore the user gave ([cam] bore_radius); the default bore
    # is derived from the profile to fit inside it, so a check against it could not fail
    if opts.bore_radius is not None:
        checks.append(bore_check(*smallest_cam_radius(design, centre), float(opts.bore_radius), opts.wall))
    return checks, ext


def check_profile(
    design: CamDesign,
    centre: np.ndarray,
    *,
    options: ProfileOptions | None = None,
    profile: Profile | None = None,
    grid: int = 2000,
) -> CheckReport:
    """Run every check on the cam of ``design`` with its centre at ``centre``.

    The checks of :func:`part_checks` (on exact extrema) and the polygons' of the sampled profile.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre in the fixed frame (``SolveResult.centre``), length unit.
    options : ProfileOptions, optional
        Tolerance, user minimum radius of curvature, bore radius and hub wall; default from
        the design file (:func:`cams.model.options.profile_options`).
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
    exact, ext = part_checks(design, centre, opts, grid=grid)
    bore_given = [c for c in exact if c.name == "bore"]
    checks = [c for c in exact if c.name != "bore"]
    largest = ext.convex if not prof.groove else min(ext.convex, ext.concave)

    # polygons
    checks.append(polygon_check("profile_polygon", prof.work, prof.phi))
    if prof.outer is not None:  # a groove
        checks.append(polygon_check("outer_polygon", prof.outer, prof.phi))
    checks += bore_given
    bore = opts.bore_radius if opts.bore_radius is not None else default_bore_radius(prof)
    return CheckReport(
        name=design.name,
        checks=tuple(checks),
        profile=prof,
        largest_roller_radius=float(largest),
        recommended_roller_radius=float(RECOMMENDED_ROLLER_FRACTION * largest),
        bore_radius=float(bore),
        extra={"smallest_cam_radius": float(prof.min_work_radius)},
    )


def check_solution(result, *, tolerance: float | None = None, options: ProfileOptions | None = None) -> CheckReport:
    """Check the profile of a solved design (an ``cams.solve.SolveResult``).

    ``tolerance`` overrides the design file's ``[profile] tolerance``.
    """
    opts = options if options is not None else profile_options(result.design, tolerance=tolerance)
    return check_profile(result.design, result.centre, options=opts)
