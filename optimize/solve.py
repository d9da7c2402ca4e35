"""One entry point for sizing a cam: the smallest admissible cam and its report.

``solve(design)`` picks the case from the design:

* no fixed L, no floor: the admissible centre nearest to the roller's start
  point A0 (minimum R0) or to the pivot (``objective="L"``);
* a fixed centre distance L (rocker, seed 3.23-3.25): the admissible point of
  the circle of radius L about the pivot with the least R0; if the circle
  misses the zone, :class:`InfeasibleError` gives the admissible range of L;
* a constructive floor on R0 larger than the minimum: the centre on the circle
  of radius R0_floor about A0 with the largest margin to the zone's edges;
* a fixed offset (translating): the nearest point on the offset's line;
* a cam the designer chose (``[cam] base_radius`` with L or the offset, or
  ``[cam] centre``): nothing is sized, that cam is checked (mode ``"chosen"``).

Every result is verified by :func:`cams.verify.pressure.check_pressure`, which
recomputes the pressure angle over the whole cycle by kinematic inversion
without the zone's formulas.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from cams.model.design import CamDesign, METHODS
from cams.model.follower import Rocker, Translating
from cams.verify.pressure import PressureReport, check_pressure
from laws.errors import InfeasibleError, InputError, check_option
from optimize.diagnose import diagnosed
from optimize.result import Binding, CentreSolution

__all__ = ["SolveResult", "solve", "nearest", "admissible_L_range", "excess", "pressure_failures"]

OBJECTIVES = ("R0", "L")


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
        from cams.profile.roller import smallest_cam_radius

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
        offset=_offset_x(float(centre[0])) + 0.0 if isinstance(f, Translating) else None,
        pressure=pressure,
        margin=float(margin),
        notes=tuple(notes),
        **how,
    )


def _offset_x(v: float) -> float:
    """The fixed offset's sign convention, ``x_O = -e``, read either way.

    The follower axis (``x = 0`` of the translating follower's frame, see
    :mod:`cams.model.follower`) lies ``e`` to the +X side of the cam centre ``O``, so
    the centre's abscissa is ``x_O = -e`` and the offset of a centre is
    ``e = -x_O``: given ``e`` this returns ``x_O``, given ``x_O`` it returns ``e``
    (lengths, the design's unit).
    """
    return -v


def _offset_line(design: CamDesign):
    """Half-planes ``N O <= c`` pinning the centre to the fixed offset's line ``x = x_O``, or None."""
    f = design.follower
    if isinstance(f, Translating) and f.offset is not None:
        x0 = _offset_x(f.offset)
        return np.array([[1.0, 0.0], [-1.0, 0.0]]), np.array([x0, -x0])
    return None


@diagnosed
def nearest(design: CamDesign, target: np.ndarray, *, method: str | None = None, extra=None) -> CentreSolution:
    """Admissible centre nearest to ``target`` by the design's (or the given) method.

    Parameters
    ----------
    design : CamDesign
    target : ndarray, shape (2,)
        Point to approach in the follower's fixed frame (:mod:`cams.model.follower`),
        length unit: the roller centre A0 at the near dwell (minimum R0) or the
        rocker pivot, the origin (minimum L).
    method : {"exact", "convex", "exhaustive"}, optional
        Overrides ``design.method``; the sampled methods use ``design.samples``.
    extra : (N, c), optional
        Additional half-planes ``N O <= c`` (unit normals, length unit), e.g.
        the line of a fixed offset.

    Returns
    -------
    CentreSolution
        The centre (same frame) and its distance to ``target`` (``objective``,
        length unit).

    Raises
    ------
    InfeasibleError
        The zone (with ``extra``) is empty: the message names the limit that
        binds and its nearest feasible value, the others held
        (:func:`optimize.diagnose.diagnosed`).
    InputError
        An unknown method; an all-pairs run that would need too much memory.
    """
    method = check_option("solve.method", method or design.method, METHODS)
    if method == "exact":
        from optimize.exact import nearest_exact

        return nearest_exact(design, target, extra=extra)
    if method == "convex":
        from optimize.convex import nearest_convex

        return nearest_convex(design, target, samples=design.samples, extra=extra)
    from optimize.exhaustive import nearest_exhaustive

    return nearest_exhaustive(design, target, samples=design.samples, extra=extra)


def _lmax(design: CamDesign) -> float:
    """Largest centre distance in the zone (inf when the zone is unbounded)."""
    from optimize.bounds import _recession_direction
    from optimize.planar import clip_polygon
    from optimize.zone import sample_wedges

    if _recession_direction(design) is not None:
        return float("inf")
    N, c = sample_wedges(design, 512).lines()
    # a bounded zone reaching beyond this box (100 times the follower) would be clipped, L max too small (open)
    s = 100 * design.scale
    poly = clip_polygon(N, c, (-s, -s, s, s))
    return float(np.max(np.linalg.norm(poly, axis=1))) if len(poly) else 0.0


def _seeds(design: CamDesign, ref: np.ndarray, radius: float, inner: np.ndarray) -> tuple[float, ...]:
    """Admissible angles on the circle (``ref``, ``radius``) from an admissible ``inner`` point.

    ``inner`` lies inside the circle; a far admissible point along the zone's
    recession direction lies outside; by convexity their segment crosses the
    circle inside the zone.
    """
    from optimize.bounds import _recession_direction
    from optimize.circle import crossing_seed

    rd = _recession_direction(design)
    if rd is None:
        return ()
    far = inner + (2 * radius + np.linalg.norm(inner - ref) + design.scale) * rd[0]
    s = crossing_seed(ref, radius, inner, far)
    return () if s is None else (s,)


def admissible_L_range(design: CamDesign) -> tuple[float, float]:
    """Smallest and largest centre distance L of admissible centres (rocker).

    Parameters
    ----------
    design : CamDesign
        With a rocker follower (L is measured from its pivot, the origin of
        the fixed frame).

    Returns
    -------
    lo, hi : float
        Length unit. ``lo`` is exact (the admissible centre nearest to the
        pivot over the continuous zone); ``hi`` is ``inf`` when the zone is
        unbounded, else the farthest vertex of the zone sampled at 512 steps
        per phase and clipped to a square of half-side ``100 * design.scale``.
    """
    lo = nearest(design, design.follower.pivot, method="exact").objective
    return lo, _lmax(design)


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
    return float(max(out))


def pressure_failures(pressure: PressureReport) -> list[str]:
    """One line per limited phase kind whose pressure angle exceeds its limit: by how much and where (degrees)."""
    out = []
    for kind, g, at, lim in (("rise", pressure.rise, pressure.rise_at, pressure.rise_limit),
                             ("return", pressure.ret, pressure.ret_at, pressure.return_limit)):
        if g is None or lim is None or not g > lim + 1e-7:
            continue
        d = np.degrees
        out.append(f"{kind} pressure angle {d(g):.4f} deg exceeds the limit {d(lim):.4f} deg by {d(g - lim):.4f} deg "
                   f"at cam angle {d(at) % 360:.4f} deg")
    return out


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
    """A flat face's cam (:func:`cams.profile.flat.size_flat_face`); it has no zone solver nor objective to choose."""
    if method is not None:
        raise InputError("method", "does not apply to a flat-faced follower: its base radius follows from "
                         "convexity directly")
    if objective not in (None, "R0"):
        raise InputError("objective", "a flat-faced follower's cam is sized by R0 (convexity); only 'R0'")
    from cams.profile.flat import size_flat_face

    return size_flat_face(design)


def solve(design, *, method: str | None = None, objective: str | None = None):
    """Size the cam of ``design`` and verify it: the one entry point for every follower.

    Parameters
    ----------
    design : CamDesign or FlatFaceDesign
        Lengths in its unit, angles in radians; ``design.limits`` may fix the
        centre distance L (rocker) or a floor on R0, the follower a fixed
        offset (translating). A flat-faced follower's design is sized by
        convexity (:func:`cams.profile.flat.size_flat_face`).
    method : {"exact", "convex", "exhaustive"}, optional
        Overrides ``design.method`` (roller followers; refused for a flat face).
    objective : {"R0", "L"}, optional
        What to minimize when neither L nor a floor on R0 is fixed; ``"L"``
        applies to rockers only. Default: the design file's ``[solve]
        objective`` (``design.extra["objective"]``), else ``"R0"``.

    Returns
    -------
    SolveResult or cams.profile.flat.FlatFaceSolution
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
    f = design.follower
    lim = design.limits
    A0 = f.position(0.0)
    samples = None if method == "exact" else design.samples
    extra = _offset_line(design)
    notes: list[str] = []
    t0 = time.perf_counter()
    if objective == "L" and not isinstance(f, Rocker):
        raise InputError("solve.objective", "'L' applies to rocker followers; use 'R0'")

    L_fixed = lim.centre_distance
    floor = lim.min_base_radius
    from optimize.circle import admissible_at_distance, best_on_circle, round_off, violation_function

    G = violation_function(design, samples)
    sol: CentreSolution | None = None
    if L_fixed is None:
        target = A0 if objective == "R0" else f.pivot
        sol = nearest(design, target, method=method, extra=extra)
        centre, mode = sol.centre, ("min_R0" if objective == "R0" else "min_L")
        if extra is not None:
            mode = "fixed_offset"
        if floor is not None and np.linalg.norm(centre - A0) < floor:
            mode = "floor_R0"
            if extra is not None:
                cands = [np.array([_offset_x(f.offset), sg * np.sqrt(max(floor**2 - f.offset**2, 0.0))]) for sg in (1, -1)]
                cands = [p for p in cands if floor >= abs(f.offset) and G(p) <= round_off(design, np.abs(p).sum())]
                if not cands:
                    raise InfeasibleError("limits.min_base_radius", f"R0 = {floor:g} with offset {f.offset:g} is not admissible")
                centre = min(cands, key=G)
            else:
                seeds = _seeds(design, A0, floor, sol.centre)
                centre = best_on_circle(design, A0, floor, G, samples=samples, seeds=seeds)
                if centre is None:  # pragma: no cover - the zone is unbounded beyond R0_min
                    raise InfeasibleError("limits.min_base_radius", f"no admissible centre at R0 = {floor:g}")
            notes.append(f"R0 raised to the constructive floor {floor:g} mm (minimum {sol.objective:.6g} mm); "
                         "centre placed with the largest margin to the zone's edges")
        elif floor is not None:
            notes.append(f"constructive floor {floor:g} mm below the minimum R0: not binding")
    else:
        mode = "fixed_L"
        dist = lambda O: float(np.linalg.norm(O - A0))  # noqa: E731
        centre = best_on_circle(design, f.pivot, L_fixed, dist, samples=samples)
        if centre is None:
            # a narrow arc near the least L: seed it from the min-L centre (convexity)
            try:
                near = nearest(design, f.pivot, method=method).centre
            except InfeasibleError as e:  # an empty zone: the limit that binds with L held too
                from optimize.diagnose import explain_infeasible

                raise (explain_infeasible(design, L=L_fixed) or e) from e
            centre = best_on_circle(design, f.pivot, L_fixed, dist, samples=samples,
                                    seeds=_seeds(design, f.pivot, L_fixed, near))
        if centre is None:
            lo, hi = admissible_L_range(design)
            rng = f"from {lo:.6g} upward" if not np.isfinite(hi) else f"from {lo:.6g} to {hi:.6g}"
            raise InfeasibleError("limits.centre_distance",
                                  f"L = {L_fixed:g} misses the allowable-centre zone; admissible L {rng}")
        least = dist(centre)
        if floor is not None and least >= floor:
            notes.append(f"constructive floor {floor:g} mm below the least R0 at this L ({least:.6g} mm): not binding")
        elif floor is not None:
            # R0 raised to the floor: the crossings of the circles |O - pivot| = L and |O - A0| = floor that lie
            # on the admissible arcs of the L circle (the least-R0 centre's arc found again from its angle)
            rel = centre - f.pivot
            cands = admissible_at_distance(design, f.pivot, L_fixed, A0, floor, samples=samples,
                                           seeds=(float(np.arctan2(rel[1], rel[0]) % (2 * np.pi)),))
            if not cands:
                raise InfeasibleError("limits.min_base_radius",
                                      f"R0 = {floor:g} is not admissible at L = {L_fixed:g} (the least R0 there is "
                                      f"{least:.6g}; the admissible centres on that circle do not reach R0 = {floor:g})")
            centre = min(cands, key=G)
            mode = "fixed_L_and_R0"
            notes.append(f"R0 raised to the constructive floor {floor:g} mm (least at this L {least:.6g} mm)")
    seconds = time.perf_counter() - t0
    if sol is not None and mode in ("min_R0", "min_L", "fixed_offset"):
        binding, error_bound, certified = sol.binding, sol.error_bound, sol.certified
        if certified is False:
            notes.append(f"NOT CERTIFIED: the exact method's bounds differ by {error_bound:.3g} (lower bound "
                         f"{sol.lower_bound:.9g}): do not use this answer; try method = \"convex\""
                         if error_bound is not None else
                         "NOT CERTIFIED: no centre was checked feasible near the exact method's answer; do not use it")
        if samples is not None:
            notes.append(f"sampled at {samples} steps per phase: the limit may be exceeded slightly between samples")
    else:
        binding, error_bound, certified = (), None, None
    R0 = float(np.linalg.norm(centre - A0))
    # the roller centre's travel: arc l*psi_max of a rocker, the stroke of a translating follower
    travel = design.program.lift * (f.arm if isinstance(f, Rocker) else 1.0)
    vanishing = InfeasibleError(
        "limits.pressure_angle",
        f"the minimum base radius vanishes (R0 = {R0:.3g}, {R0 / travel:.2g} of the roller's travel; the "
        "pressure angle cannot be verified at this size): set limits.min_base_radius to size a buildable cam",
    )
    if R0 < 1e-9 * travel:
        raise vanishing
    margin = -G(centre)
    pressure = check_pressure(design, centre)
    if not pressure.ok and R0 < 1e-6 * travel and method == "exact":
        raise vanishing
    return _result(design, centre, pressure, margin, notes, "set limits.min_base_radius or a smaller roller",
                   method=method, samples=samples, mode=mode, binding=binding, error_bound=error_bound,
                   seconds=seconds, certified=certified)
