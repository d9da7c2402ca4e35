"""Why no cam centre is admissible: the limit that binds and the nearest value of it that is feasible.

When the allowable-centre zone is empty, :func:`explain_infeasible` changes
one limit at a time, the others held, and finds by bisection on the zone's
emptiness the value where the zone stops being empty. Emptiness is decided by
the sign of the zone's largest inscribed margin (:func:`zone_margin`, every
cam angle), a quantity that varies continuously with the limits, rather than
by a solver's feasibility tolerance:

* ``limits.pressure_angle`` (the rise; also the return under form closure when
  no return limit is given) and ``limits.return_pressure_angle`` (form
  closure): the least feasible allowable angle (larger is looser);
* ``limits.safety_factor`` (K_C of seed formula 3.26, rockers): the largest
  feasible K_C (larger is stricter, 1 the loosest);
* both pressure angles together, when neither alone is enough.

A fixed offset of a translating follower never empties the zone: every wedge
contains the half-line from its apex along -Y widening at its half-angle, so
the zone reaches every offset far enough down; a fixed L misses a non-empty
zone, and :func:`admissible_L_range` gives its admissible range.

The bound of the feasible set is an infimum (a supremum for K_C). When it is
attained (the zone there a point or a segment) the value printed is rounded
towards the feasible side, so that it is feasible itself. When the zone runs
off to infinity as the limit approaches it (the least R0 grows without bound,
:func:`_attained`; a rocker's limit falling to half its swing), the message
says it is not attained and prints the bound rounded to the nearest.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from cams.model.design import CamDesign
from cams.model.follower import Rocker
from laws.errors import InfeasibleError, SolverError
from laws.search import bisect_boundary
from optimize.result import CentreSolution

__all__ = ["admissible_L_range", "diagnosed", "explain_infeasible", "Relaxation", "relaxations", "zone_margin",
           "zone_empty", "least_R0"]

#: Loosest allowable pressure angle tried (degrees; the limits must stay below 90).
LOOSEST_DEG = 89.99
#: Bisection stops when the bracket is narrower than this (degrees for angles, absolute for K_C).
ANGLE_TOL_DEG = 1e-6
K_TOL = 1e-9
#: Ratio of the least R0's successive steps, one decade closer to the bound each, at and above which it
#: grows without bound: the bound is not attained (:func:`_attained`).
GROWTH = 0.9


@dataclass(frozen=True)
class Relaxation:
    """The nearest feasible value of one limit, the others held.

    Attributes
    ----------
    field : str
        Dotted name of the limit, e.g. ``"limits.return_pressure_angle"``.
    given : float
        Its value in the design (radians for angles, K_C plain).
    bound : float
        The infimum of the feasible values (the supremum for K_C), same unit;
        the upper (lower) end of the final bisection bracket, feasible.
    attained : bool
        False when the zone runs off to infinity as the limit approaches ``bound``.
    joint : bool
        The rise's and the return's limits changed together (form closure).
    """

    field: str
    given: float
    bound: float
    attained: bool
    joint: bool = False

    @property
    def change(self) -> float:
        """Relative change the relaxation asks for, ``|bound - given| / given``."""
        return abs(self.bound - self.given) / abs(self.given)


def zone_margin(design: CamDesign, half_planes=None, *, box: float = 1e6,
                iters: int = 40) -> tuple[float, float, np.ndarray]:
    """Bounds on the zone's largest inscribed margin: ``min over O of max signed distance outside``.

    The continuous function ``G(O)`` (:func:`optimize.zone.max_violation`,
    every cam angle, length unit) is convex; its minimum is <= 0 exactly when
    the zone is not empty, and varies continuously with the limits, so the
    sign is a robust test of emptiness (no feasibility tolerance). Found by
    cutting planes: a linear program ``min t`` with ``N O - c <= t`` over the
    lines sampled at 64 steps per phase and the worst lines of the continuum
    added at each step (scipy's HiGHS), centres within ``box`` times the
    design's scale of the roller's start point A0, the box widened a
    thousandfold while the zone's best point presses on it (up to 1e12 times
    the scale: a cam far larger than its follower).

    Parameters
    ----------
    half_planes : (N, c), optional
        Half-planes held exactly (the line of a fixed offset).

    Returns
    -------
    lower, upper : float
        ``lower <= min G <= upper`` (length unit): ``lower > 0`` proves the zone
        empty (within the box), ``upper <= 0`` proves it not empty.
    centre : ndarray, shape (2,)
        The centre where ``G = upper`` (the follower's fixed frame).
    """
    scale = design.scale
    half = box * scale
    while True:
        lower, upper, best = _margin_in_box(design, half_planes, half, iters)
        # a zone that starts beyond the box (a cam far larger than its follower: tiny phases) is not
        # empty: widen the box while the best point presses on it, up to R0 ~ 1e12 times the follower
        if not (lower > 0 and np.max(np.abs(best - design.follower.position(0.0))) >= half * (1 - 1e-9)
                and half < 1e12 * scale):
            return lower, upper, best
        half *= 1e3


def _margin_in_box(design: CamDesign, half_planes, half: float, iters: int) -> tuple[float, float, np.ndarray]:
    """:func:`zone_margin` for centres within ``half`` (length unit) of A0 on each axis."""
    from scipy.optimize import linprog

    from optimize.circle import round_off
    from optimize.zone import sample_wedges, scan_peaks, zone_table

    A0 = design.follower.position(0.0)
    N, c = sample_wedges(design, 64).lines()
    eN = np.zeros((0, 2)) if half_planes is None else np.asarray(half_planes[0], float)
    ec = np.zeros(0) if half_planes is None else np.asarray(half_planes[1], float)
    bounds = [(A0[0] - half, A0[0] + half), (A0[1] - half, A0[1] + half), (None, None)]
    t = zone_table(design)
    lower, upper, best = -np.inf, np.inf, A0
    for _ in range(iters):
        A = np.vstack([np.hstack([N, -np.ones((len(N), 1))]), np.hstack([eN, np.zeros((len(eN), 1))])])
        res = linprog([0.0, 0.0, 1.0], A_ub=A, b_ub=np.concatenate([c, ec]), bounds=bounds, method="highs")
        if res.status == 2:  # the held lines miss the box
            return np.inf, np.inf, A0
        if res.status != 0:
            break
        x = np.asarray(res.x)
        O, lower = x[:2], float(x[2])
        pk = scan_peaks(t, O)
        g = float(np.max(pk.value))
        if g < upper:
            upper, best = g, O
        # G's rounding follows |O| (up to the box's size), not the follower's size alone
        if upper - lower <= max(1e-9 * design.scale, round_off(design, float(np.abs(O).sum()))) \
                or lower > 0 or upper <= 0:
            break
        bad = pk.value > lower
        N = np.vstack([N, np.stack([pk.nx[bad], pk.ny[bad]], axis=1)])
        c = np.concatenate([c, pk.offset[bad]])
    return lower, upper, best


def zone_empty(design: CamDesign, half_planes=None) -> bool:
    """True unless :func:`zone_margin` shows a centre inside the continuous zone (``upper <= 0``).

    A margin left undecided after its iterations counts as empty.
    """
    return bool(zone_margin(design, half_planes)[1] > 0)


def least_R0(design: CamDesign) -> float | None:
    """Least R0 of the continuous zone by :func:`optimize.exact.nearest_exact` (length), None if it fails."""
    from optimize.exact import nearest_exact

    try:
        return nearest_exact(design, design.follower.position(0.0)).objective
    except InfeasibleError:
        return None


def _attained(R0_at: Callable[[float], float | None], bound: float, span: float) -> bool:
    """False when the least R0 grows without bound as the limit approaches ``bound``.

    The least R0 at ``bound + k span`` for ``k = 1e-2, 1e-3, 1e-4`` (``span``
    signed towards the feasible side; ten times farther when the solver fails
    there): near an attained bound it converges to a finite value, so its
    steps from one decade to the next shrink; when the zone runs off to
    infinity they do not (a power or a logarithm of the distance). Not attained
    when the last step is positive and at least :data:`GROWTH` times the one
    before.
    """
    for ks in ((1e-2, 1e-3, 1e-4), (1e-1, 1e-2, 1e-3)):
        r0, r1, r2 = (R0_at(bound + k * span) for k in ks)
        if r0 is not None and r1 is not None and r2 is not None:
            d1, d2 = r1 - r0, r2 - r1
            return not (d2 > 0 and d2 >= GROWTH * d1)
    return True


def _misses_L(design: CamDesign, L: float) -> bool:
    """True when no admissible centre lies at centre distance ``L`` from the pivot (length): the zone is empty
    or ``L`` is outside its range (:func:`admissible_L_range`)."""
    if zone_empty(design):
        return True
    try:
        lo, hi = admissible_L_range(design)
    except InfeasibleError:
        return True
    return not lo <= L <= hi


def relaxations(design: CamDesign, half_planes=None, L: float | None = None) -> list[Relaxation]:
    """Every limit that alone can make the empty zone non-empty, with its nearest feasible value.

    Parameters
    ----------
    design : CamDesign
        A design whose zone (with ``half_planes``) is empty, or with no admissible centre at distance ``L`` from
        the pivot.
    half_planes : (N, c), optional
        Additional half-planes held (the line of a fixed offset).
    L : float, optional
        A fixed centre distance held (rocker, length): the zone must reach the circle of radius ``L`` about
        the pivot. A bounded circle: the bound is attained.

    Returns
    -------
    list of Relaxation
        Sorted by the relative change they ask for, the smallest first.
    """
    lim = design.limits
    out = []
    empty: Callable[..., bool] = zone_empty
    if L is not None:
        held = L

        def held_empty(d: CamDesign, half_planes=None) -> bool:  # L held: the zone must reach its circle
            return _misses_L(d, held)

        empty = held_empty
    loose = math.radians(LOOSEST_DEG)
    fields = ["limits.pressure_angle"]
    if lim.closure == "form" and any(p.kind == "return" for p in design.program.phases):
        fields.append("limits.return_pressure_angle")
    for name in fields:
        key = name.split(".")[1]
        given = lim.pressure_angle if key == "pressure_angle" else lim.return_limit
        if given >= loose:
            continue

        def with_value(v, key=key):
            return design.with_(limits=replace(lim, **{key: v}))

        if empty(with_value(loose), half_planes):
            continue
        bound = bisect_boundary(lambda v: not empty(with_value(v), half_planes), loose, given,
                                xtol=math.radians(ANGLE_TOL_DEG))
        attained = half_planes is not None or L is not None or _attained(lambda v: least_R0(with_value(v)), bound,
                                                                    loose - bound)
        out.append(Relaxation(name, given, bound, attained))
    if not out and len(fields) == 2:
        def both(v):
            return design.with_(limits=replace(lim, pressure_angle=v, return_pressure_angle=v))

        given = max(lim.pressure_angle, lim.return_limit)
        if given < loose and not empty(both(loose), half_planes):
            bound = bisect_boundary(lambda v: not empty(both(v), half_planes), loose, given,
                                    xtol=math.radians(ANGLE_TOL_DEG))
            attained = L is not None or _attained(lambda v: least_R0(both(v)), bound, loose - bound)
            out.append(Relaxation("limits.pressure_angle", given, bound, attained, joint=True))
    if isinstance(design.follower, Rocker) and lim.safety_factor > 1.0:
        def with_k(v):
            return design.with_(limits=replace(lim, safety_factor=v))

        if not empty(with_k(1.0), half_planes):
            bound = bisect_boundary(lambda v: not empty(with_k(v), half_planes), 1.0, lim.safety_factor, xtol=K_TOL)
            attained = half_planes is not None or L is not None or _attained(lambda v: least_R0(with_k(v)), bound,
                                                                        1.0 - bound)
            out.append(Relaxation("limits.safety_factor", lim.safety_factor, bound, attained))
    return sorted(out, key=lambda x: x.change)


def _deg(v: float, up: bool) -> str:
    """Degrees rounded to 4 decimals towards the feasible side (``up``: a larger value is feasible)."""
    d = math.degrees(v)
    r = (math.ceil if up else math.floor)(d * 1e4) / 1e4
    return f"{r:.4f} deg"


def _show(r: Relaxation, v: float) -> str:
    """A value of ``r``'s limit, rounded towards the feasible side: degrees, or K_C down to 6 decimals."""
    if r.field == "limits.safety_factor":
        return f"{math.floor(v * 1e6) / 1e6:.6f}"
    return _deg(v, up=True)


def _sentence(r: Relaxation) -> str:
    """What is feasible of ``r``'s limit, the others held."""
    kind = "largest" if r.field == "limits.safety_factor" else "least"
    if r.attained:
        return f"the {kind} feasible is {_show(r, r.bound)}"
    inf, more = ("supremum", "smaller") if kind == "largest" else ("infimum", "larger")
    near = f"{r.bound:.6f}" if r.field == "limits.safety_factor" else f"{math.degrees(r.bound):.4f} deg"
    return (f"the {inf} is {near}, not attained: every {more} value is feasible, with a cam that "
            "grows without bound as the limit approaches it")


def _where(design: CamDesign, r: Relaxation) -> str:
    """Where the limit ``r`` applies, for the message."""
    field = r.field
    if field == "limits.return_pressure_angle":
        return "on the return"
    if field == "limits.safety_factor":
        return "as K_C"
    both = design.limits.closure == "form" and design.limits.return_pressure_angle is None
    return "on the rise and the return" if both else "on the rise"


def explain_infeasible(design: CamDesign, half_planes=None, L: float | None = None) -> InfeasibleError | None:
    """One-line error naming the limit that binds and its nearest feasible value, the others held.

    Parameters
    ----------
    design : CamDesign
        A design for which a solver found no admissible centre.
    half_planes : (N, c), optional
        The half-planes of a fixed offset (``optimize.sizing._offset_line``).
    L : float, optional
        The fixed centre distance ``limits.centre_distance`` (rocker, length), held with the other limits.

    Returns
    -------
    InfeasibleError or None
        None when the continuous zone (with ``half_planes``) is not empty after all
        (the caller keeps its own error). The field is the limit whose
        feasible value is the smallest relative change; the others that alone
        would do are listed after it.
    """
    if not zone_empty(design, half_planes):
        return None
    found = relaxations(design, half_planes, L)
    held = "other limits held" if L is None else f"other limits and L = {L:g} mm held"
    if not found:
        if L is not None:
            free = explain_infeasible(design, half_planes)
            return InfeasibleError("limits.pressure_angle", f"no cam centre satisfies the limits at L = {L:g} mm, "
                                   "and no limit relaxed alone with L held makes one admissible; without "
                                   f"limits.centre_distance, {free}")
        return InfeasibleError("limits.pressure_angle", "no cam centre satisfies the limits, and no limit relaxed "
                               f"(pressure angles up to {LOOSEST_DEG:g} deg, K_C down to 1) makes one admissible")
    r = found[0]
    if r.joint:
        lim = design.limits
        return InfeasibleError(r.field, f"no cam centre satisfies {math.degrees(lim.pressure_angle):.6g} deg on the "
                               f"rise and {math.degrees(lim.return_limit):.6g} deg on the return, and no limit relaxed "
                               "alone is enough; with limits.return_pressure_angle equal to it, "
                               f"{_sentence(r)} ({held})")
    given = f"{r.given:g}" if r.field == "limits.safety_factor" else f"{math.degrees(r.given):.6g} deg"
    msg = f"no cam centre satisfies {given} {_where(design, r)}; {_sentence(r)} ({held})"
    for o in found[1:]:
        msg += f"; or {o.field}: {_sentence(o)}"
    return InfeasibleError(r.field, msg)


def diagnosed(solver: Callable[..., CentreSolution]) -> Callable[..., CentreSolution]:
    """Wrap a nearest-centre solver ``solver(design, target, *, half_planes=None, ...)``: explain an empty zone.

    An :class:`InfeasibleError` of an empty zone (field ``limits.pressure_angle``
    or ``follower.offset``) is replaced by :func:`explain_infeasible`'s, which
    names the limit that binds and its nearest feasible value. When the
    continuous zone is not empty after all (a centre where the continuous
    zone's violation, :func:`optimize.zone.max_violation`, is proven <= 0), the solver failed: a
    :class:`laws.errors.SolverError` (the product's failure, not the input's) says so and gives that centre's
    R0. A result that is not
    certified because no feasible centre was found near it (``certified`` False,
    ``error_bound`` None) is checked the same way: when the zone is empty or
    its infimum is not attained (the cam grows without bound), that diagnosis
    is raised instead of the unproven result. Every other error passes unchanged.
    """

    @functools.wraps(solver)
    def wrapper(design: CamDesign, target: np.ndarray, *args, half_planes=None, **kw):
        try:
            sol = solver(design, target, *args, half_planes=half_planes, **kw)
        except InfeasibleError as e:
            if e.field not in ("limits.pressure_angle", "follower.offset"):
                raise
            why = explain_infeasible(design, half_planes)
            if why is not None:
                raise why from e
            failed = _solver_failed(design, half_planes, e)
            if failed is None:
                raise
            raise failed from e
        if sol.certified is False and sol.error_bound is None:
            why = explain_infeasible(design, half_planes)
            if why is not None:
                raise why
        return sol

    return wrapper


def _solver_failed(design: CamDesign, half_planes, err: InfeasibleError) -> SolverError | None:
    """The error of a solver that found no centre in a zone that is not empty, or None if unconfirmed.

    A :class:`laws.errors.SolverError`: the input is valid, the solver failed on it.
    """
    _lower, upper, O = zone_margin(design, half_planes)
    if upper > 0:
        return None
    R0 = float(np.linalg.norm(O - design.follower.position(0.0)))
    return SolverError(f"the {design.method} method found no admissible cam centre ({err}), but the zone is not "
                       f"empty: a centre at R0 = {R0:.6g} mm satisfies every limit; try another method "
                       "(solve.method or --method)")


def _lmax(design: CamDesign) -> float:
    """Largest centre distance in the zone (inf when the zone is unbounded)."""
    from optimize.bounds import recession_direction
    from optimize.planar import clip_polygon
    from optimize.zone import sample_wedges

    if recession_direction(design) is not None:
        return float("inf")
    N, c = sample_wedges(design, 512).lines()
    # a bounded zone reaching beyond this box (100 times the follower) would be clipped, L max too small (open)
    s = 100 * design.scale
    poly = clip_polygon(N, c, (-s, -s, s, s))
    return float(np.max(np.linalg.norm(poly, axis=1))) if len(poly) else 0.0


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
    from optimize.exact import nearest_exact

    lo = diagnosed(nearest_exact)(design, design.follower.pivot).objective
    return lo, _lmax(design)
