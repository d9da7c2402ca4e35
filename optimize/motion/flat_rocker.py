"""The flat-faced rocker's motion design: sequential convex programming on its envelope's convexity.

A flat face's cam is sized by convexity (:mod:`optimize.flat`): its radius of
curvature ``rho = p + p_thetatheta`` (:mod:`cams.kinematics.flat`) must stay at
least ``min_radius`` at every cam angle. For a rocker, ``rho`` depends on the
swing ``psi``, its rates ``psi'`` and ``psi''`` and on R0 (through the face's
angle at the near dwell, ``cos a0 = (f - R0) / L``) nonlinearly, and it is not
concave in them: the problem is not convex. Each iteration of
:func:`optimize.motion.scp.minimize` therefore

1. linearizes ``rho`` at the samples of every free phase in the laws'
   variables and R0 (central differences in ``psi, psi', psi''`` and R0; the
   fixed phases' and the dwells' ``rho`` in R0 alone), keeps the caps, the
   joints and a trust region on ``S, S', S''`` (R0 is free in its range, as
   a rocker roller's centre is: with the laws held, the model is the sampled
   sizing);
2. solves that linear program for a step, and
3. sizes the stepped laws' cam by the exact method
   (:func:`optimize.flat.min_base_radius_oscillating`: the least R0 with
   ``rho >= min_radius`` at every cam angle), keeping the step when it is
   smaller.

The objectives that hold the cam's size (``Ca``, ``Cj``, ``jerk_squared``,
``snap_squared``) fix R0 at the size held and keep a step only when the cam of
its laws at that R0 is convex enough everywhere (:func:`optimize.flat`'s
refined minimum of ``rho``). Lengths in units of the centre distance L inside
the programs, the design's unit outside; angles in radians.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from cams.kinematics.flat import curvature_radius, flat_parts, near_dwell_angle, oscillating_support, phase_minimum
from cams.model.design import FlatFaceDesign
from cams.model.follower import FlatRocker
from laws.errors import InfeasibleError, InputError
from laws.program import Program
from optimize.motion.conic import ConicProgram
from optimize.motion.lawrows import (
    cap_rows,
    fit,
    held_objective,
    held_value,
    samples,
    stepped_laws,
    trust_rows,
)
from optimize.motion.rocker import RockerSteps, held_size, steps_of
from optimize.motion.scp import Iterate, minimize, solved
from optimize.motion.space import Space
from optimize.motion.translating import FIXED_SAMPLES

__all__ = ["design_flat_rocker", "design_flat_rocker_held", "curvature_rates"]

#: Central-difference steps of ``rho``'s rates: in the swing and its rates (radians), and in R0 (times L).
STEP = 1e-6


def _follower(design: FlatFaceDesign) -> FlatRocker:
    fo = design.follower
    if not isinstance(fo, FlatRocker):
        raise TypeError("a flat-faced rocker's design is needed")
    return fo


def _rho(design: FlatFaceDesign, R0, s, ds, d2s) -> np.ndarray:
    """The radius of curvature (length) at swing ``s`` and its rates, for base radius ``R0``."""
    fo = _follower(design)
    L, f, sigma = fo.centre_distance, fo.face_offset, fo.sense
    a0 = near_dwell_angle(L, f, R0, sigma)
    _, dth, d2th, p, dp, d2p = oscillating_support(L, f, sigma, design.cam_sense, a0, s, ds, d2s)
    with np.errstate(divide="ignore", invalid="ignore"):
        return curvature_radius(dth, d2th, p, dp, d2p)


def curvature_rates(design: FlatFaceDesign, R0: float, s, ds, d2s) -> tuple[np.ndarray, ...]:
    """``rho`` and its rates in ``s``, ``s'``, ``s''`` (per radian) and ``R0`` (per length), central differences.

    Parameters
    ----------
    design : FlatFaceDesign
        A flat-faced rocker's.
    R0 : float
        Base radius, length.
    s, ds, d2s : ndarray
        Swing (radians) and its first two rates in the cam angle.
    """
    s, ds, d2s = (np.asarray(x, float) for x in (s, ds, d2s))
    rho = _rho(design, R0, s, ds, d2s)
    e = STEP
    dR = STEP * _follower(design).centre_distance
    g_s = (_rho(design, R0, s + e, ds, d2s) - _rho(design, R0, s - e, ds, d2s)) / (2 * e)
    g_d = (_rho(design, R0, s, ds + e, d2s) - _rho(design, R0, s, ds - e, d2s)) / (2 * e)
    g_dd = (_rho(design, R0, s, ds, d2s + e) - _rho(design, R0, s, ds, d2s - e)) / (2 * e)
    g_R = (_rho(design, R0 + dR, s, ds, d2s) - _rho(design, R0 - dR, s, ds, d2s)) / (2 * dR)
    return rho, g_s, g_d, g_dd, g_R


def _range(design: FlatFaceDesign) -> tuple[float, float]:
    """The base radii the face can touch (length): ``(max(f - L, 0), f + L cos(swing))``, open."""
    fo = _follower(design)
    L, f = fo.centre_distance, fo.face_offset
    return max(f - L, 0.0), f + L * float(np.cos(design.program.lift))


def _sized(design: FlatFaceDesign, program: Program) -> float:
    """The least R0 of the cam of ``program`` (exact sizing; InfeasibleError when no R0 is convex enough)."""
    from optimize.flat import min_base_radius_oscillating

    fo = _follower(design)
    try:
        R0, _ = min_base_radius_oscillating(program, centre_distance=fo.centre_distance,
                                            face_offset=fo.face_offset, rise_sense=fo.sense,
                                            cam_sense=design.cam_sense, min_radius=design.min_radius)
    except InputError as e:
        raise InfeasibleError("optimize", str(e)) from None
    return float(R0)


def _convex_at(design: FlatFaceDesign, program: Program, R0: float) -> bool:
    """Whether the cam of ``program`` at base radius ``R0`` keeps ``rho >= min_radius`` everywhere (the
    sizing's refined minimum over every phase)."""
    try:
        rho = flat_parts(replace(design, program=program), R0)[0]
    except InputError:
        return False
    return phase_minimum(rho, program)[0] >= design.min_radius


def _step_program(design: FlatFaceDesign, space: Space, caps, v: np.ndarray, R0: float, trust: float,
                  objective: str, hold: float | None = None) -> ConicProgram:
    """The linearized program at the laws ``v`` and base radius ``R0`` (module notes, step 1).

    Variables: the laws', then ``r = R0 / L`` and the held objective's epigraph ``t``. ``"R0"`` minimizes ``r``
    (``t`` fixed at 0); the held objectives fix ``r`` at ``hold / L`` and minimize ``t``.
    """
    ell = _follower(design).centre_distance
    nc = space.size
    n = nc + 2
    ir, it = nc, nc + 1
    u = samples(space)
    vv = np.concatenate([v, np.zeros(2)])
    rk = R0 / ell
    rmin = design.min_radius
    G: list[np.ndarray] = []
    h: list[np.ndarray] = []
    index = {i: k for k, i in enumerate(space.free)}
    program = space.program

    def hold_rho(rho: np.ndarray, g_R: np.ndarray, row_v: np.ndarray | None, now: np.ndarray | None) -> None:
        # rho + row_v (v - v_k) + g_R L (r - r_k) >= rmin, divided by L
        rows = np.zeros((rho.size, n)) if row_v is None else -row_v
        rows[:, ir] = -g_R
        rhs = (rho - rmin) / ell - g_R * rk - (0.0 if now is None else now / ell)
        G.append(rows)
        h.append(rhs)

    for i, phase in enumerate(program.phases):
        if phase.kind == "dwell":
            continue
        if i in index:
            k = index[i]
            sh, beta, lev = space.phase_scale(i)
            r0, r1, r2 = (space.rows(k, r, n, samples=u) for r in (0, 1, 2))
            s = lev + sh * (r0 @ vv)
            ds = sh / beta * (r1 @ vv)
            d2s = sh / beta**2 * (r2 @ vv)
            rho, g_s, g_d, g_dd, g_R = curvature_rates(design, R0, s, ds, d2s)
            row_v = ((g_s * sh)[:, None] * r0 + (g_d * sh / beta)[:, None] * r1
                     + (g_dd * sh / beta**2)[:, None] * r2)
            hold_rho(rho, g_R, row_v / ell, row_v @ vv)
        else:
            m = program.evaluate_phase(i, np.linspace(0.0, 1.0, FIXED_SAMPLES))
            rho, _, _, _, g_R = curvature_rates(design, R0, m.s, m.ds, m.d2s)
            hold_rho(rho, g_R, None, None)
    levels = np.unique(program.levels)            # the dwells' arcs: rho = p at each level
    rho, _, _, _, g_R = curvature_rates(design, R0, levels, 0 * levels, 0 * levels)
    hold_rho(rho, g_R, None, None)
    Gc, hc = cap_rows(space, caps, n)
    G.append(Gc)
    h.append(hc)
    trust_rows(space, vv, u, trust, 2, G, h)
    A, b = space.equalities(n)
    cost = np.zeros(n)
    lo_R, hi_R = _range(design)
    hi = np.concatenate([space.bounds(caps), [0.0, 0.0]])
    lo = -hi
    if objective == "R0":
        cost[ir] = 1.0
        lo[ir] = lo_R / ell
        hi[ir] = hi_R / ell * (1 - 1e-9)
        cones: tuple = ()
    else:
        if hold is None:
            raise ValueError(f"objective {objective!r} needs the size held")
        cost[it] = 1.0
        lo[ir] = hi[ir] = hold / ell
        hi[it] = 1e6
        cones = held_objective(space, n, it, objective, G, h)
    enforce = np.zeros(n, bool)
    enforce[nc:] = True
    return ConicProgram(cost, np.vstack(G), np.concatenate(h), A, b, lo, hi, cones, enforce)


def design_flat_rocker(design: FlatFaceDesign, space: Space, caps: dict[tuple[int, int], float],
                       name: str, measure: bool = True) -> RockerSteps:
    """The laws of least R0 of a flat-faced rocker's cam (module notes); ``centre`` holds ``(R0, 0)``.
    ``measure``: compute the local-optimality measure (:func:`optimize.motion.scp.minimize`).

    Raises
    ------
    InfeasibleError
        The caps admit no law of the space, or the starting laws have no convex enough cam.
    """
    if not space.free:
        R0 = _sized(design, space.program)
        return RockerSteps(v=np.zeros(0), program=space.program, value=R0, centre=np.array([R0, 0.0]),
                           iterations=0, local_measure=0.0, history=(R0,))
    ell = _follower(design).centre_distance
    v = fit(space, caps)
    caps_ = cap_rows(space, caps, space.size)
    program = space.programme(v, name)
    R0 = _sized(design, program)
    start = Iterate(v, R0, (program, R0))

    def model(it: Iterate, trust: float) -> tuple[float, np.ndarray] | None:
        step = solved(_step_program(design, space, caps, it.v, it.state[1], trust, "R0"), space.size + 2)
        return None if step is None else (step[0] * ell, step[1])

    def exact(raw: np.ndarray) -> Iterate | None:
        stepped = stepped_laws(space, caps_, raw, name)
        if stepped is None:
            return None
        v_new, program_new = stepped
        try:
            R0 = _sized(design, program_new)
        except InfeasibleError:
            return None
        return Iterate(v_new, R0, (program_new, R0))

    return steps_of(minimize(start, model, exact, measure=measure), flat=True)


def design_flat_rocker_held(design: FlatFaceDesign, space: Space, caps: dict[tuple[int, int], float],
                            objective: str, hold: float, name: str) -> RockerSteps:
    """The laws of least ``objective`` (``"Ca"``, ``"Cj"``, ``"jerk_squared"``, ``"snap_squared"``) whose cam
    is convex enough at R0 = ``hold`` (length); ``centre`` holds ``(hold, 0)``.

    First the least R0 (:func:`design_flat_rocker`), whose laws must be convex enough at ``hold``; then the
    same sequential convex programming on the objective with R0 fixed at ``hold``, a step kept only when its
    cam at ``hold`` is convex enough everywhere and the objective smaller.

    Raises
    ------
    InfeasibleError
        No law of the space found is convex enough at ``hold`` under the caps.
    """
    first = design_flat_rocker(design, space, caps, name, measure=False)
    if not space.free:
        return first
    hold = held_size(first.value, hold, caps)
    if not _convex_at(design, first.program, hold):
        raise InfeasibleError("optimize", f"the least-R0 laws found are not convex enough at the size held (R0 = "
                              f"{hold:.10g} mm) though they are at {first.value:.10g} mm: minimize R0")
    caps_ = cap_rows(space, caps, space.size)

    def model(it: Iterate, trust: float) -> tuple[float, np.ndarray] | None:
        return solved(_step_program(design, space, caps, it.v, hold, trust, objective, hold), space.size + 2)

    def exact(raw: np.ndarray) -> Iterate | None:
        stepped = stepped_laws(space, caps_, raw, name)
        if stepped is None:
            return None
        v_new, program_new = stepped
        if not _convex_at(design, program_new, hold):
            return None
        return Iterate(v_new, held_value(space, v_new, objective), (program_new, hold))

    start = Iterate(first.v, held_value(space, first.v, objective), (first.program, hold))
    return steps_of(minimize(start, model, exact), first, flat=True)
