"""Sizing a roller or knife-edge follower's cam: the solver side of ``solve``.

:func:`size` picks the case from the design:

* no fixed L, no floor: the admissible centre nearest to the roller's start
  point A0 (minimum R0) or to the pivot (``objective="L"``);
* a fixed centre distance L (rocker, seed 3.23-3.25): the admissible point of
  the circle of radius L about the pivot with the least R0; if the circle
  misses the zone, :class:`InfeasibleError` gives the admissible range of L;
* a constructive floor on R0 larger than the minimum: the centre on the circle
  of radius R0_floor about A0 with the largest margin to the zone's edges;
* a fixed offset (translating): the nearest point on the offset's line.

It returns the centre and how it was found (:class:`Sizing`); the verified
result, with the independent check of the pressure angle, is
:func:`cams.solve.solve` (the layer rule keeps the check out of this package).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from cams.model.design import METHODS, CamDesign
from cams.model.follower import Rocker, Translating
from laws.errors import InfeasibleError, InputError, check_option
from optimize.diagnose import admissible_L_range, diagnosed
from optimize.result import Binding, CentreSolution

__all__ = ["Sizing", "size", "nearest", "offset_x", "vanishing_error", "roller_travel",
           "OBJECTIVES"]

OBJECTIVES = ("R0", "L")


@dataclass(frozen=True)
class Sizing:
    """A sized cam centre and how it was found (not yet verified).

    Attributes
    ----------
    centre : ndarray, shape (2,)
        Cam centre in the follower's fixed frame (:mod:`cams.model.follower`), length unit.
    method : str
        The solver used: ``"exact"``, ``"convex"`` or ``"exhaustive"``.
    samples : int or None
        Steps per phase of a sampled method; None for ``"exact"``.
    mode : str
        ``"min_R0"``, ``"min_L"``, ``"fixed_L"``, ``"fixed_L_and_R0"``,
        ``"floor_R0"`` or ``"fixed_offset"``.
    binding : tuple of Binding
        The zone's lines through the centre (minimum R0, minimum L, fixed offset).
    error_bound : float or None
        The exact method's proven bound on the answer's error (length unit).
    certified : bool or None
        False when the exact method's bounds disagree; None where no bound is stated.
    margin : float
        Smallest distance of the centre from the zone's edges (length, > 0 inside).
    seconds : float
        Time spent sizing.
    notes : tuple of str
        What the user should know (a floor that binds, sampling, a result not certified).
    """

    centre: np.ndarray
    method: str
    samples: int | None
    mode: str
    binding: tuple[Binding, ...]
    error_bound: float | None
    certified: bool | None
    margin: float
    seconds: float
    notes: tuple[str, ...]


def offset_x(v: float) -> float:
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
        x0 = offset_x(f.offset)
        return np.array([[1.0, 0.0], [-1.0, 0.0]]), np.array([x0, -x0])
    return None


@diagnosed
def nearest(design: CamDesign, target: np.ndarray, *, method: str | None = None, half_planes=None) -> CentreSolution:
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
    half_planes : (N, c), optional
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
        The zone (with ``half_planes``) is empty: the message names the limit that
        binds and its nearest feasible value, the others held
        (:func:`optimize.diagnose.diagnosed`).
    InputError
        An unknown method; an all-pairs run that would need too much memory.
    """
    method = check_option("solve.method", method or design.method, METHODS)
    if method == "exact":
        from optimize.exact import nearest_exact

        return nearest_exact(design, target, half_planes=half_planes)
    if method == "convex":
        from optimize.convex import nearest_convex

        return nearest_convex(design, target, samples=design.samples, half_planes=half_planes)
    from optimize.exhaustive import nearest_exhaustive

    return nearest_exhaustive(design, target, samples=design.samples, half_planes=half_planes)




def _seeds(design: CamDesign, ref: np.ndarray, radius: float, inner: np.ndarray) -> tuple[float, ...]:
    """Admissible angles on the circle (``ref``, ``radius``) from an admissible ``inner`` point.

    ``inner`` lies inside the circle; a far admissible point along the zone's
    recession direction lies outside; by convexity their segment crosses the
    circle inside the zone.
    """
    from optimize.bounds import recession_direction
    from optimize.circle import crossing_seed

    rd = recession_direction(design)
    if rd is None:
        return ()
    far = inner + (2 * radius + np.linalg.norm(inner - ref) + design.scale) * rd[0]
    s = crossing_seed(ref, radius, inner, far)
    return () if s is None else (s,)


def size(design: CamDesign, *, method: str | None = None, objective: str = "R0") -> Sizing:
    """The smallest admissible cam centre of ``design`` (roller or knife edge; not a chosen cam).

    Parameters
    ----------
    design : CamDesign
        Lengths in its unit, angles in radians; ``design.limits`` may fix the
        centre distance L (rocker) or a floor on R0, the follower a fixed
        offset (translating).
    method : {"exact", "convex", "exhaustive"}, optional
        Overrides ``design.method``.
    objective : {"R0", "L"}
        What to minimize when neither L nor a floor on R0 is fixed; ``"L"``
        applies to rockers only.

    Returns
    -------
    Sizing
        The centre in the follower's fixed frame and how it was found.

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
    method = check_option("solve.method", method or design.method, METHODS)
    check_option("solve.objective", objective, OBJECTIVES)
    design = design.with_(method=method) if method != design.method else design
    f = design.follower
    lim = design.limits
    A0 = f.position(0.0)
    samples = None if method == "exact" else design.samples
    half_planes = _offset_line(design)
    notes: list[str] = []
    t0 = time.perf_counter()
    if objective == "L" and not isinstance(f, Rocker):
        raise InputError("solve.objective", "'L' applies to rocker followers; use 'R0'")

    L_fixed = lim.centre_distance
    floor = lim.min_base_radius
    from optimize.circle import (
        admissible_at_distance,
        best_on_circle,
        round_off,
        violation_function,
    )

    G = violation_function(design, samples)
    sol: CentreSolution | None = None
    if L_fixed is None:
        target = A0 if objective == "R0" else f.pivot
        sol = nearest(design, target, method=method, half_planes=half_planes)
        centre, mode = sol.centre, ("min_R0" if objective == "R0" else "min_L")
        if half_planes is not None:
            mode = "fixed_offset"
        if floor is not None and np.linalg.norm(centre - A0) < floor:
            mode = "floor_R0"
            off = f.offset if isinstance(f, Translating) else None
            if off is not None:  # the fixed offset (``half_planes`` is its line)
                cands = [np.array([offset_x(off), sg * np.sqrt(max(floor**2 - off**2, 0.0))]) for sg in (1, -1)]
                cands = [p for p in cands if floor >= abs(off) and G(p) <= round_off(design, np.abs(p).sum())]
                if not cands:
                    raise InfeasibleError("limits.min_base_radius",
                                          f"R0 = {floor:g} with offset {off:g} is not admissible")
                centre = min(cands, key=G)
            else:
                seeds = _seeds(design, A0, floor, sol.centre)
                on_floor = best_on_circle(design, A0, floor, G, samples=samples, seeds=seeds)
                if on_floor is None:  # pragma: no cover - the zone is unbounded beyond R0_min
                    raise InfeasibleError("limits.min_base_radius", f"no admissible centre at R0 = {floor:g}")
                centre = on_floor
            notes.append(f"R0 raised to the constructive floor {floor:g} mm (minimum {sol.objective:.6g} mm); "
                         "centre placed with the largest margin to the zone's edges")
        elif floor is not None:
            notes.append(f"constructive floor {floor:g} mm below the minimum R0: not binding")
    else:
        mode = "fixed_L"
        dist = lambda O: float(np.linalg.norm(O - A0))  # noqa: E731
        on_L = best_on_circle(design, f.pivot, L_fixed, dist, samples=samples)
        if on_L is None:
            # a narrow arc near the least L: seed it from the min-L centre (convexity)
            try:
                near = nearest(design, f.pivot, method=method).centre
            except InfeasibleError as e:  # an empty zone: the limit that binds with L held too
                from optimize.diagnose import explain_infeasible

                raise (explain_infeasible(design, L=L_fixed) or e) from e
            on_L = best_on_circle(design, f.pivot, L_fixed, dist, samples=samples,
                                  seeds=_seeds(design, f.pivot, L_fixed, near))
        if on_L is None:
            lo, hi = admissible_L_range(design)
            rng = f"from {lo:.6g} upward" if not np.isfinite(hi) else f"from {lo:.6g} to {hi:.6g}"
            raise InfeasibleError("limits.centre_distance",
                                  f"L = {L_fixed:g} misses the allowable-centre zone; admissible L {rng}")
        centre = on_L
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
                                      f"{least:.6g}; the admissible centres on that circle do not reach "
                                      f"R0 = {floor:g})")
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
    if R0 < 1e-9 * roller_travel(design):
        raise vanishing_error(design, R0)
    return Sizing(centre=np.asarray(centre, float), method=method, samples=samples, mode=mode, binding=binding,
                  error_bound=error_bound, certified=certified, margin=float(-G(centre)), seconds=seconds,
                  notes=tuple(notes))


def roller_travel(design: CamDesign) -> float:
    """The roller centre's travel (length unit): the arc ``l psi_max`` of a rocker, the stroke of a translating one."""
    f = design.follower
    return design.program.lift * (f.arm if isinstance(f, Rocker) else 1.0)


def vanishing_error(design: CamDesign, R0: float) -> InfeasibleError:
    """The error of a minimum base radius ``R0`` (length unit) too small against the roller's travel to verify."""
    travel = roller_travel(design)
    return InfeasibleError(
        "limits.pressure_angle",
        f"the minimum base radius vanishes (R0 = {R0:.3g}, {R0 / travel:.2g} of the roller's travel; the "
        "pressure angle cannot be verified at this size): set limits.min_base_radius to size a buildable cam",
    )
