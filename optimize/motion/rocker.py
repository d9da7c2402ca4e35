"""The rocker roller's motion design: sequential convex programming around the exact zone.

A rocker's constraint is not jointly convex in the law and the centre: the
sides of a position's wedge turn with the swing ``psi`` (``optimize.zone``,
``h = n(psi) . O - (b0 + b1 psi')``). Each iteration therefore

1. takes the current laws and sizes their cam by the exact method
   (:func:`optimize.sizing.size`: the least R0 or L over every cam angle,
   certified), which gives the centre ``O_k`` and the value ``f_k``;
2. linearizes every sampled side in the laws' variables and the centre at
   ``(v_k, O_k)`` (``dh = n . dO + dh/dpsi dpsi + dh/dpsi' dpsi'``,
   :func:`optimize.zone.side_terms`), keeps the fixed phases' sides exact
   (linear in ``O``), the caps on every span's Bernstein coefficients, the
   space's joints, and a trust region on ``S`` and ``S'`` at the samples;
3. solves that second-order cone program for a step, sizes the stepped laws'
   cam exactly, and accepts the step only when that exact value is smaller
   (the trust region grows after a good step and shrinks after a refused one).

Every accepted iterate is a cam sized exactly for its laws (feasible at every
cam angle); the last one is returned with its local-optimality measure
(:func:`optimize.motion.scp.stationarity`: the decrease the model predicts
within a small radius against none, relative; 0 at a first-order stationary
point). There is no gap: the problem is not convex.

The least pressure angle at the size held (:func:`design_rocker_pressure`)
is the same iteration on ``(laws, centre, t)``: every limit times ``t``, the
sides' rate in ``t`` by central differences, the centre within the held R0
(a cone), and the step's exact value the largest ratio of pressure angle to
limit at its centre (:func:`ratio_at`, 2,001 positions a phase: its centre
is the model's, not a sizing's; the cam returned is checked by the
independent check like any other). The ratio is the pressure angle's own
(the wedges with K_C = 1); a K_C above 1 keeps its stricter zone at the
limits themselves as a further constraint (:data:`ZONE_MARGIN` inside it at
the samples).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from cams.model.design import CamDesign
from laws.errors import InfeasibleError
from laws.program import Program
from optimize.motion.conic import Cone, ConicProgram
from optimize.motion.lawrows import (
    HOLD_RTOL,
    cap_rows,
    fit,
    held_objective,
    held_value,
    samples,
    stepped_laws,
    trust_rows,
)
from optimize.motion.scp import Iterate, Outcome, minimize, solved
from optimize.motion.space import Space
from optimize.motion.translating import FIXED_SAMPLES
from optimize.zone import side_terms, wedges

__all__ = ["RockerSteps", "design_rocker", "design_rocker_held", "design_rocker_pressure", "ratio_at", "held_size",
           "steps_of"]



@dataclass(frozen=True)
class RockerSteps:
    """The SCP's result.

    Attributes
    ----------
    v : ndarray
        The laws' variables of the last accepted iterate (projected on the space's equalities).
    program : Program
        Its programme.
    value : float
        The exact value of the objective minimized: R0 or L (length), the held objective's
        (:func:`held_value`: a peak's bound, or the root of an integral), or the pressure-angle ratio.
    centre : ndarray, shape (2,)
        Its cam centre (fixed frame); a flat-faced rocker's ``(R0, 0)``.
    iterations : int
        All the iterations, a held objective's first loop (the least R0) included.
    local_measure : float
        :func:`optimize.motion.scp.stationarity` at the result.
    history : tuple of float
        The last loop's exact value after each accepted step, its start first.
    """

    v: np.ndarray
    program: Program
    value: float
    centre: np.ndarray
    iterations: int
    local_measure: float
    history: tuple[float, ...]


def _sized_step(design: CamDesign, space: Space, caps_rows, raw: np.ndarray, name: str, objective: str):
    """A model's step as laws (:func:`optimize.motion.lawrows.stepped_laws`) and their cam sized exactly:
    ``(v, programme, value, centre)``, or None when a cap is exceeded or the laws have no cam."""
    stepped = stepped_laws(space, caps_rows, raw, name)
    if stepped is None:
        return None
    try:
        return (*stepped, *_sized(design, stepped[1], objective))
    except InfeasibleError:
        return None


def _sized(design: CamDesign, program: Program, objective: str) -> tuple[float, np.ndarray]:
    """The exact value and centre of the cam of ``program`` (InfeasibleError when it has no cam)."""
    from optimize.sizing import size

    d = design.with_(program=program)
    sol = size(d, method="exact", objective=objective if design.limits.centre_distance is None else "R0")
    c = np.asarray(sol.centre, float)
    if objective == "L" and design.limits.centre_distance is None:
        return float(np.linalg.norm(c)), c
    return float(np.linalg.norm(c - design.follower.position(0.0))), c


def _step_program(design: CamDesign, space: Space, caps, v: np.ndarray, centre: np.ndarray, trust: float,
                  objective: str, hold: float | None = None, ratio: float | None = None) -> ConicProgram:
    """The linearized program at ``(v, centre)`` with trust radius ``trust`` (module notes, step 2).

    Lengths in units of the design's scale (the arm): the centre's variables are ``O / scale`` and the value
    ``R0 / scale`` or ``L / scale``, so the program does not depend on the design's unit. For the objectives
    that hold the cam's size (``"Ca"``, ``"Cj"``, ``"jerk_squared"``, ``"snap_squared"``), ``hold`` is the R0
    the centre must stay within and the value is :func:`held_value`'s. For ``"pressure_angle"``, ``ratio``
    is the current ratio ``t_k``: the limits are the design's times the variable ``t`` (the value), linearized
    in ``t`` too (central differences of the sides in the limit), and the centre stays within ``hold``.
    """
    ell = design.scale
    nc = space.size
    n = nc + 3
    io, it = nc, nc + 2
    u = samples(space)
    vv = np.concatenate([v, np.zeros(3)])
    G: list[np.ndarray] = []
    h: list[np.ndarray] = []
    if ratio is None:
        _side_rows(design, space, vv, centre, u, None, G, h)
    else:
        # the pressure angle's own wedges (K_C = 1) at the limits times t; K_C's zone at the limits themselves
        pure = design.with_(limits=replace(design.limits, safety_factor=1.0))
        _side_rows(pure, space, vv, centre, u, ratio, G, h)
        if design.limits.safety_factor != 1.0:
            _side_rows(design, space, vv, centre, u, None, G, h, margin=ZONE_MARGIN)
    Gc, hc = cap_rows(space, caps, n)
    G.append(Gc)
    h.append(hc)
    trust_rows(space, vv, u, trust, 1, G, h)
    A, b = space.equalities(n)
    L = design.limits.centre_distance
    if L is not None:    # O on the circle |O| = L, linearized: its tangent at O_k
        row = np.zeros((1, n))
        row[0, io:io + 2] = centre / np.linalg.norm(centre)
        A, b = np.vstack([A, row]), np.concatenate([b, [L / ell]])
    cost = np.zeros(n)
    cost[it] = 1.0
    a = np.zeros(n)
    a[it] = 1.0
    F = np.zeros((2, n))
    F[0, io], F[1, io + 1] = 1.0, 1.0
    A0 = design.follower.position(0.0)
    if objective in ("R0", "L"):
        target = np.zeros(2) if (objective == "L" and L is None) else A0
        cones: tuple[Cone, ...] = (Cone(a, 0.0, F, -target / ell),)
    elif objective == "pressure_angle":
        if hold is None or ratio is None:
            raise ValueError("the least pressure angle needs the size held and the current ratio")
        cones = (Cone(np.zeros(n), hold / ell, F, -A0 / ell),)
    else:
        if hold is None:
            raise ValueError(f"objective {objective!r} needs the size held")
        cones = (Cone(np.zeros(n), hold / ell, F, -A0 / ell), *held_objective(space, n, it, objective, G, h))
    scale = 1.0 + float(np.linalg.norm(centre)) / ell
    top = 100 * scale if objective in ("R0", "L") else 1e6
    if objective == "pressure_angle":
        top = _top_ratio(design)
    hi = np.concatenate([space.bounds(caps), [100 * scale] * 2, [top]])
    lo = -hi
    lo[it] = 0.0
    enforce = np.zeros(n, bool)
    enforce[nc:] = True
    return ConicProgram(cost, np.vstack(G), np.concatenate(h), A, b, lo, hi, cones, enforce)


#: How far inside K_C's sampled sides the least pressure angle's model keeps the centre (units of the scale):
#: more than the sides bulge between the samples, so that the iterate passes :func:`_zone_admits`.
ZONE_MARGIN = 1e-4
#: The step in the ratio of the central differences of the sides.
RATE_STEP = 1e-6


def _times(design: CamDesign, ratio: float):
    """``design``'s limits with every pressure-angle limit multiplied by ``ratio`` (K_C, L, floors unchanged)."""
    lim = design.limits
    ret = None if lim.return_pressure_angle is None else lim.return_pressure_angle * ratio
    return replace(lim, pressure_angle=lim.pressure_angle * ratio, return_pressure_angle=ret)


def _rate_points(design: CamDesign, tk: float) -> tuple[float, float]:
    """The ratios of the sides' differences around ``tk``: ``tk +- RATE_STEP``, the upper one kept below
    :func:`_top_ratio` (every limit below 90 degrees)."""
    return min(tk + RATE_STEP, _top_ratio(design)), tk - RATE_STEP


def _top_ratio(design: CamDesign) -> float:
    """The largest ratio that keeps every limit below 90 degrees."""
    return (np.pi / 2) / max(lim for _, lim in design.constrained_phases()) * (1 - 1e-9)


#: Positions a phase at which :func:`ratio_at` evaluates the wedges.
RATIO_SAMPLES = 2001


def ratio_at(design: CamDesign, program: Program, centre: np.ndarray) -> float:
    """The largest ratio of pressure angle to its limit of the cam of ``program`` centred at ``centre``: the
    least ``t`` for which ``centre`` lies in every wedge of the limited phases with the limits times ``t``
    (K_C = 1: the pressure angle's own wedges). Bisection to 1e-12 on :data:`RATIO_SAMPLES` positions a phase;
    ``inf`` when no limit below 90 degrees admits the centre.
    """
    d = design.with_(program=program, limits=replace(design.limits, safety_factor=1.0))
    limited = d.constrained_phases()
    u = np.linspace(0.0, 1.0, RATIO_SAMPLES)
    motion = {i: program.evaluate_phase(i, u) for i, _ in limited}
    O = np.asarray(centre, float)

    def admits(t: float) -> bool:
        return all(float(np.max(side_terms(d, lim * t, motion[i].s, motion[i].ds, O)[0])) <= 0.0
                   for i, lim in limited)

    lo, hi = 0.0, _top_ratio(design)
    if not admits(hi):
        return np.inf
    while hi - lo > 1e-12 * hi:
        mid = 0.5 * (lo + hi)
        if admits(mid):
            hi = mid
        else:
            lo = mid
    return float(hi)


def _side_rows(design: CamDesign, space: Space, vv: np.ndarray, centre: np.ndarray, u: np.ndarray,
               ratio: float | None, G: list, h: list, margin: float = 0.0) -> None:
    """Append to ``G, h`` the rows of every limited phase's wedge sides at the samples ``u`` (a free phase's
    linearized at the laws ``vv`` and ``centre``, a fixed phase's exact in the centre, at FIXED_SAMPLES positions).

    Variables as :func:`_step_program`'s (``vv`` padded with its three: the centre over the scale, then the
    value). With ``ratio`` (the current ``t_k``), the limits are the design's times the value ``t``,
    linearized in it by central differences of the sides. ``margin`` (units of the scale) keeps the centre
    that far inside every sampled side.
    """
    ell = design.scale
    n = vv.size
    io, it = n - 3, n - 1
    index = {i: k for k, i in enumerate(space.free)}
    tk = 1.0 if ratio is None else ratio
    limits = {i: lim * tk for i, lim in design.constrained_phases()}
    fixed = {i: np.linspace(0.0, 1.0, FIXED_SAMPLES) for i in limits if i not in index}
    if fixed:
        N, c = wedges(design.with_(limits=_times(design, tk)), fixed).lines()
        rows = np.zeros((N.shape[0], n))
        rows[:, io:io + 2] = N
        rhs = c / ell
        if ratio is not None:   # h = N(t) . O - c(t), its rate in t by differences
            t_up, t_down = _rate_points(design, tk)
            up, down = (wedges(design.with_(limits=_times(design, t)), fixed).lines() for t in (t_up, t_down))
            ht = ((up[0] - down[0]) @ centre - (up[1] - down[1])) / (t_up - t_down)
            rows[:, it] = ht / ell
            rhs = rhs + ht * tk / ell
        G.append(rows)
        h.append(rhs - margin)
    for i, k in index.items():
        if i not in limits:
            continue
        sh, beta, lev = space.phase_scale(i)
        r0 = space.rows(k, 0, n, samples=u)
        r1 = space.rows(k, 1, n, samples=u)
        s = lev + sh * (r0 @ vv)
        ds = sh / beta * (r1 @ vv)
        hk, hs, hd, normals = side_terms(design, limits[i], s, ds, centre)
        if ratio is not None:
            lim = limits[i] / tk
            t_up, t_down = _rate_points(design, tk)
            ht = (side_terms(design, lim * t_up, s, ds, centre)[0]
                  - side_terms(design, lim * t_down, s, ds, centre)[0]) / (t_up - t_down)
        for side in (0, 1):
            nrm = normals[:, side]
            # h ~ h_k + n . (O - O_k) + dh/ds (s - s_k) + dh/ds' (s' - s'_k) [+ dh/dt (t - t_k)] <= 0
            rows = (hs[:, side, None] * sh / ell) * r0 + (hd[:, side, None] * sh / (beta * ell)) * r1
            rows[:, io:io + 2] = nrm
            rhs = (-hk[:, side] + nrm @ centre + hs[:, side] * (s - lev) + hd[:, side] * ds) / ell
            if ratio is not None:
                rows[:, it] = ht[:, side] / ell
                rhs = rhs + ht[:, side] * tk / ell
            G.append(rows)
            h.append(rhs - margin)


def _zone_admits(design: CamDesign, program: Program, centre: np.ndarray) -> bool:
    """Whether ``centre`` lies in every wedge of ``program``'s limited phases at the design's limits with its
    K_C (:data:`RATIO_SAMPLES` positions a phase, to 1e-9 of the scale); True when K_C = 1 (nothing more than
    the pressure angle)."""
    if design.limits.safety_factor == 1.0:
        return True
    d = design.with_(program=program)
    u = np.linspace(0.0, 1.0, RATIO_SAMPLES)
    worst = max(float(np.max(wedges(d, {i: u}).violation(centre))) for i, _ in d.constrained_phases())
    return worst <= 1e-9 * design.scale


def held_size(least: float, hold: float, caps: dict) -> float:
    """The size a held objective's iteration keeps: ``hold``, or ``least`` (the space's least R0 found, length)
    when it exceeds ``hold`` by at most :data:`HOLD_RTOL` (the facade notes it).

    Raises
    ------
    InfeasibleError
        ``least`` exceeds ``hold`` by more: the space's laws (under the caps) cannot keep the size held.
    """
    if least <= hold * (1 + HOLD_RTOL):
        return max(hold, least)
    advice = "raise a cap, add spans or minimize R0" if caps else "add spans or minimize R0"
    raise InfeasibleError("optimize", f"no law of the space found keeps the cam within the size held (R0 <= "
                          f"{hold:.10g} mm; the least found is {least:.10g} mm): {advice}")


def steps_of(out: Outcome, before: RockerSteps | None = None, flat: bool = False) -> RockerSteps:
    """The :class:`RockerSteps` of a loop's outcome, its iterates' state ``(programme, centre)`` (a flat face's
    ``(programme, R0)``); the iterations of ``before`` (a first loop) added."""
    b = out.best
    program, where = b.state
    centre = np.array([where, 0.0]) if flat else np.asarray(where, float)
    return RockerSteps(v=b.v, program=program, value=b.value, centre=centre,
                       iterations=out.iterations + (before.iterations if before else 0),
                       local_measure=out.local_measure, history=out.history)


def design_rocker(design: CamDesign, space: Space, caps: dict[tuple[int, int], float], objective: str,
                  name: str, start: np.ndarray | None = None, measure: bool = True) -> RockerSteps:
    """The SCP of the module notes for ``design`` (a rocker roller), minimizing ``objective`` (``"R0"``/``"L"``).

    ``start``: the laws' variables to start from (default: the space's law nearest the original laws,
    :func:`optimize.motion.lawrows.fit`), projected on the joints; the caller sees that they meet the caps.
    ``measure``: compute the local-optimality measure (:func:`optimize.motion.scp.minimize`).

    Raises
    ------
    InfeasibleError
        The caps admit no law of the space, or the starting law has no cam.
    """
    if not space.free:           # nothing to design: the laws' own cam, sized exactly
        value, centre = _sized(design, space.program, objective)
        return RockerSteps(v=np.zeros(0), program=space.program, value=value, centre=centre, iterations=0,
                           local_measure=0.0, history=(value,))
    v = fit(space, caps) if start is None else space.project(np.asarray(start, float))
    caps_rows = cap_rows(space, caps, space.size)
    program = space.programme(v, name)
    value, centre = _sized(design, program, objective)

    def model(it: Iterate, trust: float) -> tuple[float, np.ndarray] | None:
        step = solved(_step_program(design, space, caps, it.v, it.state[1], trust, objective), space.size + 3)
        return None if step is None else (step[0] * design.scale, step[1])

    def exact(raw: np.ndarray) -> Iterate | None:
        step = _sized_step(design, space, caps_rows, raw, name, objective)
        return None if step is None else Iterate(step[0], step[2], (step[1], step[3]))

    return steps_of(minimize(Iterate(v, value, (program, centre)), model, exact, measure=measure))


def design_rocker_held(design: CamDesign, space: Space, caps: dict[tuple[int, int], float], objective: str,
                       hold: float, name: str) -> RockerSteps:
    """The laws of least ``objective`` (``"Ca"``, ``"Cj"``, ``"jerk_squared"``, ``"snap_squared"``) whose cam
    has an R0 at most ``hold`` (length): the cam's size held, its centre free to move within it.

    First the least R0 (:func:`design_rocker`), which must come within ``hold``; then the same sequential
    convex programming on the objective, each step's laws sized by the exact method and kept only when that R0
    is within ``hold`` and the objective is smaller. ``value`` is the objective's (:func:`held_value`).

    Raises
    ------
    InfeasibleError
        No law of the space found keeps the cam within ``hold`` under the caps.
    """
    first = design_rocker(design, space, caps, "R0", name, measure=False)
    if not space.free:
        return first
    hold = held_size(first.value, hold, caps)
    caps_rows = cap_rows(space, caps, space.size)

    def model(it: Iterate, trust: float) -> tuple[float, np.ndarray] | None:
        return solved(_step_program(design, space, caps, it.v, it.state[1], trust, objective, hold),
                       space.size + 3)

    def exact(raw: np.ndarray) -> Iterate | None:
        step = _sized_step(design, space, caps_rows, raw, name, "R0")
        if step is None or step[2] > hold:
            return None
        return Iterate(step[0], held_value(space, step[0], objective), (step[1], step[3]))

    start = Iterate(first.v, held_value(space, first.v, objective), (first.program, first.centre))
    return steps_of(minimize(start, model, exact), first)


def design_rocker_pressure(design: CamDesign, space: Space, caps: dict[tuple[int, int], float], hold: float,
                           name: str) -> RockerSteps:
    """The laws and cam centre of least pressure-angle ratio whose cam fits within ``hold`` (R0, length).

    First the least R0 (:func:`design_rocker`), which must come within ``hold``; from its laws and centre, the
    same sequential convex programming on ``(laws, centre, t)``: the limits times ``t``, the sides linearized
    in the laws, the centre and ``t`` (:func:`_step_program`), the centre within ``hold`` of the roller's
    start (exact: a cone). A step is kept when its centre fits within ``hold`` (a fixed L: the centre put back
    on its circle first), K_C's zone admits it (:func:`_zone_admits`) and its ratio, :func:`ratio_at` at that
    centre, is smaller. ``value`` is that ratio; the centre is the last accepted step's.

    Raises
    ------
    InfeasibleError
        No law of the space found keeps the cam within ``hold`` at the pressure-angle limits.
    """
    first = design_rocker(design, space, caps, "R0", name, measure=False)
    start = Iterate(first.v, ratio_at(design, first.program, first.centre), (first.program, first.centre))
    if not space.free:          # nothing to design: the laws' own least cam and its ratio
        return replace(first, value=start.value, history=(start.value,))
    hold = held_size(first.value, hold, caps)
    A0 = design.follower.position(0.0)
    L = design.limits.centre_distance
    caps_rows = cap_rows(space, caps, space.size)

    def model(it: Iterate, trust: float) -> tuple[float, np.ndarray] | None:
        return solved(_step_program(design, space, caps, it.v, it.state[1], trust, "pressure_angle", hold,
                                     it.value), space.size + 3)

    def exact(raw: np.ndarray) -> Iterate | None:
        centre_new = raw[space.size:space.size + 2] * design.scale
        if L is not None:
            centre_new = centre_new * (L / np.linalg.norm(centre_new))
        out = np.linalg.norm(centre_new - A0)
        if hold < out <= hold * (1 + 1e-6):     # the solver's tolerance on the cone: back onto the circle
            centre_new = A0 + (centre_new - A0) * (hold / out)
        stepped = stepped_laws(space, caps_rows, raw, name)
        if stepped is None or np.linalg.norm(centre_new - A0) > hold:
            return None
        v_new, program_new = stepped
        if not _zone_admits(design, program_new, centre_new):
            return None
        return Iterate(v_new, ratio_at(design, program_new, centre_new), (program_new, centre_new))

    return steps_of(minimize(start, model, exact), first)
