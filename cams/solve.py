"""The verified solve: one entry point for sizing a cam and checking it independently.

``solve(design)`` sizes the cam (:func:`optimize.sizing.size` for roller and
knife-edge followers, :func:`cams.profile.flat.size_flat_face` for flat faces),
or takes the cam the designer chose (``[cam] base_radius`` with L or the
offset, or ``[cam] centre``: nothing is sized, mode ``"chosen"``), and verifies
it with :func:`cams.verify.pressure.check_pressure`, which recomputes the
pressure angle over the whole cycle by kinematic inversion without the zone's
formulas.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from cams.checks.profile import CheckReport, check_profile
from cams.model.design import METHODS, OBJECTIVE_SUPERSEDED, CamDesign, FlatFaceDesign
from cams.model.follower import Rocker, Translating
from cams.model.options import profile_options
from cams.verify.pressure import PressureReport, check_pressure
from laws.errors import InputError, check_option
from optimize.result import Binding
from optimize.sizing import OBJECTIVES, offset_x, roller_travel, size, vanishing_error

if TYPE_CHECKING:
    from cams.checks.flat import FlatCheckReport

__all__ = ["SolveResult", "solve", "check_design", "excess", "pressure_failures", "profile_passes"]


@dataclass(frozen=True)
class SolveResult:
    """A sized cam.

    Attributes
    ----------
    centre : ndarray, shape (2,)
        Cam centre in the follower's fixed frame (see :mod:`cams.model.follower`).
    R0 : float
        Base radius of the pitch curve: cam centre to the roller centre at the
        near dwell (length).
    L : float or None
        Centre distance, cam centre to rocker pivot (rocker only).
    offset : float or None
        Offset of the follower axis from the cam centre, positive when the axis
        lies on the +X side (translating only).
    mode : str
        ``"min_R0"``, ``"min_L"``, ``"fixed_L"``, ``"fixed_L_and_R0"``,
        ``"floor_R0"``, ``"fixed_offset"`` or ``"chosen"`` (the designer's cam,
        ``[cam] base_radius`` or ``centre``: checked, not sized; ``method`` is
        then None).
    pressure : PressureReport
        The independent check of the pressure angle.
    margin : float
        Smallest distance of the centre from the zone's edges (length, > 0
        inside; only meaningful for ``floor_R0`` and ``fixed_L``).
    certified : bool or None
        The exact method's verdict on its own bounds (minimum R0, minimum L,
        fixed offset): False when the proven lower bound and the feasible
        upper bound disagree beyond the stated accuracy, so the answer is not
        certified; None where no bound is stated.
    """

    design: CamDesign
    centre: np.ndarray
    R0: float
    L: float | None
    offset: float | None
    method: str | None
    samples: int | None
    mode: str
    binding: tuple[Binding, ...]
    error_bound: float | None
    seconds: float
    pressure: PressureReport
    margin: float
    notes: tuple[str, ...] = field(default_factory=tuple)
    certified: bool | None = None
    optimization: dict | None = None

    @property
    def verified(self) -> bool:
        """True when the independent check finds every limit respected."""
        return self.pressure.ok

    @property
    def buildable(self) -> bool:
        """True when the roller centre's base circle is larger than the roller (a working profile exists)."""
        return bool(self.R0 > self.design.follower.roller_radius)

    def to_dict(self) -> dict:
        """JSON-ready report: lengths in the design's unit, angles in degrees.

        Returns
        -------
        dict
            ``R0`` (the pitch curve's base radius), ``smallest_cam_radius``
            (the working profile's nearest point to the cam centre, and
            ``smallest_cam_radius_at_deg`` where), ``L``, ``offset`` and
            ``centre`` (``x``, ``y`` in the follower's fixed frame) in the
            design's length unit; the largest
            pressure angles, where they occur (cam angle) and the limits, and
            the binding lines' cam angles, in degrees; the solver's mode,
            method, samples, error bound, margin, time (s) and notes.
        """
        from cams.kinematics.inversion import smallest_cam_radius

        deg = lambda x: None if x is None else float(np.degrees(x))  # noqa: E731
        p = self.pressure
        cam_r, cam_r_at = smallest_cam_radius(self.design, self.centre)
        return {
            "name": self.design.name,
            "follower": self.design.follower.kind,
            "R0": float(self.R0),
            "smallest_cam_radius": cam_r,
            "smallest_cam_radius_at_deg": float(np.degrees(cam_r_at)),
            "L": None if self.L is None else float(self.L),
            "offset": None if self.offset is None else float(self.offset),
            "centre": {"x": float(self.centre[0]), "y": float(self.centre[1])},
            "max_pressure_angle": {"rise": deg(p.rise), "return": deg(p.ret)},
            "pressure_angle_at": {"rise": deg(p.rise_at), "return": deg(p.ret_at)},
            "limits": {"rise": deg(p.rise_limit), "return": deg(p.return_limit)},
            **({} if p.safety is None else {"safety_factor": p.safety.to_dict()}),
            "verified": bool(self.verified),
            "buildable": self.buildable,
            "binding": [
                {"phi": float(np.degrees(b.phi)), "phase": b.phase, "line": b.line,
                 "phase_kind": self.design.program.phases[b.phase].kind}
                for b in self.binding
            ],
            "method": self.method,
            "samples": self.samples,
            "mode": self.mode,
            "error_bound": self.error_bound,
            "certified": None if self.certified is None else bool(self.certified),
            "margin": float(self.margin),
            "seconds": float(self.seconds),
            "notes": list(self.notes),
            **({} if self.optimization is None else {"optimize": self.optimization}),
        }


def _no_base_circle(R0: float, roller_radius: float, remedy: str) -> list[str]:
    """The note of a cam whose R0 (mm) is not larger than the roller radius (mm): no working profile; else none."""
    if R0 > roller_radius:
        return []
    return [f"not buildable: R0 = {R0:.6g} mm is not larger than the roller radius {roller_radius:g} mm (the working "
            f"profile would have no base circle); {remedy}"]


def _result(design: CamDesign, centre, pressure: PressureReport, margin: float, notes: list[str], remedy: str,
            **how) -> SolveResult:
    """A :class:`SolveResult` of the cam centred at ``centre`` (fixed frame, mm), sized or chosen alike.

    R0, L and the offset are read off the centre; the notes gain the
    independent check's failures (by how much) and, when R0 is not larger
    than the roller, that there is no base circle (with ``remedy``). ``how``
    holds the solver's fields (method, samples, mode, binding, error bound,
    seconds, certified).
    """
    f = design.follower
    R0 = float(np.linalg.norm(centre - f.position(0.0)))
    notes = [*notes, *pressure_failures(pressure), *_no_base_circle(R0, f.roller_radius, remedy)]
    return SolveResult(
        design=design,
        centre=np.asarray(centre, float),
        R0=R0,
        L=float(np.linalg.norm(centre - f.pivot)) if isinstance(f, Rocker) else None,
        offset=offset_x(float(centre[0])) + 0.0 if isinstance(f, Translating) else None,
        pressure=pressure,
        margin=float(margin),
        notes=tuple(notes),
        **how,
    )


#: Two candidate centres whose largest pressure-angle excesses differ by less than this (radians) are a tie.
TIE = 1e-9


def excess(pressure: PressureReport) -> float:
    """Largest excess of the pressure angle over its limit (radians; <= 0 when every limit holds).

    The rise against ``rise_limit``; the return against ``return_limit``
    when it is limited (form closure). ``-inf`` when no phase is limited.
    """
    out = [-np.inf]
    if pressure.rise is not None:
        out.append(pressure.rise - pressure.rise_limit)
    if pressure.ret is not None and pressure.return_limit is not None:
        out.append(pressure.ret - pressure.return_limit)
    if pressure.safety is not None:  # K_C: the moved lines' excess, an angle's sine
        out.append(pressure.safety.excess)
    return float(max(out))


def pressure_failures(pressure: PressureReport) -> list[str]:
    """One line per limited phase kind whose pressure angle exceeds its limit: by how much and where (degrees)."""
    out = []
    for kind, g, at, lim in (("rise", pressure.rise, pressure.rise_at, pressure.rise_limit),
                             ("return", pressure.ret, pressure.ret_at, pressure.return_limit)):
        if g is None or lim is None or at is None or not g > lim + 1e-7:
            continue
        d = np.degrees
        out.append(f"{kind} pressure angle {d(g):.4f} deg exceeds the limit {d(lim):.4f} deg by {d(g - lim):.4f} deg "
                   f"at cam angle {d(at) % 360:.4f} deg")
    safety = None if pressure.safety is None else pressure.safety.failure()  # K_C (seed 3.26)
    return out if safety is None else [*out, safety]


def _solve_chosen(design: CamDesign) -> SolveResult:
    """Check the cam the designer chose (``design.base_radius`` or ``design.centre``): nothing is sized.

    Where R0 with L (rocker) admits two centres, the one whose largest pressure-angle excess over its limit
    (:func:`excess`, from the independent check) is smaller is taken and a
    note names both; a tie (within :data:`TIE` radians) is refused, naming both.
    """
    t0 = time.perf_counter()
    cands = design.chosen_centres()
    checked = [(c, check_pressure(design, c)) for c in cands]
    notes: list[str] = []
    centre, pressure = checked[0]
    if len(checked) == 2:
        (c1, p1), (c2, p2) = checked
        e1, e2 = excess(p1), excess(p2)
        other = "limits.centre_distance"
        both = (f"({c1[0]:.6g}, {c1[1]:.6g}) mm (largest pressure angle {np.degrees(e1):+.4f} deg from its limit) "
                f"and ({c2[0]:.6g}, {c2[1]:.6g}) mm ({np.degrees(e2):+.4f} deg)")
        if abs(e1 - e2) <= TIE:
            raise InputError("cam.base_radius", f"with {other} admits two cam centres, equally good: {both}; "
                             "give cam.centre = [x, y] instead")
        centre, pressure = checked[0] if e1 < e2 else checked[1]
        notes.append(f"cam.base_radius with {other} admits two cam centres, {both}: the one with the smaller "
                     f"pressure angle against its limit is taken, ({centre[0]:.6g}, {centre[1]:.6g}) mm; give "
                     "cam.centre to take the other")
    from optimize.circle import violation_function

    margin = -violation_function(design, None)(centre)
    return _result(design, centre, pressure, margin, notes, "choose a larger cam or a smaller roller",
                   method=None, samples=None, mode="chosen", binding=(), error_bound=None,
                   seconds=time.perf_counter() - t0)


def _solve_flat(design, method: str | None, objective: str | None):
    """A flat face's cam (:func:`optimize.flat.size_flat_face`); it has no zone solver nor objective to choose."""
    if method is not None:
        raise InputError("method", "does not apply to a flat-faced follower: its base radius follows from "
                         "convexity directly")
    if objective not in (None, "R0"):
        raise InputError("objective", "a flat-faced follower's cam is sized by R0 (convexity); only 'R0'")
    from optimize.flat import size_flat_face

    return size_flat_face(design)


def solve(design, *, method: str | None = None, objective: str | None = None):
    """Size the cam of ``design`` and verify it: the one entry point for every follower.

    Parameters
    ----------
    design : CamDesign or FlatFaceDesign
        Lengths in its unit, angles in radians; ``design.limits`` may fix the
        centre distance L (rocker) or a floor on R0, the follower a fixed
        offset (translating). A flat-faced follower's design is sized by
        convexity (:func:`optimize.flat.size_flat_face`).
    method : {"exact", "convex", "exhaustive"}, optional
        Overrides ``design.method`` (roller followers; refused for a flat face).
    objective : {"R0", "L"}, optional
        What to minimize when neither L nor a floor on R0 is fixed; ``"L"``
        applies to rockers only. Default: the design file's ``[solve]
        objective`` (``design.objective``), else ``"R0"``.

    Returns
    -------
    SolveResult or optimize.flat.FlatFaceSolution
        For a flat face, the latter (what ``cams solve`` prints for it); else
        The cam centre in the follower's fixed frame (:mod:`cams.model.follower`),
        ``R0 = |O - A0|`` (A0 the roller centre at the near dwell), ``L = |O|``
        for a rocker (pivot at the origin), the offset ``e = -x_O`` for a
        translating follower (positive: the follower's axis on the +X side of
        the cam centre), lengths in the design's unit, and the independent
        pressure-angle check.

    Raises
    ------
    InfeasibleError
        Empty zone; a fixed L outside the admissible range (the message gives
        the range); a floor on R0 and a fixed L (or a fixed offset) that
        cannot both hold; a minimum R0 that vanishes (set a floor).
    InputError
        An unknown method or objective; ``objective="L"`` for a translating
        follower.
    """
    if getattr(design, "optimize", None) is not None:
        # the laws are designed first; the method applies to the solves of the cams of fixed laws
        if objective not in (None, getattr(design, "objective", "R0")):
            raise InputError("solve.objective", OBJECTIVE_SUPERSEDED)
        from functools import partial

        from cams.motion_design import design_motion

        return design_motion(design, partial(solve, method=method), profile_passes)
    if getattr(design, "face", "roller") == "flat":
        return _solve_flat(design, method, objective)
    if objective is None:
        objective = design.objective
    method = check_option("solve.method", method or design.method, METHODS)
    check_option("solve.objective", objective, OBJECTIVES)
    design = design.with_(method=method) if method != design.method else design
    if design.chosen:
        if objective != "R0":
            raise InputError("solve.objective", "nothing is minimized for a chosen cam (cam.base_radius or "
                             "cam.centre); only 'R0'")
        return _solve_chosen(design)
    sized = size(design, method=method, objective=objective)
    f = design.follower
    centre = sized.centre
    R0 = float(np.linalg.norm(centre - f.position(0.0)))
    pressure = check_pressure(design, centre)
    if not pressure.ok and R0 < 1e-6 * roller_travel(design) and sized.method == "exact":
        raise vanishing_error(design, R0)
    return _result(design, centre, pressure, sized.margin, list(sized.notes),
                   "set limits.min_base_radius or a smaller roller", method=sized.method, samples=sized.samples,
                   mode=sized.mode, binding=sized.binding, error_bound=sized.error_bound, seconds=sized.seconds,
                   certified=sized.certified)


#: ``profile_passes(..., search=True)`` samples a cam at a chord of this fraction of R0 when that is coarser than
#: the default (a search over many candidate cams of kilometres is not sampled at a micrometre).
SEARCH_CHORD = 1e-7


def profile_passes(result, *, search: bool = False) -> bool:
    """True when the cam of ``result`` (a roller's :class:`SolveResult`) has a working profile whose checks pass.

    The base circle larger than the roller, no knife edge in a groove, and every check of
    :func:`cams.checks.profile.check_profile` but the pressure angle's (undercut, sharp points, a closed
    profile, the bore, the least radius of curvature) at the design's chord tolerance: the buildability of
    :mod:`cams.assess` without the ``[dynamics]`` checks. A flat face's result: its checks
    (:func:`cams.checks.flat.check_flat_face`). ``search``: a design without a tolerance of its own is sampled
    at :data:`SEARCH_CHORD` times R0 when that is coarser than the default (for a search; the answer is then
    checked without it).
    """
    from dataclasses import replace

    from cams.checks.base import PRESSURE_CHECKS
    from cams.profile.roller import DEFAULT_TOLERANCE

    d = result.design
    if search and d.tolerance is None and SEARCH_CHORD * result.R0 > DEFAULT_TOLERANCE:
        d = replace(d, tolerance=SEARCH_CHORD * float(result.R0))
    try:
        if isinstance(d, FlatFaceDesign):
            from cams.checks.flat import check_flat_face
            from cams.profile.flat import flat_face_profile

            checks = check_flat_face(d, result, flat_face_profile(d, result.R0, tolerance=d.tolerance)).checks
        else:
            r = d.follower.roller_radius
            if not result.R0 > r or (d.limits.closure == "form" and not r > 0):
                return False
            checks = check_profile(d, result.centre, options=profile_options(d)).checks
    except InputError:          # a profile the chord tolerance cannot carry
        return False
    return all(c.passed or c.name in PRESSURE_CHECKS for c in checks)


def check_design(design: CamDesign | FlatFaceDesign, *, tolerance: float | None = None,
                 method: str | None = None) -> CheckReport | FlatCheckReport:
    """Solve ``design`` (:func:`cams.solve.solve`) and check the profile of the solved centre.

    A flat-faced follower's design (:class:`cams.model.design.FlatFaceDesign`) is
    sized by convexity and checked by :func:`cams.checks.flat.check_flat_face`
    (a :class:`cams.checks.flat.FlatCheckReport`); it takes no ``method``.
    """
    if isinstance(design, FlatFaceDesign):
        from cams.checks.flat import check_flat_face
        from cams.model.options import resolve_tolerance
        from cams.profile.flat import flat_face_profile

        tol, field = resolve_tolerance(design.tolerance, tolerance)  # bad options fail before sizing
        solution = solve(design, method=method)
        return check_flat_face(design, solution, flat_face_profile(design, solution.R0, tolerance=tol, field=field))

    opts = profile_options(design, tolerance=tolerance)  # bad options fail before solving
    result = solve(design, method=method, objective=design.objective)
    return check_profile(result.design, result.centre, options=opts)
