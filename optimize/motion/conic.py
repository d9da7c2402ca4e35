"""A convex program in one standard form, solved by Clarabel, and its proven lower bound.

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

The solver (Clarabel, called directly) returns multipliers that satisfy the
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

from dataclasses import dataclass, field

import numpy as np

__all__ = ["Cone", "ConicProgram", "Solution", "Assembly", "solve", "lower_bound", "SolverFailure"]

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
    """Solve ``prog`` with Clarabel, called directly (no modelling layer: cvxpy's import and its
    canonicalization cost more than the solve): :class:`Assembly` of ``prog``, solved once.

    Returns a :class:`Solution` whose status is ``"infeasible"`` when the
    solver proves the program infeasible (no point, no multipliers), else
    ``"optimal"`` (or ``"optimal_inaccurate"``).

    Raises
    ------
    SolverFailure
        Any other ending (numerical trouble after every setting of :data:`RETRIES`, unbounded: the box forbids
        it).
    """
    return Assembly(prog).solve()


class Assembly:
    """A :class:`ConicProgram` in Clarabel's form, assembled once, sparse, without scipy.

    The rows are handed over as ``M x + s = rhs``, ``s`` in a product of cones: the equalities and the fixed
    variables (zero cone), the inequalities and the enforced bounds (nonnegative cone), each second-order cone
    as ``s = (a @ v + a0, F @ v + f)``. With that form the multipliers Clarabel returns satisfy
    ``cost + G' lam + A' nu - sum_k (mu0_k a_k + F_k' mu_k) = 0`` at its tolerance, as :func:`lower_bound`
    takes them. Every row is scaled to unit norm (the derivatives' rows carry powers of the spans' count) and
    the multipliers scaled back.

    With ``scales``, variable ``j`` is handed over as ``v'_j = v_j / scales[j]`` (the point scaled back; an
    enforced variable's scale is 1), before the rows' scaling. The solver stops when the optimality conditions'
    residual in the variables it sees is small; :func:`lower_bound` pays each variable's residual times its box's
    half-width, which with the half-width as the scale is the residual the solver sees: the bound's loss then
    does not grow with a wide declared box (1e5 on coefficients of size 4.5e4 turned a residual of 5.6e-7,
    within the solver's tolerance, into a loss of 0.45).

    ``M`` is built in compressed-column form from each block's nonzeros (no dense stack of the whole matrix).
    With ``pattern = (rows, cols)`` the first ``m = rows.max() + 1`` rows of ``prog.G`` are parameters: their
    nonzeros lie in ``pattern`` (row-major order, every row present), their values and right-hand sides are
    given to :meth:`solve` (``prog.G[:m]`` and ``prog.h[:m]`` are not read), the rest of the matrix, its order
    and its scaling are kept from one solve to the next. The programs of one family (the least pressure angle's
    programs at every ratio and weighting) are so assembled once.
    """

    def __init__(self, prog: ConicProgram, pattern: tuple[np.ndarray, np.ndarray] | None = None, *,
                 scales: np.ndarray | None = None):
        n = prog.n
        self.n = n
        mask = np.zeros(n, bool) if prog.enforce is None else prog.enforce
        cs = np.ones(n) if scales is None else np.asarray(scales, float)
        if cs.shape != (n,) or not np.all((cs > 0) & np.isfinite(cs)) or np.any(mask & (cs != 1)):
            raise ValueError("scales: one positive finite number per variable, 1 for an enforced one")
        self.cs = cs
        self.q = (np.asarray(prog.cost, float) * cs).tolist()
        empty = np.zeros(0, np.intp)
        pr, pc = (empty, empty) if pattern is None else pattern
        m = int(pr.max(initial=-1)) + 1
        self.m = m
        G, h = prog.G[m:] * cs, prog.h[m:]
        A = prog.A * cs
        gs = _row_norms(G)
        As = _row_norms(A)
        fixed = np.flatnonzero(mask & (prog.lo == prog.hi))
        ranged = np.flatnonzero(mask & (prog.lo != prog.hi))
        n_eq = prog.A.shape[0]
        n_zero = n_eq + fixed.size
        n_lin = m + G.shape[0] + 2 * ranged.size
        # the blocks' nonzeros (row, column, value), rows increasing block after block
        rows: list[np.ndarray] = []
        cols: list[np.ndarray] = []
        vals: list[np.ndarray] = []
        at = 0

        def dense(B: np.ndarray, scale: np.ndarray | None = None) -> None:
            nonlocal at
            r, c = np.nonzero(B)
            rows.append(r + at)
            cols.append(c)
            vals.append(B[r, c] / scale[r] if scale is not None else B[r, c])
            at += B.shape[0]

        def unit(columns: np.ndarray, value: float) -> None:
            nonlocal at
            rows.append(at + np.arange(columns.size))
            cols.append(columns)
            vals.append(np.full(columns.size, value))
            at += columns.size

        dense(A, As)
        unit(fixed, 1.0)
        if m:
            rows.append(pr + at)
            cols.append(pc)
            vals.append(np.zeros(pr.size))
            at += m
        dense(G, gs)
        unit(ranged, -1.0)
        unit(ranged, 1.0)
        cone_rhs = []
        for c in prog.cones:
            dense(np.vstack([-c.a[None], -c.F]) * cs)
            cone_rhs.append(np.concatenate([[c.a0], c.f]))
        r_all, c_all, v_all = np.concatenate(rows), np.concatenate(cols), np.concatenate(vals)
        order = np.argsort(c_all, kind="stable")        # by column, rows increasing within each (CSC)
        where = np.empty(order.size, np.intp)
        where[order] = np.arange(order.size)
        self.data = v_all[order]
        self.indices = r_all[order].tolist()
        self.indptr = np.concatenate([[0], np.cumsum(np.bincount(c_all, minlength=n))]).tolist()
        self.shape = (at, n)
        if m:
            start = len(rows[0]) + len(rows[1])
            self.slots = where[start:start + pr.size]
            self.prow = pr
            self.pcs = cs[pc]
        self.rhs = np.concatenate([prog.b / As, prog.lo[fixed], np.zeros(m), h / gs, -prog.lo[ranged],
                                   prog.hi[ranged], *cone_rhs]).astype(float)
        self.cones = (n_zero, n_lin, tuple(1 + c.F.shape[0] for c in prog.cones))
        self.n_eq, self.n_zero, self.n_G = n_eq, n_zero, m + G.shape[0]
        self.gs, self.As = gs, As

    def matrix(self, values: np.ndarray | None = None,
               h: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(data, rhs, scale)``: the scaled matrix's nonzeros in compressed-column order (the indices
        :attr:`indices`, :attr:`indptr`), the right-hand side, and the norms each row of ``G`` was divided by;
        the parameter rows (if any) given as in :meth:`solve`."""
        m = self.m
        if not m:
            return self.data, self.rhs, self.gs
        if values is None or h is None:
            raise ValueError("the parameter rows' values and right-hand sides are needed")
        values = values * self.pcs
        ps = _row_norms_of(self.prow, values, m)
        data, rhs = self.data.copy(), self.rhs.copy()
        data[self.slots] = values / ps[self.prow]
        rhs[self.n_zero:self.n_zero + m] = h / ps
        return data, rhs, np.concatenate([ps, self.gs])

    def solve(self, values: np.ndarray | None = None, h: np.ndarray | None = None) -> Solution:
        """Solve the program, the parameter rows (if any) given by their ``values`` (in the pattern's order)
        and right-hand sides ``h`` (``m``).

        Raises
        ------
        SolverFailure
            As :func:`solve`.
        """
        import clarabel  # type: ignore[import-untyped]  # it ships no types

        n = self.n
        data, rhs, gs = self.matrix(values, h)
        M = _Csc(data.tolist(), self.indices, self.indptr, self.shape)
        P = _Csc([], [], [0] * (n + 1), (n, n))
        n_zero, n_lin, socs = self.cones
        cones = []
        if n_zero:
            cones.append(clarabel.ZeroConeT(n_zero))
        if n_lin:
            cones.append(clarabel.NonnegativeConeT(n_lin))
        cones += [clarabel.SecondOrderConeT(k) for k in socs]
        b = rhs.tolist()
        for settings in RETRIES:
            options = clarabel.DefaultSettings()
            options.verbose = False
            for key, value in settings.items():
                setattr(options, key, value)
            sol = clarabel.DefaultSolver(P, self.q, M, b, cones, options).solve()
            status = str(sol.status)
            if status not in _RETRY:
                break
        else:
            raise SolverFailure("solver error")
        if status in ("PrimalInfeasible", "AlmostPrimalInfeasible"):
            return Solution("infeasible", np.full(n, np.nan), np.inf, np.zeros(0), np.zeros(0))
        if status not in _OPTIMAL:
            raise SolverFailure(status)
        z = np.asarray(sol.z, float)
        n_eq = self.n_eq
        nu = z[:n_eq] / self.As
        lam = np.maximum(z[n_zero:n_zero + self.n_G], 0.0) / gs
        mu = []
        at = n_zero + n_lin
        for k in socs:
            mu.append((float(z[at]), z[at + 1:at + k].copy()))
            at += k
        x = np.asarray(sol.x, float) * self.cs
        return Solution(_OPTIMAL[status], x, float(sol.obj_val), lam, nu, tuple(mu))


class _Csc:
    """A matrix in compressed-column form as Clarabel reads it (the attributes of scipy's ``csc_matrix``, whose
    import a solve then does not pay), indices sorted, no duplicates."""

    has_canonical_format = True

    def __init__(self, data: list, indices: list, indptr: list, shape: tuple[int, int]):
        self.data, self.indices, self.indptr, self.shape = data, indices, indptr, shape
        self.nnz = len(data)


def _row_norms_of(rows: np.ndarray, values: np.ndarray, m: int) -> np.ndarray:
    """Euclidean norms of the ``m`` rows of a matrix given by its nonzeros' ``rows`` and ``values`` (1 for a zero
    row)."""
    n = np.sqrt(np.bincount(rows, weights=values * values, minlength=m))
    return np.where(n > 0, n, 1.0)


#: Clarabel's endings with a solution, as the statuses :class:`Solution` keeps.
_OPTIMAL = {"Solved": "optimal", "AlmostSolved": "optimal_inaccurate"}
#: Clarabel's endings on numerical trouble: the next settings of :data:`RETRIES` are tried.
_RETRY = ("NumericalError", "InsufficientProgress", "Unsolved")


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
