"""The driver: a design's free phases' laws, designed with the cam.

:func:`design_laws` resolves the request (free phases, caps, what is held).
For a translating follower it solves the conservative program (every
constraint at every cam angle, by the Bernstein coefficients of every piece of
every span) for the laws and the relaxed program (the constraints at samples
only) for a proven lower bound on the space's optimum. A rocker's problem is
not convex: sequential convex programming (:mod:`optimize.motion.rocker`, a
flat face's :mod:`optimize.motion.flat_rocker`) gives a local optimum and its
measure, no bound. The caller (:mod:`cams.motion_design`) then sizes and checks
the cam of the laws found, which gives the upper bound.

A translating follower's laws then go through a second stage
(:mod:`optimize.motion.smooth`): the same conservative program with the
objective held within ``(1 + smoothing_slack)`` of the value found, minimizing
the integral of the squared derivative after the last continuous one; the
first stage's laws are kept beside them (:attr:`LawDesign.first`) for the
caller to check and compare. A rocker's laws are its iteration's, unsmoothed.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace

import numpy as np

from cams.model.design import CamDesign, FlatFaceDesign
from cams.model.follower import Translating
from cams.model.motiondesign import (
    CAP_KEYS,
    MAX_DEGREE,
    MAX_ROCKER_SPANS,
    MAX_SPANS,
    MAX_VARIABLES,
    MotionDesignSpec,
)
from laws.errors import InfeasibleError, InputError
from laws.program import Program
from optimize.motion.conic import Assembly, ConicProgram, Solution, SolverFailure, lower_bound, solve
from optimize.motion.lawrows import check_lift
from optimize.motion.smooth import allowance, pulled_back, smoothing_derivative, smoothing_program
from optimize.motion.space import CONSISTENT, Space
from optimize.motion.translating import (
    Request,
    build,
    conservative_ratio,
    form_ratio,
    pressure_rows,
    pressure_terms,
)

__all__ = ["LawDesign", "design_laws", "free_phases", "resolve_caps", "BISECTION_STEPS"]

#: Steps of the pressure-angle bisection (each halves the bracket of the ratio) where no law meets the limits.
BISECTION_STEPS = 18
#: Relative decrease of the least pressure-angle ratio below which Dinkelbach's iteration stops.
RATIO_RTOL = 1e-6
#: At most this many programs per Dinkelbach iteration.
MAX_DESCENT = 30
#: Dinkelbach's steps on the relaxed program, from the conservative program's least point: the relaxed least
#: ratio is then found to the precision the proof's margin needs (the step from so near converges superlinearly).
RELAXED_STEPS = 1
#: The first ratio tried for the proof of the lower end is below the relaxed program's least found by this many
#: times the solver's loss in the bound over the slack's slope (:func:`_proven_below`).
PROOF_SAFETY = 2.0
#: Ratios tried for that proof (each lower than the last by what its slack lacked, :func:`_proven_below`) before
#: the bisection.
PROOF_TRIES = 4
#: The conservative program's descent stops when the decrease of the ratio still possible
#: (:func:`_still_possible`) is below this share of the certificate's gap (the ratio found less the proven
#: lower bound): a further step could not change what the certificate says beyond its last digits.
GAP_SHARE = 0.01
#: The lower end is proven (the relaxed step and the proof) once a step of the conservative descent moved every
#: pressure row's ``d + s`` by less than this share (the iteration has settled: the relaxed step from there is
#: as good as from its end).
SETTLED = 1e-3


@dataclass(frozen=True)
class LawDesign:
    """The laws found and what the programs proved.

    Attributes
    ----------
    program : Program
        The cycle with the free phases' laws replaced by :class:`laws.spline.SplineLaw`.
    free : tuple of int
        The free phases.
    objective : str
    solver_value : float
        The conservative program's value as the solver reports it (not a bound).
    lower_bound : float or None
        A proven lower bound of the objective over the space (the relaxed program's multipliers); None for a
        rocker (not convex: a local optimum, see ``local_measure``).
    centre : (float, float)
        Translating roller: the cam centre ``(x, d)`` the conservative program found (``x = -e``, the centre at
        ``(x, -d)``); flat: ``(R0, 0)``; rocker: the centre ``(x, y)`` of the last iterate's exact sizing.
    caps : dict of (int, int) to float
        The caps imposed, ``(k, r) -> cap`` (free phase ``k``, derivative ``r``).
    space : Space
    box_binds : bool
        True when the returned laws touch the space's declared box (the bound then holds in the box only).
    seconds : float
    local_measure : float or None
        Rocker: the relative decrease the linearized program still predicts in the last trust region
        (:mod:`optimize.motion.rocker`); None otherwise.
    iterations : int or None
        Rocker: the sequential convex programming's iterations.
    history : tuple of float
        Rocker: the exact value after each accepted step, the start first.
    first : Program or None
        The first stage's laws when the second stage (:mod:`optimize.motion.smooth`) replaced them by the
        smoothest within ``smoothing_slack``; None when no second stage ran (see ``smoothing_note``).
    first_centre : (float, float) or None
        The first stage's centre, as ``centre``.
    smoothing_note : str or None
        Why no second stage ran, or why its laws were not kept (None when they were, or for no free phase).
    """

    program: Program
    free: tuple[int, ...]
    objective: str
    solver_value: float
    lower_bound: float | None
    centre: tuple[float, float]
    caps: dict[tuple[int, int], float]
    space: Space
    box_binds: bool
    seconds: float
    local_measure: float | None = None
    iterations: int | None = None
    history: tuple[float, ...] = ()
    first: Program | None = None
    first_centre: tuple[float, float] | None = None
    smoothing_note: str | None = None


def free_phases(spec: MotionDesignSpec, program: Program) -> tuple[int, ...]:
    """The indices of the free phases ``spec.free`` names, increasing.

    Raises
    ------
    InputError
        ``optimize.free`` naming a phase that does not exist or is a dwell, or
        a kind the program does not have.
    """
    out: set[int] = set()
    kinds = [p.kind for p in program.phases]
    for v in spec.free:
        if isinstance(v, str):
            found = [i for i, k in enumerate(kinds) if k == v]
            if not found:
                raise InputError("optimize.free", f"the program has no {v} phase")
            out.update(found)
        else:
            if not 0 <= v < len(kinds):
                raise InputError("optimize.free", f"phase {v} does not exist: the phases are numbered 0 to "
                                 f"{len(kinds) - 1}")
            if kinds[v] == "dwell":
                raise InputError("optimize.free", f"phase {v} is a dwell: only a rise or a return has a law to design")
            if v in out:
                raise InputError("optimize.free", f"names phase {v} twice: give each free phase once")
            out.add(v)
    return tuple(sorted(out))


def resolve_caps(spec: MotionDesignSpec, free: tuple[int, ...]) -> dict[tuple[int, int], float]:
    """``(k, r) -> cap``: the numbers of the caps (a law's name gives that law's peak, ``laws.characteristics``)."""
    from laws.characteristics import characteristics
    from laws.registry import get_law

    out = {}
    for key, r in CAP_KEYS.items():
        caps = getattr(spec, key)
        if len(caps) not in (1, len(free)):
            raise InputError(f"optimize.{key}", f"gives {len(caps)} caps for {len(free)} free phases: give one, or "
                             "one per free phase")
        for k in range(len(free)):
            c = spec.cap(key, k)
            if c is None:
                continue
            if isinstance(c, str):
                ch = characteristics(get_law(c, f"optimize.{key}"))
                value = (ch.cv, ch.ca, ch.cj)[r - 1]
                if not np.isfinite(value):
                    raise InputError(f"optimize.{key}", f"the law {c!r} has no finite peak of that derivative "
                                     "(it jumps): give a number")
                c = float(value)
            out[(k, r)] = float(c)
    return out


def _check_request(design: CamDesign | FlatFaceDesign, spec: MotionDesignSpec) -> None:
    flat = isinstance(design, FlatFaceDesign)
    f = design.follower
    if f.kind == "rocker":
        if spec.smoothing_slack > 0:
            raise InputError("optimize.smoothing_slack", "applies to translating followers (one convex program): a "
                             "rocker's laws are its sequential iteration's local optimum, not smoothed; remove it")
        if spec.spans > MAX_ROCKER_SPANS:
            raise InputError("optimize.spans", f"a rocker's motion design (sequential convex programming) takes "
                             f"from 1 to {MAX_ROCKER_SPANS} spans, got {spec.spans}: its time grows with their "
                             "square")
        if flat and spec.objective == "L":
            raise InputError("optimize.objective", "a flat-faced rocker's centre distance is given "
                             "(follower.centre_distance): its cam is sized by 'R0'")
        if spec.objective not in ("R0", "L") and isinstance(design, CamDesign) and design.chosen:
            raise InputError("optimize.objective", f"{spec.objective!r} holds the cam's size: for a rocker, the "
                             "original laws' least R0, not a chosen cam (remove [cam] base_radius or centre)")
    elif spec.objective == "L":
        raise InputError("optimize.objective", "'L' (the centre distance) applies to rocker followers; a "
                         "translating follower's cam is sized by 'R0'")
    if flat and spec.objective == "pressure_angle":
        raise InputError("optimize.objective", "a flat face's pressure angle is fixed by its geometry: "
                         "'pressure_angle' does not apply")
    r = {"jerk_squared": 3, "snap_squared": 4}.get(spec.objective)
    if r is not None and spec.degree < r:
        raise InputError("optimize.degree", f"{spec.objective!r} integrates derivative {r}: the degree must be at "
                         f"least {r}")
    need = {"Cj": 2, "jerk_squared": 2, "snap_squared": 3}.get(spec.objective, 0)
    if any(c is not None for c in spec.max_Cj):
        need = max(need, 2)
    if spec.continuity < need:
        what = "a cap on Cj" if spec.objective not in ("Cj", "jerk_squared", "snap_squared") else repr(spec.objective)
        raise InputError("optimize.continuity", f"{what} needs continuity at least {need}: with {spec.continuity} "
                         f"the derivative {need} jumps at the knots and its peak is infinite")
    if spec.objective not in ("R0", "L") and getattr(design.limits if isinstance(design, CamDesign) else design,
                                                     "min_base_radius", None) is not None:
        raise InputError("limits.min_base_radius", f"[optimize] objective {spec.objective!r} holds the cam's size: "
                         "a floor on R0 has nothing to size; remove one of them")
    if flat and spec.continuity < 2:
        raise InputError("optimize.continuity", "a flat face's profile curvature follows s'': it must be "
                         "continuous, continuity at least 2")


def design_laws(design: CamDesign | FlatFaceDesign, spec: MotionDesignSpec, *, hold: float | None = None,
                pieces: int | None = None) -> LawDesign:
    """Design the free phases' laws of ``design`` as ``spec`` asks.

    Parameters
    ----------
    design : CamDesign or FlatFaceDesign
        Its free phases' laws are the reference (a translating follower's
        programs do not use them; a rocker's iteration starts from the
        space's law nearest them).
    spec : MotionDesignSpec
    hold : float or None
        For objectives other than ``"R0"``: the base radius held (length; the
        cam centre may move on or inside that circle, the offset if it is
        free). A chosen cam (``[cam] base_radius`` or ``centre``) is held as
        it is. Ignored for ``"R0"``.
    pieces : int or None
        Subdivisions per span of the conservative constraints (default
        :data:`optimize.motion.space.PIECES`).

    Returns
    -------
    LawDesign

    Raises
    ------
    InputError
        A request the follower cannot take, or a cap no law of the space can
        meet with the joints' conditions (named, proven by solving the space
        with that cap alone).
    InfeasibleError
        The request is infeasible as a whole (the families whose union is
        infeasible are named).
    """
    try:
        return _design_laws(design, spec, hold, pieces)
    except SolverFailure:
        raise InfeasibleError("optimize", f"the conic solver failed on this space ({spec.spans} spans of degree "
                              f"{spec.degree}: numerical trouble); try fewer spans or a lower degree") from None


def _design_laws(design: CamDesign | FlatFaceDesign, spec: MotionDesignSpec, hold: float | None,
                 pieces: int | None) -> LawDesign:
    """:func:`design_laws`, its solver's failures not yet said in words."""
    t0 = time.perf_counter()
    _check_request(design, spec)
    program = design.program
    free = free_phases(spec, program)
    if not free and spec.objective in ("Ca", "Cj", "jerk_squared", "snap_squared"):
        raise InputError("optimize.free", f"objective {spec.objective!r} is a property of the designed laws: name "
                         "the free phases (free = [] designs none)")
    size = len(free) * spec.spans * (spec.degree + 1)
    if size > MAX_VARIABLES:
        most = MAX_VARIABLES // (len(free) * (spec.degree + 1))
        raise InputError("optimize.spans", f"{spec.spans} spans of degree {spec.degree} for {len(free)} free "
                         f"phase{'s' if len(free) > 1 else ''} are {size:,} variables, the programs take at most "
                         f"{MAX_VARIABLES:,} (their memory grows with the square): at most {most} spans at this "
                         "degree, or fewer free phases")
    caps = resolve_caps(spec, free)
    kw = {} if pieces is None else {"pieces": pieces}
    space = Space(program, free, spec.degree, spec.spans, spec.continuity, **kw)
    _check_space(space)
    name = f"designed spline (degree {spec.degree}, {spec.spans} spans, C{spec.continuity})"
    if isinstance(design, FlatFaceDesign) and design.follower.kind == "rocker":
        from optimize.motion.flat_rocker import design_flat_rocker, design_flat_rocker_held

        if spec.objective == "R0":
            steps = design_flat_rocker(design, space, caps, name)
        else:
            held = design.base_radius if design.base_radius is not None else hold
            if held is None:
                raise ValueError("an objective other than R0 needs the size held")
            steps = design_flat_rocker_held(design, space, caps, spec.objective, float(held), name)
        return _rocker_result(steps, spec, free, caps, space, t0)
    if isinstance(design, CamDesign) and design.follower.kind == "rocker":
        from optimize.motion.rocker import design_rocker

        if spec.objective in ("R0", "L"):
            steps = design_rocker(design, space, caps, spec.objective, name)
        elif spec.objective == "pressure_angle":
            from optimize.motion.rocker import design_rocker_pressure

            if hold is None:
                raise ValueError("the least pressure angle needs the size held")
            steps = design_rocker_pressure(design, space, caps, float(hold), name)
        else:
            from optimize.motion.rocker import design_rocker_held

            if hold is None:
                raise ValueError("an objective other than R0 or L needs the size held")
            steps = design_rocker_held(design, space, caps, spec.objective, float(hold), name)
        return _rocker_result(steps, spec, free, caps, space, t0)
    flat = isinstance(design, FlatFaceDesign)
    f = design.follower
    limits: dict[int, float] = {}
    min_radius = 0.0
    if isinstance(design, FlatFaceDesign):
        min_radius = float(design.min_radius)
    else:
        limits = dict(design.constrained_phases())
    centre = None
    x_fixed = None
    held = None
    if spec.objective != "R0":
        if isinstance(design, CamDesign) and design.chosen:
            c = design.chosen_centres()[0]
            centre = (float(c[0]), float(-c[1]))
        elif flat and design.base_radius is not None:
            centre = (float(design.base_radius), 0.0)
        else:
            if hold is None:
                raise ValueError("an objective other than R0 needs the size held")
            held = float(hold)
    if isinstance(f, Translating) and f.offset is not None and centre is None:
        x_fixed = -float(f.offset)
    # the declared box on the geometry: far beyond any cam this design could want
    bound = 100.0 * (design.scale + float(program.lift) + (held or 0.0) + (float(np.hypot(*centre)) if centre else 0.0))
    base = Request(space=space, follower="flat" if flat else "roller", cam_sense=design.cam_sense, limits=limits,
                   caps=caps, objective=spec.objective, bound=bound, centre=centre, x_fixed=x_fixed, hold=held,
                   min_radius=min_radius, length=design.scale)
    squared = spec.objective in ("jerk_squared", "snap_squared")
    if spec.objective == "pressure_angle":
        result, lb, conservative = _least_pressure(base, limits)
        # the second stage: the feasibility program at the ratio found times (1 + slack), its slack at most 0; the
        # ratio found is the first stage's point's own in the conservative rows (the iteration ends at it)
        found = min(conservative_ratio(base, result.v), float(result.value))
        ratio = min(allowance(found, spec.smoothing_slack), _top(limits))
        stage, bound = conservative.program(ratio), 0.0
    else:
        stage = build(base, "conservative")
        result = _solve_or_explain(stage, base)
        bound = allowance(float(result.value), spec.smoothing_slack, root=squared)
        relaxed = build(base, "relaxed")
        lb = lower_bound(relaxed, solve(relaxed))
        value = result.value
        if spec.objective == "R0":                # the programs' lengths are in units of the design's scale
            lb, value = lb * design.scale, value * design.scale
        if squared:
            lb = max(lb, 0.0) ** 2
            value = value**2
        result = replace(result, value=value)
    nc = space.size
    ell = design.scale

    def geometry(w: np.ndarray) -> tuple[float, float]:
        geo = (float(w[nc]) * ell, 0.0) if flat else (float(w[nc]) * ell, float(w[nc + 1]) * ell)
        if held is not None and not flat:
            geo = _within(geo, held, x_fixed is not None)
        return geo

    v = space.project(result.v)
    first, first_centre, note = None, None, None
    if free:
        smoothed, note = _second_stage(stage, space, bound, spec.objective)
        if smoothed is not None:
            first, first_centre = space.programme(v, name), geometry(v)
            v = pulled_back(space, caps, v, space.project(smoothed))
    new_program = space.programme(v, name)
    box = space.bounds(caps)
    binds = bool(np.any((np.abs(v[:nc]) >= 0.999 * box) & space.declared(caps)))
    return LawDesign(program=new_program, free=free, objective=spec.objective, solver_value=float(result.value),
                     lower_bound=float(lb), centre=geometry(v), caps=caps, space=space, box_binds=binds,
                     seconds=time.perf_counter() - t0, first=first, first_centre=first_centre, smoothing_note=note)


def _second_stage(stage: ConicProgram, space: Space, bound: float,
                  objective: str) -> tuple[np.ndarray | None, str | None]:
    """The second stage's point (:mod:`optimize.motion.smooth`) on the first stage's program ``stage`` with
    its objective at most ``bound``: ``(v, None)``, or ``(None, why not)``."""
    r = smoothing_derivative(space)
    if {"jerk_squared": 3, "snap_squared": 4}.get(objective) == r:
        return None, (f"the objective is the smoothing integral itself (of the derivative {r}): its optimum is the "
                      "smoothest law")
    try:
        sol = solve(smoothing_program(stage, space, bound))
    except SolverFailure as e:
        return None, f"the second stage's solver failed ({e.status}): the first stage's laws are returned"
    if not sol.feasible:
        return None, "the second stage's solver found no point: the first stage's laws are returned"
    return sol.v[:-1], None


def _within(centre: tuple[float, float], held: float, x_fixed: bool) -> tuple[float, float]:
    """A translating roller's centre ``(x, d)`` (length) put within the size held, ``hypot(x, d) <= held``: the
    conic solver meets the size's cone only to its tolerance (a centre 7e-8 of R0 outside was returned).
    Radially, or, with the offset fixed (``x_fixed``), by ``d`` alone; unchanged when it is within."""
    x, d = centre
    if np.hypot(x, d) <= held:
        return centre
    if x_fixed:
        d = float(np.sqrt(max(held * held - x * x, 0.0)))
    else:
        k = held / float(np.hypot(x, d))
        x, d = x * k, d * k
    while np.hypot(x, d) > held and d > 0:       # the rounding of the products
        d = float(np.nextafter(d, 0.0))
        if not x_fixed:
            x = float(np.nextafter(x, 0.0))
    return x, d


def _check_space(space: Space) -> None:
    """Refuse a space that holds no law meeting the ends and the joints (its equalities have no solution,
    :meth:`optimize.motion.space.Space.inconsistency`), naming the spans or the degree that would hold one.

    Raises
    ------
    InputError
        Field ``"optimize"``: the space is empty, whatever the cam, the limits and the caps.
    """
    if space.inconsistency() <= CONSISTENT:
        return
    p, n, c = space.degree, space.spans, space.continuity

    def holds(**change) -> bool:
        return replace(space, **change).inconsistency() <= CONSISTENT

    spans = next((m for m in range(n + 1, min(n + 2 * (c + 1), MAX_SPANS) + 1) if holds(spans=m)), None)
    degree = next((q for q in range(p + 1, MAX_DEGREE + 1) if holds(degree=q)), None)
    ways = [f"{spans} spans" if spans else "", f"degree {degree}" if degree else ""]
    would = " or ".join(w for w in ways if w)
    raise InputError("optimize", f"the space (degree {p}, continuity {c}, {n} span{'s' if n > 1 else ''} per free "
                     f"phase) holds no law that meets the joints' conditions (S(0) = 0, S(1) = 1 and derivatives 1 "
                     f"to {c} equal to the neighbouring phases' at both ends): "
                     + (f"{would} would hold one, or a lower continuity" if would else "lower the continuity"))


def _rocker_result(steps, spec: MotionDesignSpec, free: tuple[int, ...], caps: dict[tuple[int, int], float],
                   space: Space, t0: float) -> LawDesign:
    """The :class:`LawDesign` of a rocker's sequential convex programming (no bound: a local optimum)."""
    box = space.bounds(caps)
    history, value = steps.history, steps.value
    if spec.objective in ("jerk_squared", "snap_squared"):     # the programs minimize the integral's root
        history, value = tuple(x**2 for x in history), value**2
    return LawDesign(program=steps.program, free=free, objective=spec.objective, solver_value=value,
                     lower_bound=None, centre=(float(steps.centre[0]), float(steps.centre[1])), caps=caps,
                     space=space, box_binds=bool(np.any((np.abs(steps.v) >= 0.999 * box) & space.declared(caps))),
                     seconds=time.perf_counter() - t0, local_measure=steps.local_measure,
                     iterations=steps.iterations, history=history)


def _explain_caps(req: Request) -> None:
    """Raise when the space alone has no law within the lift (:func:`optimize.motion.lawrows.check_lift`), or
    naming a cap that no law of the space meets on its own (with the joints), proven by solving the space with
    that cap alone; return when each alone is feasible."""
    check_lift(req.space)
    names = {r: k for k, r in CAP_KEYS.items()}
    for (k, r), cap in req.caps.items():
        alone = replace(req, caps={(k, r): cap}, limits={}, objective="Ca",
                        centre=None, hold=None, x_fixed=None, follower="roller", min_radius=0.0)
        if not solve(build(alone, "relaxed")).feasible:
            raise InputError(f"optimize.{names[r]}", f"{cap:g} is below what any law of the space can meet with the "
                             f"joints' conditions (free phase {req.space.free[k]}: the space with this cap alone is "
                             "infeasible); raise it, lower the continuity or free the neighbouring phase")


def _solve_or_explain(prog: ConicProgram, req: Request):
    """Solve ``prog``; when it is infeasible, find a family of constraints infeasible on its own and say so."""
    sol = solve(prog)
    if sol.feasible:
        return sol
    if (req.hold is not None or req.centre is not None) and req.follower != "flat" and req.limits:
        _no_law_at_size(req)
    _explain_caps(req)
    limit = "the convexity limit (limits.min_radius)" if req.follower == "flat" else "the pressure-angle limits"
    field = "limits.min_radius" if req.follower == "flat" else "optimize"
    with_caps = " with the caps (each cap alone is feasible)" if req.caps else ""
    if req.hold is not None or req.centre is not None:
        raise InfeasibleError(field, f"{limit} admit no law of the space at the cam size held{with_caps}; "
                              "let the cam grow (objective 'R0') or choose a larger cam")
    if req.caps and not req.limits and req.follower != "flat":
        raise InfeasibleError("optimize", "the caps together admit no law of the space (each alone is feasible): "
                              "raise one of them or lower the continuity")
    raise InfeasibleError(field, f"{limit} admit no law of the space with the joints' conditions{with_caps}: "
                          "lengthen the free phases, lower the continuity, or raise a cap")


def _top(limits: dict[int, float]) -> float:
    """The largest ratio that keeps every pressure-angle limit (radians) below 90 degrees."""
    return (np.pi / 2) / max(limits.values()) * (1 - 1e-9)


class _Programs:
    """The feasibility programs of one form (:func:`optimize.motion.translating.build`, objective
    ``"feasibility"``) at every ratio and weighting of their pressure rows: built and assembled for the solver
    once (:class:`optimize.motion.translating.PressureRows`, :class:`optimize.motion.conic.Assembly`); each ratio
    then changes only the pressure rows' values. The solver sees coefficients over their boxes (:func:`_scales`):
    in the caller's variables an uncapped space's box
    (1e5 on the coefficients of ``S^(c)``) times the residual the solver leaves within its tolerance took the
    whole lower bound (0.45 of a ratio of 0.47: translating_force, its rise free, 20 spans) and stopped the
    descent short of the least."""

    def __init__(self, base: Request, form: str):
        self.form = form
        self.rows = pressure_rows(replace(base, objective="feasibility"), form)
        self.assembly = Assembly(self.rows.program, self.rows.pattern, scales=_scales(base, self.rows.program.n, form))

    def solve(self, ratio: float, weights: np.ndarray | None = None) -> Solution:
        return self.assembly.solve(*self.rows.values(ratio, weights))

    def program(self, ratio: float, weights: np.ndarray | None = None) -> ConicProgram:
        return self.rows.program_at(ratio, weights)


def _scales(base: Request, n: int, form: str) -> np.ndarray:
    """The ``n`` variables' scales for the solver (:class:`optimize.motion.conic.Assembly`) of ``base``'s
    programs (:func:`optimize.motion.translating.build`): a coefficient's box's half-width (the space's
    :meth:`~optimize.motion.space.Space.bounds`), else 1 (the geometry's and the slack's boxes are enforced).

    The relaxed programs give bounds: every coefficient's box pays the residual there. The conservative ones give
    the laws: only the coefficients of a free phase without caps are scaled (their boxes declared, far wider than
    a law's needs). A cap's rows, scaled to unit norm after the columns, would have a right-hand side that
    small beside the row's norm that the solver's tolerance let the law exceed the cap (by 6e-6 of it, where the
    conservative program's margin is 1e-7).
    """
    sp = base.space
    out = np.ones(n)
    take = np.ones(sp.size, bool)
    if form == "conservative":
        take = sp.declared(base.caps)
        for k in {k for k, _ in base.caps}:
            take[sp.offset(k):sp.offset(k) + sp.per_phase] = False
    half = sp.bounds(base.caps)
    out[:sp.size] = np.where(take & (half > 0), half, 1.0)
    return out


def _proven_above(base: Request, ratio: float, relaxed: _Programs | None = None) -> bool:
    """Whether no law of the space meets the limits times ``ratio`` at ``base``'s cam: the relaxed program's
    proven lower bound of the pressure rows' least slack is above 0 (weak duality; the samples a relaxation).
    ``relaxed``: the relaxed programs already built, if any."""
    if relaxed is None:
        rel = build(replace(base, objective="feasibility", ratio=ratio), "relaxed")
        return lower_bound(rel, Assembly(rel, scales=_scales(base, rel.n, "relaxed")).solve()) > 0
    return lower_bound(relaxed.program(ratio), relaxed.solve(ratio)) > 0


def _least_ratio_proven(base: Request, lo: float, hi: float, relaxed: _Programs | None = None) -> float:
    """The largest ratio in ``[lo, hi]`` at which :func:`_proven_above` holds, by bisection (``lo`` where it is
    known to hold, else 0): no law of the space has a smaller ratio of pressure angle to limit."""
    from laws.search import bisect_boundary

    return bisect_boundary(lambda r: _proven_above(base, r, relaxed), lo, hi, max_steps=BISECTION_STEPS)


def _down(x: float, digits: int = 6) -> str:
    """``x`` with ``digits`` significant digits, rounded down (a lower bound printed stays one)."""
    if x <= 0 or not np.isfinite(x):
        return f"{x:.{digits}g}"
    e = int(np.floor(np.log10(x))) - digits + 1
    q = np.floor(x / 10.0**e) * 10.0**e
    while q > x:
        q -= 10.0**e
    return f"{q:.{digits}g}"


def _no_law_at_size(base: Request) -> None:
    """Raise: no law of the space found meets the pressure-angle limits at the cam held (its size, or the chosen
    centre), said the same way by every objective, with the least ratio of pressure angle to limit proven.

    First a family infeasible on its own (the lift, a cap: :func:`_explain_caps`); then, when the relaxation
    proves that no law meets the limits, the least ratio proven (bisection up to every limit at 90 degrees);
    else that none was found and none is proven not to exist.

    Raises
    ------
    InputError, InfeasibleError
    """
    _explain_caps(base)
    where = ("at the chosen cam" if base.centre is not None or base.hold is None else
             f"at the cam size held (R0 = {base.hold:.10g} mm)")
    with_caps = " with the caps (each cap alone is feasible)" if base.caps else ""
    top = _top(base.limits)
    one = min(1.0, top)
    if not _proven_above(base, one):
        raise InfeasibleError("optimize", f"no law of the space found meets the pressure-angle limits at every cam "
                              f"angle {where}{with_caps}, and none is proven not to (the relaxation at samples "
                              "has laws that meet them): let the cam grow (objective 'R0'), choose a larger cam, or "
                              "add spans")
    if _proven_above(base, top):
        raise InfeasibleError("optimize", f"no law of the space meets the caps {where} with any pressure angle "
                              "below 90 degrees (each cap alone is feasible)")
    least = _least_ratio_proven(base, one, top)
    raise InfeasibleError("optimize", f"the pressure-angle limits admit no law of the space {where}{with_caps}: "
                          f"the least ratio of pressure angle to limit there is at least {_down(least)} (proven); "
                          "let the cam grow (objective 'R0') or choose a larger cam")


def _weights(terms: list[tuple[np.ndarray, np.ndarray, float]]) -> np.ndarray:
    """The pressure rows' weights at a point (``terms``, :func:`optimize.motion.translating.pressure_terms`, in
    the rows' order): each row's ``d + s`` there, floored at 1e-3 of the largest. Each row
    ``sign (s' + eps x) - T (d + s)`` divided by its weight is the normalized step of the generalized fractional
    programs' Dinkelbach method (Crouzeix, Ferland and Schaible, *J. Optim. Theory Appl.* 47, 1985). A
    positive weight per row changes no row's feasible set."""
    w = np.concatenate([np.concatenate([b, b]) for _, b, _ in terms])
    return np.maximum(w, 1e-3 * max(float(np.max(w, initial=0.0)), 1e-12))


def _still_possible(ratio: float, least: float, moved: np.ndarray, limits: np.ndarray, got: float) -> float:
    """How much further Dinkelbach's iteration could still lower the ratio ``got`` of the point a step found.

    The step solved the weighted program at ``ratio`` (weights ``w``, the rows' ``d + s`` at the step's start)
    and found the least slack ``least`` (``F <= 0``) at a point of ratio ``got``; ``moved`` is the rows'
    ``d + s`` at that point over ``w`` (both floored as :func:`_weights` floors them). For any point ``y`` of
    ratio ``rho`` below ``ratio``, each weighted row at ``ratio`` is at most
    ``-(T_i(ratio) - T_i(rho)) (d + s)_i(y) / w_i`` (``T_i(r) = tan(r limit_i)``), so ``F`` is at most that,
    and with ``m <= (d + s)_i(y) / w_i`` for every row (Crouzeix, Ferland and Schaible's bound)::

        rho >= min over the limits of arctan(tan(ratio limit) - |F| / m) / limit

    The least point ``y`` is not known: ``m`` is taken as ``1 - 2 delta`` with ``delta`` the largest relative
    change of ``d + s`` in the step just made (``moved``), the iteration's next change being smaller than its
    last (it converges superlinearly near the least). Returns ``got`` less that lower end (``inf`` when ``m``
    is not positive): an estimate, which bounds how much of the value a stop can leave, never the certificate's
    truth (the value is a point's own ratio, the lower bound proven apart).
    """
    m = 1.0 - 2.0 * float(np.max(np.abs(moved - 1.0)))
    if not m > 0:
        return float("inf")
    drop = max(-least, 0.0) / m
    low = min(float(np.arctan(max(np.tan(ratio * lim) - drop, 0.0))) / lim for lim in np.unique(limits))
    return got - low


def _descend(base: Request, programs: _Programs, ratio: float, v: np.ndarray | None, steps: int = MAX_DESCENT,
             relaxed: _Programs | None = None):
    """Dinkelbach's iteration from ``ratio`` (and the point ``v`` that meets it, if any): the feasibility
    program of ``programs``' form at the ratio of the last point found, its rows weighted at that point
    (:func:`_weights`), until the ratio decreases by less than :data:`RATIO_RTOL` (relative) or the program has
    no point with a smaller ratio, or, with ``relaxed`` given, until the decrease still possible
    (:func:`_still_possible`) is below :data:`RATIO_RTOL` of the ratio or :data:`GAP_SHARE` of the certificate's
    gap, the ratio less the lower end proven (:func:`_lower_end` with ``relaxed``, once the iteration has
    settled, :data:`SETTLED`): a step that could not change the certificate beyond its last digits is not taken.

    Returns ``(ratio, best, last, lower)``: the least ratio of the points found, the solution whose point has it
    (``None`` when none was found below ``ratio``; from no ``v``, when the program at ``ratio`` has no point
    with slack at most 0), ``(programs, ratio, weights, solution)`` of the last program solved and the lower
    end proven on the way (``None`` if none). Each step's point meets the rows at its own ratio
    (:func:`optimize.motion.translating.form_ratio`, computed on the point), so the ratio returned is a point's
    own (or, when the first point's is not below ``ratio`` from no ``v``, ``ratio`` itself, met to the solver's
    tolerance): an upper end of the program's least ratio.
    """
    form = programs.form
    best = None
    weights = None if v is None else _weights(pressure_terms(base, v, form))
    last = None
    lower = None
    limits = programs.rows.limit
    for _ in range(steps):
        sol = programs.solve(ratio, weights)
        last = (programs, ratio, weights, sol)
        if not sol.feasible or (best is None and v is None and sol.value > 0):
            break
        got = form_ratio(base, sol.v, form)
        if not got < ratio:
            if best is None and v is None:      # the start meets ``ratio`` to the solver's tolerance
                best = sol
            break
        done = got > ratio * (1 - RATIO_RTOL)
        at = _weights(pressure_terms(base, sol.v, form))
        if relaxed is not None and weights is not None:
            moved = at / weights
            left = _still_possible(ratio, float(sol.value), moved, limits, got)
            done = done or left <= RATIO_RTOL * got
            if not done and lower is None and np.max(np.abs(moved - 1.0)) <= SETTLED:
                lower = _lower_end(base, relaxed, got, sol.v)
            done = done or (lower is not None and left <= GAP_SHARE * (got - lower))
        ratio, best, weights = got, sol, at
        if done:
            break
    return ratio, best, last, lower


def _lower_end(base: Request, relaxed: _Programs, ratio: float, v: np.ndarray) -> float:
    """A ratio proven below every law's, from the conservative program's point ``v`` of ratio ``ratio``: the
    relaxed program's Dinkelbach step from there (:data:`RELAXED_STEPS`), then :func:`_proven_below`."""
    rel, rsol, last, _ = _descend(base, relaxed, ratio, v, RELAXED_STEPS)
    return _proven_below(base, rel, v if rsol is None else rsol.v, last)


def _proven_below(base: Request, ratio: float, v: np.ndarray, last) -> float:
    """A ratio proven to be below every law's: the relaxed program proven infeasible there, the proven lower
    bound of its least slack above 0 (weak duality, :func:`optimize.motion.conic.lower_bound`).

    ``ratio`` is the relaxed program's least found from above (:func:`_descend`, its point ``v``, ``last`` its
    last programs, ratio, weights and solution). The proof at a ratio ``r`` below it holds when the least slack
    there, about ``slope (ratio - r)``, exceeds what the bound loses to the solver's accuracy (the solver's
    value less the proven bound): the first ``r`` tried is ``ratio`` less :data:`PROOF_SAFETY` times the loss
    of ``last`` over the slope (the least ``limit sec^2(ratio limit)``: the weighted rows' derivative in the
    ratio); when the proof fails there, the next ``r`` is lower by what the slack still lacks, PROOF_SAFETY
    times the loss measured at that ``r`` less the least slack found there, over the slope (the distance at
    least 1.5 times the last; doubled when the solver gave no point there); the bisection
    (:func:`_least_ratio_proven`) between 0 and the last ratio tried (``ratio`` if none) when none is proven
    after :data:`PROOF_TRIES`, or when the next distance would reach 0.

    The loss is what the solver's residual costs at the box (:func:`optimize.motion.conic.lower_bound`): the
    programs hand the solver their variables over their boxes (:class:`_Programs`), so that it stays of the
    order of the solver's tolerance.
    """
    relaxed, at, w, sol = last
    weights = _weights(pressure_terms(base, v, "relaxed"))
    loss = max(float(sol.value) - lower_bound(relaxed.program(at, w), sol), 0.0) if sol.feasible else 0.0
    slope = min(lim / np.cos(ratio * lim) ** 2 for lim in base.limits.values())
    step = max(PROOF_SAFETY * loss / slope, RATIO_RTOL * ratio)
    r = ratio
    for _ in range(PROOF_TRIES):
        if ratio - step <= 0:
            break
        r = ratio - step
        tried = relaxed.solve(r, weights)
        bound = lower_bound(relaxed.program(r, weights), tried)
        if bound > 0:
            return r
        if not tried.feasible:      # no measure of the loss there (the solver's trouble): double the distance
            step *= 2
            continue
        lacks = PROOF_SAFETY * (float(tried.value) - bound) - float(tried.value)
        step = max(step + lacks / slope, 1.5 * step)
    return _least_ratio_proven(base, 0.0, r, relaxed)


def _least_pressure(base: Request, limits: dict[int, float]) -> tuple[Solution, float, _Programs]:
    """The least ratio of pressure angle to limit, at most 1, a proven lower bound of it and the conservative
    programs (the second stage's is one of them).

    Upper end: Dinkelbach's iteration (:func:`_descend`) on the conservative program from the limits
    themselves (ratio 1): each step's point meets every limit times its own ratio at every cam angle; it stops
    at the certificate's own gap (:data:`GAP_SHARE`). When no law found meets the limits themselves (ratio 1),
    :func:`_no_law_at_size` says so.
    Lower end (:func:`_lower_end`, proven during the iteration once it has settled, else from its end): the same
    iteration on the relaxed program from the conservative program's point, then that ratio less a margin
    proven infeasible (:func:`_proven_below`).
    """
    conservative = _Programs(base, "conservative")
    relaxed = _Programs(base, "relaxed")
    hi, feas, _, lb = _descend(base, conservative, min(1.0, _top(limits)), None, relaxed=relaxed)
    if feas is None:
        _no_law_at_size(base)
    if lb is None:
        lb = _lower_end(base, relaxed, hi, feas.v)
    return replace(feas, value=hi), lb, conservative
