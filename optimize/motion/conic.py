"""A convex program in one standard form, solved by cvxpy, and its proven lower bound.

The form::

    minimize    cost @ v
    subject to  G @ v <= h                       (linear inequalities)
                A @ v == b                       (linear equalities)
                a_k @ v + a0_k >= || F_k @ v + f_k ||   (second-order cones)
                lo <= v <= hi                    (a finite box: part of the space)

The box is declared, not all of it is handed to the solver (a box far wider
than the solution only slows an interior-point method): the solver sees the
bounds that ``enforce`` marks (fixed variables, a centre's side); the lower
bound holds over the whole box all the same.

The solver (Clarabel, through cvxpy) returns multipliers that satisfy the
optimality conditions only to its tolerance, so its objective value is not a
bound. :func:`lower_bound` turns any multipliers into a proven one by weak
duality: with ``lam >= 0`` and ``(mu0, mu)`` in the (self-dual) cone, for every
feasible ``v``::

    cost @ v >= L(v) = cost @ v + lam @ (G v - h) + nu @ (A v - b)
                       - sum_k (mu0_k (a_k @ v + a0_k) + mu_k @ (F_k v + f_k))

and ``L`` is affine in ``v``, so its least value over the box is attained at a
corner and computed exactly, up to the rounding of the sums, which is bounded
(Higham, *Accuracy and Stability of Numerical Algorithms*, eq. 3.5:
``|fl(sum) - sum| <= gamma_n sum |terms|``) and subtracted. Whatever the
solver's accuracy, the result is a lower bound; its accuracy sets how tight.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Cone", "ConicProgram", "Solution", "solve", "lower_bound", "SolverFailure"]

#: Clarabel's settings tried in turn when it stops on numerical trouble: its defaults, then without
#: equilibration, then with more static regularization (each rescued a program the others did not).
RETRIES: tuple[dict, ...] = ({}, {"equilibrate_enable": False}, {"static_regularization_constant": 1e-7})
#: Unit roundoff of float64.
_U = np.finfo(float).eps / 2


class SolverFailure(RuntimeError):
    """The conic solver returned no solution (status other than optimal, or infeasible)."""

    def __init__(self, status: str):
        super().__init__(f"the conic solver ended with status {status!r}")
        self.status = status


@dataclass(frozen=True)
class Cone:
    """``a @ v + a0 >= || F @ v + f ||``."""

    a: np.ndarray
    a0: float
    F: np.ndarray
    f: np.ndarray


@dataclass(frozen=True)
class ConicProgram:
    """The program of the module notes; matrices dense ``(rows, n)`` (converted to sparse for the solver)."""

    cost: np.ndarray
    G: np.ndarray
    h: np.ndarray
    A: np.ndarray
    b: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    cones: tuple[Cone, ...] = ()
    enforce: np.ndarray | None = None

    @property
    def n(self) -> int:
        return int(self.cost.size)


@dataclass(frozen=True)
class Solution:
    """The solver's point and multipliers (``lam`` for ``G``, ``nu`` for ``A``, ``(mu0, mu)`` per cone)."""

    status: str
    v: np.ndarray
    value: float
    lam: np.ndarray
    nu: np.ndarray
    mu: tuple[tuple[float, np.ndarray], ...] = field(default_factory=tuple)

    @property
    def feasible(self) -> bool:
        return self.status in ("optimal", "optimal_inaccurate")


def solve(prog: ConicProgram) -> Solution:
    """Solve ``prog`` with Clarabel through cvxpy.

    Returns a :class:`Solution` whose status is ``"infeasible"`` when the
    solver proves the program infeasible (no point, no multipliers), else
    ``"optimal"`` (or ``"optimal_inaccurate"``).

    Raises
    ------
    SolverFailure
        Any other ending (numerical trouble, unbounded: the box forbids it).
    """
    import cvxpy as cp
    import scipy.sparse as sp

    v = cp.Variable(prog.n)
    cons: list[cp.constraints.constraint.Constraint] = []
    # rows scaled to unit norm: the derivatives' rows carry powers of the spans' count
    gs = _row_norms(prog.G)
    As = _row_norms(prog.A)
    lin = (sp.csr_matrix(prog.G / gs[:, None]) @ v <= prog.h / gs) if prog.G.shape[0] else None
    eq = (sp.csr_matrix(prog.A / As[:, None]) @ v == prog.b / As) if prog.A.shape[0] else None
    cons += [c for c in (lin, eq) if c is not None]
    socs = [cp.SOC(prog.cones[k].a @ v + prog.cones[k].a0, sp.csr_matrix(prog.cones[k].F) @ v + prog.cones[k].f)
            for k in range(len(prog.cones))]
    cons += socs
    mask = np.zeros(prog.n, bool) if prog.enforce is None else prog.enforce
    fixed = mask & (prog.lo == prog.hi)
    ranged = mask & ~fixed
    if fixed.any():
        cons.append(v[np.flatnonzero(fixed)] == prog.lo[fixed])
    if ranged.any():
        idx = np.flatnonzero(ranged)
        cons += [v[idx] >= prog.lo[ranged], v[idx] <= prog.hi[ranged]]
    problem = cp.Problem(cp.Minimize(prog.cost @ v), cons)
    for settings in RETRIES:
        try:
            with warnings.catch_warnings():
                # "optimal_inaccurate" is kept in the status; no answer rests on the solver's accuracy (the bound
                # is proven from its multipliers, the laws are checked on themselves): its warning is not the user's
                warnings.simplefilter("ignore", UserWarning)
                problem.solve(solver="CLARABEL", **settings)
            break
        except cp.error.SolverError:
            continue
    else:
        raise SolverFailure("solver error")
    status = problem.status
    if status in ("infeasible", "infeasible_inaccurate"):
        return Solution("infeasible", np.full(prog.n, np.nan), np.inf, np.zeros(0), np.zeros(0))
    if status not in ("optimal", "optimal_inaccurate") or v.value is None:
        raise SolverFailure(str(status))
    lam = np.maximum(np.asarray(lin.dual_value, float).ravel(), 0.0) / gs if lin is not None else np.zeros(0)
    nu = np.asarray(eq.dual_value, float).ravel() / As if eq is not None else np.zeros(0)
    mu = []
    for c in socs:
        d0, d1 = c.dual_value
        mu.append((float(np.ravel(d0)[0]), np.asarray(d1, float).ravel()))
    return Solution(str(status), np.asarray(v.value, float), float(problem.value), lam, nu, tuple(mu))


def _row_norms(M: np.ndarray) -> np.ndarray:
    """Euclidean norms of the rows of ``M`` (1 for a zero row)."""
    n = np.linalg.norm(M, axis=1) if M.shape[0] else np.zeros(0)
    return np.where(n > 0, n, 1.0)


def _gamma(n: int) -> float:
    return n * _U / (1 - n * _U)


def lower_bound(prog: ConicProgram, sol: Solution) -> float:
    """A proven lower bound on ``prog``'s optimal value from the multipliers of ``sol`` (see the module notes).

    The multipliers are first put in their cones (``lam`` clipped at 0, each
    ``mu`` scaled into the second-order cone), so that weak duality holds
    exactly; the residual of the optimality conditions is paid for at the
    box's corners, and the rounding of every sum is bounded and subtracted.
    """
    if not sol.feasible:
        return -np.inf
    first = _bound(prog, np.maximum(sol.lam, 0.0), sol.nu, sol.mu)
    lam, nu = _polish(prog, sol)
    return max(first, _bound(prog, lam, nu, sol.mu))


def _residual(prog: ConicProgram, lam: np.ndarray, nu: np.ndarray, mu) -> np.ndarray:
    r = prog.cost.astype(float).copy()
    if lam.size:
        r += prog.G.T @ lam
    if nu.size:
        r += prog.A.T @ nu
    for cone, (m0, m) in zip(prog.cones, mu, strict=True):
        r -= m0 * cone.a + cone.F.T @ m
    return r


def _polish(prog: ConicProgram, sol: Solution) -> tuple[np.ndarray, np.ndarray]:
    """Multipliers closer to stationarity: a least-squares step on ``nu`` and the active ``lam``, ``lam`` kept
    >= 0. Any multipliers give a bound; these give a tighter one (the residual is paid for at the box)."""
    lam = np.maximum(sol.lam, 0.0)
    nu = sol.nu.copy()
    for _ in range(2):
        r = _residual(prog, lam, nu, sol.mu)
        active = np.flatnonzero(lam > 1e-9 * max(1.0, float(lam.max(initial=0.0))))
        M = np.hstack([prog.A.T, prog.G[active].T]) if prog.A.shape[0] else prog.G[active].T
        if M.shape[1] == 0:
            break
        step = np.linalg.lstsq(M, -r, rcond=None)[0]
        nu = nu + step[:prog.A.shape[0]]
        lam = lam.copy()
        lam[active] = np.maximum(lam[active] + step[prog.A.shape[0]:], 0.0)
    return lam, nu


def _bound(prog: ConicProgram, lam: np.ndarray, nu: np.ndarray, mu) -> float:
    """The weak-duality bound of the module notes at the multipliers ``lam >= 0``, ``nu``, ``mu``."""
    r = prog.cost.astype(float).copy()
    r_abs = np.abs(prog.cost).astype(float)
    const = 0.0
    const_abs = 0.0
    if lam.size:
        r += prog.G.T @ lam
        r_abs += np.abs(prog.G).T @ lam
        const -= float(lam @ prog.h)
        const_abs += float(lam @ np.abs(prog.h))
    if nu.size:
        r += prog.A.T @ nu
        r_abs += np.abs(prog.A).T @ np.abs(nu)
        const -= float(nu @ prog.b)
        const_abs += float(np.abs(nu) @ np.abs(prog.b))
    for cone, (m0, m) in zip(prog.cones, mu, strict=True):
        norm = float(np.linalg.norm(m))
        m0 = max(m0, norm * (1 + 4 * _U * max(len(m), 1)))  # (m0, m) inside the cone despite rounding
        r -= m0 * cone.a + cone.F.T @ m
        r_abs += abs(m0) * np.abs(cone.a) + np.abs(cone.F).T @ np.abs(m)
        const -= m0 * cone.a0 + float(m @ cone.f)
        const_abs += abs(m0 * cone.a0) + float(np.abs(m) @ np.abs(cone.f))
    rows = prog.G.shape[0] + prog.A.shape[0] + sum(c.F.shape[0] + 1 for c in prog.cones) + 1
    g = _gamma(rows + 2)
    corner = np.minimum(r * prog.lo, r * prog.hi)
    span = np.maximum(np.abs(prog.lo), np.abs(prog.hi))
    # rounding: of each r_i (g * r_abs_i, times the box), of the constant, of the final sum over the variables
    err = g * float(r_abs @ span) + g * const_abs + _gamma(prog.n + 2) * float(np.abs(corner).sum() + abs(const))
    return float(const + corner.sum() - err)
