"""Rows on the free laws' variables that every sequential convex model shares.

The laws' variables are :class:`optimize.motion.space.Space`'s (Bernstein
coefficients of each span's highest continuous derivative, with the start
values); a model appends its own variables after them (``n`` the total).
Here: the samples, the start (:func:`fit`), the caps and the follower within
its lift (:func:`cap_rows`), the trust region (:func:`trust_rows`), and the
objectives that hold the cam's size (:func:`held_objective`, :func:`held_value`).
"""

from __future__ import annotations

import numpy as np

from laws.errors import InfeasibleError, InputError
from optimize.motion.conic import Cone, ConicProgram, solve
from optimize.motion.space import Space
from optimize.motion.translating import S_MARGIN, SAMPLES_PER_SPAN, TIGHTEN

__all__ = ["HOLD_RTOL", "samples", "fit", "check_lift", "cap_rows", "trust_rows", "held_objective", "held_value",
           "within_caps", "stepped_laws"]

#: The held size is met within this (relative): the space's law nearest the original ones may need a cam
#: larger by the rounding of their fit (a size held at the original laws' least R0 is then that law's). A
#: designed cam larger than the size held by more is said so, and not certified (:mod:`cams.motion_design`).
HOLD_RTOL = 1e-8


def samples(space: Space) -> np.ndarray:
    """The positions u in [0, 1] where the models hold their sampled rows: SAMPLES_PER_SPAN a span."""
    return np.linspace(0.0, 1.0, (SAMPLES_PER_SPAN - 1) * space.spans + 1)


def fit(space: Space, caps: dict[tuple[int, int], float]) -> np.ndarray:
    """The space's law nearest the original laws (least squares at the samples), under the caps and joints.

    The least-squares law under the joints alone (a linear system) when it meets the caps; else the
    second-order cone program with the caps.
    """
    u = samples(space)
    n = space.size + 1
    F = np.vstack([space.rows(k, 0, n, samples=u) for k in range(len(space.free))])
    f = np.concatenate([-space.program.law_of(i).evaluate(u)[0] for i in space.free])
    A, b = space.equalities(n)
    G, h = cap_rows(space, caps, n)
    # min |F v + f|^2 subject to A v = b: the KKT system (t, the last variable, unused)
    m = space.size
    K = np.block([[F[:, :m].T @ F[:, :m], A[:, :m].T], [A[:, :m], np.zeros((A.shape[0], A.shape[0]))]])
    rhs = np.concatenate([-F[:, :m].T @ f, b])
    v = np.linalg.lstsq(K, rhs, rcond=None)[0][:m]
    if not G.shape[0] or np.all(G[:, :m] @ v <= h):
        return space.project(v)
    cost = np.zeros(n)
    cost[-1] = 1.0
    a = np.zeros(n)
    a[-1] = 1.0
    hi = np.concatenate([space.bounds(caps), [1e6]])
    lo = -hi
    lo[-1] = 0.0
    enforce = np.zeros(n, bool)
    enforce[-1] = True
    sol = solve(ConicProgram(cost, G, h, A, b, lo, hi, (Cone(a, 0.0, F, f),), enforce))
    if not sol.feasible:
        check_lift(space)
        raise InfeasibleError("optimize", "the caps admit no law of the space with the joints' conditions: raise "
                              "a cap or lower the continuity")
    return space.project(sol.v[:-1])


def check_lift(space: Space) -> None:
    """Refuse a space none of whose laws meets the ends and the joints with the follower within its lift as
    every program keeps it (``S`` within [0, 1], :data:`optimize.motion.translating.S_MARGIN` outside allowed,
    on the Bernstein coefficients of every piece of every span): a linear program on the space alone. The
    caller asks it once a program of the space is infeasible, before it blames the caps or the limits.

    Raises
    ------
    InputError
        Field ``"optimize"``: no law to search, whatever the cam, the limits and the caps.
    """
    n = space.size
    rows = np.vstack([space.rows(k, 0, n) for k in range(len(space.free))])
    G = np.vstack([rows, -rows])
    h = np.concatenate([np.full(rows.shape[0], 1 + S_MARGIN), np.full(rows.shape[0], S_MARGIN)])
    A, b = space.equalities(n)
    hi = space.bounds()
    if solve(ConicProgram(np.zeros(n), G, h, A, b, -hi, hi, (), np.zeros(n, bool))).feasible:
        return
    spans = space.spans
    raise InputError("optimize", f"the space (degree {space.degree}, continuity {space.continuity}, {spans} "
                     f"span{'s' if spans > 1 else ''} per free phase) holds no law that meets the joints' conditions "
                     f"and keeps the follower within its lift (S between 0 and 1 on the Bernstein coefficients of "
                     f"{space.pieces} pieces a span, as the programs keep it): a fixed neighbour meets a free phase "
                     "moving out of the lift, or the space is too narrow; free the neighbour, or raise the spans or "
                     "the degree")


def cap_rows(space: Space, caps: dict[tuple[int, int], float], n: int) -> tuple[np.ndarray, np.ndarray]:
    """The caps on every piece's Bernstein coefficients (tightened by TIGHTEN), and S within [0, 1] (the follower
    within its swing), over ``n`` variables."""
    G, h = [np.zeros((0, n))], [np.zeros(0)]
    for (k, r), cap in caps.items():
        rows = space.rows(k, r, n)
        G.append(np.vstack([rows, -rows]))
        h.append(np.full(2 * rows.shape[0], cap * (1 - TIGHTEN)))
    for k in range(len(space.free)):
        rows = space.rows(k, 0, n)
        G.append(np.vstack([rows, -rows]))
        h.append(np.concatenate([np.full(rows.shape[0], 1 + S_MARGIN), np.full(rows.shape[0], S_MARGIN)]))
    return np.vstack(G), np.concatenate(h)


def held_objective(space: Space, n: int, it: int, objective: str, G: list, h: list) -> tuple[Cone, ...]:
    """The objective's epigraph on ``t`` (variable ``it``): rows appended to ``G, h`` (a peak), or a cone (an
    integral's square root)."""
    if objective in ("Ca", "Cj"):
        r = 2 if objective == "Ca" else 3
        for k in range(len(space.free)):
            rows = space.rows(k, r, n)
            rows = np.vstack([rows, -rows])
            rows[:, it] = -1.0
            G.append(rows)
            h.append(np.zeros(rows.shape[0]))
        return ()
    r = 3 if objective == "jerk_squared" else 4
    F = np.vstack([space.integral_factor(k, r, n) for k in range(len(space.free))])
    a = np.zeros(n)
    a[it] = 1.0
    return (Cone(a, 0.0, F, np.zeros(F.shape[0])),)


def held_value(space: Space, v: np.ndarray, objective: str) -> float:
    """The value the held programs minimize at the laws ``v``: the largest Bernstein coefficient of the second
    or third derivative's magnitude on the pieces (a bound of its peak at every u), or the root of the integral
    of the third or fourth derivative's square."""
    n = space.size
    if objective in ("Ca", "Cj"):
        r = 2 if objective == "Ca" else 3
        return max(float(np.max(np.abs(space.rows(k, r, n) @ v))) for k in range(len(space.free)))
    r = 3 if objective == "jerk_squared" else 4
    return float(np.linalg.norm(np.vstack([space.integral_factor(k, r, n) for k in range(len(space.free))]) @ v))


def within_caps(caps_rows: tuple[np.ndarray, np.ndarray], v: np.ndarray) -> bool:
    """Whether the laws ``v`` meet :func:`cap_rows`'s rows, the caps and S within [0, 1], with the caps'
    tightening given back and 1e-12 (the solver may leave a row exceeded by its tolerance)."""
    G, h = caps_rows
    return not G.shape[0] or bool(np.all(G[:, :v.size] @ v <= h / (1 - TIGHTEN) + 1e-12))


def trust_rows(space: Space, vv: np.ndarray, u: np.ndarray, trust: float, top: int, G: list, h: list) -> None:
    """Append the trust region around the laws ``vv`` (padded to ``n``) to ``G, h``: ``S^(r)`` within
    ``4**r * trust`` of its value at the samples ``u``, for ``r = 0 .. top``."""
    n = vv.size
    for k in range(len(space.free)):
        for r in range(top + 1):
            width = 4.0**r * trust
            rows = space.rows(k, r, n, samples=u)
            now = rows @ vv
            G += [rows, -rows]
            h += [now + width, width - now]


def stepped_laws(space: Space, caps_rows: tuple[np.ndarray, np.ndarray], raw: np.ndarray, name: str):
    """A model's step as laws: its first ``space.size`` variables projected on the joints and their
    programme (named ``name``), or None when they exceed a cap (:func:`within_caps`)."""
    v = space.project(raw[:space.size])
    if not within_caps(caps_rows, v):
        return None
    return v, space.programme(v, name)
