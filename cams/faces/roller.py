"""The roller follower's pipeline (a knife edge is a roller of radius 0): size, profile, checks, forces.

Sizing: :func:`optimize.sizing.size` finds the smallest cam in the allowable-centre zone (or the designer's cam is
taken, ``[cam] base_radius`` with L or the offset, or ``[cam] centre``: nothing is sized, mode ``"chosen"``), and
:func:`cams.verify.pressure.check_pressure` verifies it, recomputing the pressure angle over the whole cycle by
kinematic inversion without the zone's formulas; a cam that fails the part's constraints (the bore and its hub
wall, undercut, the least radius of curvature) is raised along the floor family to the smallest that meets them
(:mod:`cams.faces.part`). The profile is :func:`cams.profile.roller.build_profile`'s, its checks
:func:`cams.checks.profile.check_profile`'s (on exact extrema: :func:`cams.checks.profile.part_checks`), the
forces :func:`cams.dynamics.forces.design_forces`', the lift table :func:`cams.profile.table.roller_table`'s.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from cams.faces.base import Face
from cams.faces.result import SolveResult
from cams.model.design import METHODS, CamDesign
from cams.model.follower import Rocker, Translating
from cams.model.options import ProfileOptions
from cams.verify.pressure import PressureReport, check_pressure
from laws.errors import InputError, check_option
from laws.units import turn_degrees
from optimize.result import Binding
from optimize.sizing import OBJECTIVES, offset_x, roller_travel, size, vanishing_error

if TYPE_CHECKING:
    from cams.checks.profile import CheckReport
    from cams.profile.roller import Profile

__all__ = ["RollerSizing", "RollerFace", "ROLLER", "excess", "pressure_failures", "TIE"]


@dataclass(frozen=True)
class RollerSizing:
    """What only a roller's sized cam has (:attr:`cams.faces.result.SolveResult.detail`).

    Attributes
    ----------
    method : str or None
        ``"exact"``, ``"convex"`` or ``"exhaustive"``; None for a chosen cam.
    samples : int or None
        Steps per phase of a sampled method.
    mode : str
        ``"min_R0"``, ``"min_L"``, ``"fixed_L"``, ``"fixed_L_and_R0"``, ``"floor_R0"``, ``"fixed_offset"`` or
        ``"chosen"`` (the designer's cam, ``[cam] base_radius`` or ``centre``: checked, not sized).
    binding : tuple of optimize.result.Binding
        The binding lines t-t and t1-t1: cam angle (rad) and ``[[motion]]`` phase index from 0.
    error_bound : float or None
        The size's proven accuracy (length), where the method states one.
    pressure : PressureReport
        The independent check of the pressure angle.
    margin : float
        Smallest distance of the centre from the zone's edges (length, > 0 inside; only meaningful for
        ``floor_R0`` and ``fixed_L``).
    """

    method: str | None
    samples: int | None
    mode: str
    binding: tuple[Binding, ...]
    error_bound: float | None
    pressure: PressureReport
    margin: float

    @property
    def verified(self) -> bool:
        """True when the independent check finds every pressure-angle limit respected."""
        return self.pressure.ok

    def to_dict(self, result: SolveResult) -> dict:
        """JSON-ready report of ``result``: lengths in the design's unit, angles in degrees.

        Returns
        -------
        dict
            ``R0`` (the pitch curve's base radius), ``smallest_cam_radius`` and ``largest_cam_radius`` (the working
            profile's nearest and farthest point from the cam centre, a groove's outer wall for the largest; where:
            ``*_at_deg``), ``L``, ``offset`` and ``centre`` (``x``, ``y`` in the follower's fixed frame) in the
            design's length unit (the part's other keys are :meth:`cams.faces.result.SolveResult.to_dict`'s); the
            largest pressure angles, where they occur (cam angle) and the limits, and the binding lines' cam angles,
            in degrees; the solver's mode, method, samples, error bound, margin, time (s) and notes.
        """
        from cams.kinematics.inversion import largest_cam_radius, smallest_cam_radius

        design, centre = result.design, result.centre
        assert isinstance(design, CamDesign)  # a roller's sizing is of a roller's design
        deg = lambda x: None if x is None else float(np.degrees(x))  # noqa: E731
        p = self.pressure
        small, small_at = smallest_cam_radius(design, centre)
        large, large_at = largest_cam_radius(design, centre)
        return {
            "name": design.name,
            "follower": design.follower.kind,
            "R0": float(result.R0),
            "smallest_cam_radius": small,
            "smallest_cam_radius_at_deg": float(turn_degrees(small_at)),
            "largest_cam_radius": large,
            "largest_cam_radius_at_deg": float(turn_degrees(large_at)),
            "L": None if result.L is None else float(result.L),
            "offset": None if result.offset is None else float(result.offset),
            "centre": {"x": float(centre[0]), "y": float(centre[1])},
            "max_pressure_angle": {"rise": deg(p.rise), "return": deg(p.ret)},
            "pressure_angle_at": {"rise": deg(p.rise_at), "return": deg(p.ret_at)},
            "limits": {"rise": deg(p.rise_limit), "return": deg(p.return_limit)},
            **({} if p.safety is None else {"safety_factor": p.safety.to_dict()}),
            "verified": bool(self.verified),
            "buildable": bool(result.R0 > design.follower.roller_radius),
            "binding": [
                {"phi": float(np.degrees(b.phi)), "phase": b.phase, "line": b.line,
                 "phase_kind": design.program.phases[b.phase].kind}
                for b in self.binding
            ],
            "method": self.method,
            "samples": self.samples,
            "mode": self.mode,
            "error_bound": self.error_bound,
            "certified": None if result.certified is None else bool(result.certified),
            "margin": float(self.margin),
            "seconds": float(result.seconds),
            "notes": list(result.notes),
        }


# -- the verified sizing ----------------------------------------------------------------------------------------


def _no_base_circle(R0: float, roller_radius: float, remedy: str) -> list[str]:
    """The note of a cam whose R0 (mm) is not larger than the roller radius (mm): no working profile; else none."""
    if R0 > roller_radius:
        return []
    return [f"not buildable: R0 = {R0:.6g} mm is not larger than the roller radius {roller_radius:g} mm (the working "
            f"profile would have no base circle); {remedy}"]


def _result(design: CamDesign, centre, pressure: PressureReport, margin: float, notes: list[str], remedy: str, *,
            seconds: float, certified: bool | None = None, **how) -> SolveResult:
    """The :class:`SolveResult` of the cam centred at ``centre`` (fixed frame, mm), sized or chosen alike.

    R0, L and the offset are read off the centre; the notes gain the independent check's failures (by how much)
    and, when R0 is not larger than the roller, that there is no base circle (with ``remedy``). ``how`` holds the
    solver's fields of :class:`RollerSizing` (method, samples, mode, binding, error bound).
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
        detail=RollerSizing(pressure=pressure, margin=float(margin), **how),
        seconds=seconds,
        notes=tuple(notes),
        certified=certified,
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
                   f"at cam angle {turn_degrees(at):.4f} deg")
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


def _size_alone(design: CamDesign, method: str | None, objective: str | None) -> SolveResult:
    """The cam of ``design`` sized by the pressure angle alone (its floor honoured), or the chosen cam, verified."""
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


#: The sizing's modes in which a floor on R0 (the user's) set the size.
FLOOR_MODES = ("floor_R0", "fixed_L_and_R0")


def size_roller(design: CamDesign, *, method: str | None = None, objective: str | None = None) -> SolveResult:
    """Size the roller cam of ``design`` (fixed laws) and verify it; see :meth:`RollerFace.size`."""
    res = _size_alone(design, method, objective)
    if design.chosen:
        from cams.faces.part import chosen_bore_notes

        return replace(res, governs="chosen", notes=(*res.notes, *chosen_bore_notes(ROLLER, design, res)))
    detail = res.detail
    assert isinstance(detail, RollerSizing)  # this pipeline's sizing
    floored = detail.mode in FLOOR_MODES
    pa_R0 = float(res.R0)
    if floored:     # the pressure angle's own minimum, without the floor (L or the offset held)
        m = detail.method
        pa_R0 = float(np.linalg.norm(size(design.with_floor(None), method=m, objective=objective or design.objective)
                                     .centre - design.follower.position(0.0)))
    res = replace(res, governs="min_base_radius" if floored else "pressure_angle", pressure_angle_R0=pa_R0)
    from cams.faces.part import sized_to_part

    return sized_to_part(ROLLER, design, res, lambda d: _size_alone(d, method, objective))


def knife_in_groove(design: CamDesign) -> bool:
    """True for form closure (a groove) with roller radius 0 (a knife edge): no profile can be built."""
    return design.limits.closure == "form" and not design.follower.roller_radius > 0


class RollerFace(Face):
    """The pipeline of a roller (or knife-edge) follower's cam."""

    name = "roller"
    forces_computed = True

    def size(self, design, *, method=None, objective=None) -> SolveResult:
        """The smallest cam in the allowable-centre zone, or the chosen cam, verified independently.

        ``method`` (``"exact"``, ``"convex"``, ``"exhaustive"``) overrides ``[solve] method``; ``objective``
        (``"R0"``, ``"L"``) ``[solve] objective``. The cam centre is in the follower's fixed frame
        (:mod:`cams.model.follower`): ``R0 = |O - A0|`` (A0 the roller centre at the near dwell), ``L = |O|`` for
        a rocker (pivot at the origin), the offset ``e = -x_O`` for a translating follower. With
        ``design.constraints = "all"`` (the default) a cam that fails the part's constraints (the bore and its hub
        wall, undercut, the least radius of curvature) is raised along the floor family to the smallest that meets
        them (:mod:`cams.faces.part`); ``governs`` says what set the size.
        """
        return size_roller(design, method=method, objective=objective)

    def part_checks(self, design, solution: SolveResult) -> list:
        from cams.checks.profile import part_checks
        from cams.model.options import profile_options

        return part_checks(design, solution.centre, profile_options(design))[0]

    def radii(self, design, solution: SolveResult) -> tuple[float, float, float, float]:
        from cams.kinematics.inversion import largest_cam_radius, smallest_cam_radius

        return (*smallest_cam_radius(design, solution.centre), *largest_cam_radius(design, solution.centre))

    def bore_R0(self, design) -> float | None:
        """The bore radius plus the hub wall plus the roller: the roller centre passes the base circle of R0, so
        the working profile's smallest radius is at most ``R0 - r``."""
        if design.bore_radius is None:
            return None
        return float(design.bore_radius + (design.hub_wall or 0.0) + design.follower.roller_radius)

    def table(self, design, solution: SolveResult, phi):
        from cams.profile.table import roller_table

        return roller_table(design, solution.centre, phi)

    def no_profile(self, design) -> str | None:
        if knife_in_groove(design):
            return "a knife edge cannot run in a groove, there is no profile"
        return None

    def profile(self, design, solution: SolveResult, options: ProfileOptions) -> Profile:
        from cams.profile.roller import build_profile

        return build_profile(design, solution.centre, tolerance=options.tolerance, field=options.tolerance_field)

    def exact(self, design, solution: SolveResult):
        from cams.profile.exact import roller_exact

        return roller_exact(design, solution.centre)

    def checks(self, design, solution: SolveResult, profile, options: ProfileOptions) -> CheckReport:
        from cams.checks.profile import check_profile

        return check_profile(design, solution.centre, options=options, profile=profile)

    def forces(self, design, solution: SolveResult):
        from cams.dynamics.forces import design_forces

        return design_forces(design, solution.centre)

    def contact_geometry(self, design, solution: SolveResult, phi, length_unit: float):
        from cams.strength.along import roller_geometry

        return roller_geometry(design, solution.centre, phi, length_unit)

    def vibration(self, design, solution: SolveResult, forces):
        from cams.dynamics.vibration import design_vibration

        if forces is None and design.dynamics is not None and design.limits.closure == "form" and design.rpm:
            # a groove: no rigid forces; the contact geometry of the forces stage with no closing spring
            from cams.dynamics.forces import cam_forces
            from cams.model.dynamics import Spring

            dyn = design.dynamics.dynamics.with_spring(Spring(0.0, 0.0))
            return design_vibration(design, None, cam_forces(design, solution.centre, dyn).amplification)
        return design_vibration(design, forces)

    def tradeoff(self, design):
        if design.follower.kind != "rocker":
            return None
        from optimize.tradeoff import tradeoff

        return tradeoff(design, 15)

    def unbuildable(self, design, solution: SolveResult) -> list[tuple[str, str]]:
        r = float(design.follower.roller_radius)
        out = []
        if not solution.R0 > r:
            out.append(("no working profile", f"no working profile: R0 = {solution.R0:.6g} mm is not larger than "
                        f"the roller radius {r:g} mm"))
        if knife_in_groove(design):
            out.append(("knife edge in a groove", "a knife edge cannot run in a groove: form closure needs "
                        "follower.roller_radius > 0"))
        return out

    def not_verified(self, solution: SolveResult) -> list[str]:
        detail = solution.detail
        assert isinstance(detail, RollerSizing)  # the roller pipeline's sizing
        return pressure_failures(detail.pressure)


#: The roller follower's pipeline.
ROLLER = RollerFace()
