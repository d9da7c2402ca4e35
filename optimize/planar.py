"""Exact planar primitives: nearest point of a polygon given by half-planes, clipping.

All functions take half-planes as ``N (m, 2)`` unit normals and ``c (m,)``
offsets meaning ``N @ x <= c``.

The nearest point (:class:`NearestPoint`, :func:`nearest_point`) is a 2-D
dual active-set method (Goldfarb and Idnani, Math. Programming 27, 1983) with
the identity as Hessian. In the coordinates ``y = x - P`` it minimizes
``|y|^2 / 2`` subject to ``N y <= c - N P``: starting from ``y = 0``, the
most violated half-plane is made active, dropping an active one when its
multiplier would turn negative. At every step ``y = -N^T lam`` with
``lam >= 0``, so the dual value ``-|N^T lam|^2 / 2 + lam . (N P - c)`` is a
lower bound of ``dist^2 / 2`` and never decreases. Half-planes can be added
one batch at a time (an exchange method only adds cuts): the method goes on
from the last optimum, each step costs one product ``N y`` (O(m)), and the
memory is O(m). Tolerances follow the numbers computed: half-plane ``i``
counts as violated when ``N_i y - (c_i - N_i P)`` exceeds a few rounding
errors of ``|c_i| + |P| + |y|``. An active half-plane never counts as
violated (it holds as an equation), and the vertex of two active ones is
computed backward stably, so that their residuals stay within that rounding
however nearly parallel the lines are (cuts at neighbouring cam angles are).
"""

from __future__ import annotations

import numpy as np

from laws.errors import InfeasibleError, SolverError

__all__ = ["NearestPoint", "nearest_point", "line_crossings", "clip_polygon", "feasible_mask", "EPS"]

#: Rounding errors allowed per computed signed distance: ``EPS * (|c_i| + |P| + |y|)``.
EPS = 16 * np.finfo(float).eps
#: ``|sin|`` of the angle between two unit normals below which the lines count as parallel.
_PARALLEL = 1e-14


class NearestPoint:
    """Nearest point to ``P`` of ``{x : N x <= c}``, half-planes added in batches.

    Parameters
    ----------
    P : array_like, shape (2,)
        The point to approach (for the solvers: the target of the objective,
        the follower's fixed frame, length unit).

    Attributes
    ----------
    x : ndarray, shape (2,)
        The current nearest point (after :meth:`solve`), same frame and unit.
    active : list of int
        Indices (in the order of addition) of the half-planes active at ``x``
        (at most two, independent normals).
    lam : ndarray, shape (len(active),)
        Their multipliers, >= 0 (length unit): ``x - P = -sum lam_k N_k``.
    steps : int
        Active-set changes so far.
    """

    def __init__(self, P: np.ndarray):
        self.P = np.asarray(P, dtype=float).copy()
        self._N = np.zeros((16, 2))
        self._c = np.zeros(16)   # offsets relative to P: c_i - N_i . P
        self._tol = np.zeros(16)  # rounding allowance of each c_i - N_i . P
        self.m = 0
        self.y = np.zeros(2)
        self.active: list[int] = []
        self.lam = np.zeros(0)
        self.steps = 0

    @property
    def x(self) -> np.ndarray:
        """The current point ``P + y`` (fixed frame, length unit)."""
        return self.P + self.y

    def add(self, N: np.ndarray, c: np.ndarray) -> None:
        """Add the half-planes ``N x <= c`` (unit normals ``N (k, 2)``, offsets ``c (k,)``, length unit)."""
        N = np.asarray(N, dtype=float).reshape(-1, 2)
        c = np.asarray(c, dtype=float).reshape(-1)
        k = len(N)
        need = self.m + k
        if need > len(self._c):
            cap = max(need, 2 * len(self._c))
            self._N = np.resize(self._N, (cap, 2))
            self._c = np.resize(self._c, cap)
            self._tol = np.resize(self._tol, cap)
        sl = slice(self.m, need)
        self._N[sl] = N
        self._c[sl] = c - N @ self.P
        self._tol[sl] = EPS * (np.abs(c) + np.abs(self.P).sum())
        self.m = need

    def tolerances(self) -> np.ndarray:
        """Allowed residual of every half-plane: rounding of the numbers computed (length unit)."""
        return self._tol[: self.m] + EPS * float(np.abs(self.y).sum())

    def dual_value(self) -> float:
        """``-|N^T lam|^2 / 2 + lam . (N P - c)`` for the current multipliers: <= ``dist^2 / 2``."""
        if not self.active:
            return 0.0
        lam = np.maximum(self.lam, 0.0)
        g = lam @ self._N[self.active]
        return float(-0.5 * (g @ g) - lam @ self._c[self.active])

    def lower_bound(self) -> float:
        """A proven lower bound of the distance from ``P`` to ``{x : N x <= c}`` (length unit).

        Weak duality at the current multipliers (any ``lam >= 0`` will do),
        less what the rounding of each offset ``c_i - N_i P`` can change it
        by: ``sqrt(2 (dual_value - lam . tolerances))``, 0 when that is
        negative. After :meth:`solve` it meets the distance to rounding.
        """
        if not self.active:
            return 0.0
        lam = np.maximum(self.lam, 0.0)
        g = self.dual_value() - float(lam @ self._tol[self.active])
        return float(np.sqrt(2.0 * g)) * (1.0 - 4 * EPS) if g > 0 else 0.0

    def solve(self, max_steps: int | None = None) -> np.ndarray:
        """Make the current point the nearest point of all half-planes added so far.

        Parameters
        ----------
        max_steps : int, optional
            Cap on the active-set changes of this call; default ``4 m + 100``
            (each step raises the dual value, and an active set recurs only
            with a higher value, so the cap is never reached in exact
            arithmetic).

        Returns
        -------
        ndarray, shape (2,)
            The nearest point (fixed frame, length unit).

        Raises
        ------
        InfeasibleError
            When the half-planes have no common point (a dual ray: the
            violated half-plane is opposed by the active ones).
        SolverError
            When the cap on the steps is reached (the solver's fault).
        """
        N, c = self._N, self._c
        limit = (max_steps if max_steps is not None else 4 * self.m + 100)
        steps = 0
        while self.m:
            excess = N[: self.m] @ self.y - c[: self.m] - self.tolerances()
            # an active half-plane holds as an equation: its residual is the vertex's rounding, never a
            # violation (entering it again would drop it and enter it again, a cycle)
            excess[self.active] = -np.inf
            p = int(np.argmax(excess))
            if excess[p] <= 0:
                break
            n, up = N[p], 0.0
            while True:  # raise the multiplier of p until p is active (full step)
                steps += 1
                if steps > limit:
                    raise SolverError(f"the nearest-point method did not settle in {limit} steps")
                A = self.active
                if not A:
                    w, r = n, np.zeros(0)
                elif len(A) == 1:
                    a = N[A[0]]
                    an = float(a @ n)
                    parallel = abs(a[0] * n[1] - a[1] * n[0]) <= _PARALLEL
                    w, r = (np.zeros(2) if parallel else n - an * a), np.array([an])
                else:
                    a1, a2 = N[A[0]], N[A[1]]
                    det = a1[0] * a2[1] - a1[1] * a2[0]
                    w = np.zeros(2)
                    r = np.array([n[0] * a2[1] - n[1] * a2[0], a1[0] * n[1] - a1[1] * n[0]]) / det
                # n = r . (active normals) + w: moving y by -t w and the multipliers by -t r, +t keeps
                # y = -N^T lam and the active half-planes tight, and lowers the residual of p by t |w|^2
                ww = float(w @ w)
                sp = max(float(n @ self.y - c[p]), 0.0)
                t1 = sp / ww if ww > 0 else np.inf
                t2, k = np.inf, -1
                for j in range(len(r)):
                    if r[j] > 0 and self.lam[j] / r[j] < t2:
                        t2, k = self.lam[j] / r[j], j
                if t1 == np.inf and t2 == np.inf:
                    raise InfeasibleError("limits.pressure_angle",
                                          "no cam centre satisfies the pressure-angle limits")
                t = min(t1, t2)
                if ww > 0:
                    self.y = self.y - t * w
                self.lam = self.lam - t * r
                up += t
                if t1 <= t2:
                    self.active = [*A, p]
                    self.lam = np.append(self.lam, up)
                    break
                self.active = A[:k] + A[k + 1:]
                self.lam = np.delete(self.lam, k)
            self._snap()
        self.steps += steps
        return self.x

    def _snap(self) -> None:
        """Recompute the point from its active half-planes (no drift of the accumulated steps).

        Two active half-planes: the foot of the first line, ``c_1 a_1``, then
        along that line (direction ``k x a_1``) to the second one. Each
        residual ``a_i . y - c_i`` is then a few rounding errors of
        ``|c_i| + |y|`` however nearly parallel the lines are (backward
        stable); Cramer's rule is not: its residuals grow with ``1 / sin`` of
        the angle between the lines (Higham, Accuracy and Stability of
        Numerical Algorithms, 2nd ed., section 1.10.1).
        """
        N, c, A = self._N, self._c, self.active
        if len(A) == 2:
            a1, a2 = N[A[0]], N[A[1]]
            b1, b2 = c[A[0]], c[A[1]]
            det = a1[0] * a2[1] - a1[1] * a2[0]   # a2 . (k x a1)
            foot = b1 * a1
            along = (b2 - float(a2 @ foot)) / det
            self.y = foot + along * np.array([-a1[1], a1[0]])
            # y = -(lam1 a1 + lam2 a2)
            lam = -np.array([self.y[0] * a2[1] - self.y[1] * a2[0], a1[0] * self.y[1] - a1[1] * self.y[0]]) / det
            self.lam = np.maximum(lam, 0.0)
        elif len(A) == 1:
            self.y = c[A[0]] * N[A[0]]
            self.lam = np.array([max(-c[A[0]], 0.0)])
        else:
            self.y = np.zeros(2)


def nearest_point(P: np.ndarray, N: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """Exact nearest point to ``P`` of ``{x : N x <= c}`` (:class:`NearestPoint`).

    Parameters
    ----------
    P : array_like, shape (2,)
        The point to approach (length unit).
    N : ndarray, shape (m, 2)
        Unit normals of the half-planes.
    c : ndarray, shape (m,)
        Offsets, length unit. No tolerance is passed: it follows the numbers
        computed (module notes).

    Returns
    -------
    (x, active) or None
        The point and the indices of the half-planes active there (at most
        two, the ones whose multipliers certify it); ``None`` when the
        half-planes have no common point.
    """
    q = NearestPoint(P)
    q.add(N, c)
    try:
        x = q.solve()
    except InfeasibleError:
        return None
    return x, np.array(sorted(q.active), dtype=int)


def feasible_mask(points: np.ndarray, N: np.ndarray, c: np.ndarray, tol: float) -> np.ndarray:
    """True for the points that satisfy every half-plane ``N x <= c`` within ``tol``.

    Parameters
    ----------
    points : ndarray, shape (k, 2)
        Points in the frame of the half-planes (for the solvers: cam centres
        in the follower's fixed frame, :mod:`cams.model.follower`; length unit).
    N : ndarray, shape (m, 2)
        Unit normals, pointing out of the half-planes.
    c : ndarray, shape (m,)
        Offsets (length unit): ``N x - c`` is the signed distance outside.
    tol : float
        Allowed distance outside (length unit), >= 0.

    Returns
    -------
    ndarray of bool, shape (k,)
        True where ``N x <= c + tol`` holds for every half-plane (all True
        when ``m = 0``).
    """
    if len(N) == 0:
        return np.ones(len(points), dtype=bool)
    return np.all(points @ N.T <= c + tol, axis=1)


def line_crossings(N1, c1, N2, c2) -> tuple[np.ndarray, np.ndarray]:
    """Crossings of lines ``N1[i] x = c1[i]`` with ``N2[j] x = c2[j]``, all pairs.

    Parameters
    ----------
    N1 : ndarray, shape (n1, 2)
        Normals of the first lines (unit length not needed).
    c1 : ndarray, shape (n1,)
        Their offsets.
    N2 : ndarray, shape (n2, 2)
        Normals of the second lines.
    c2 : ndarray, shape (n2,)
        Their offsets.

    Returns
    -------
    points : ndarray, shape (n1, n2, 2)
    ok : ndarray of bool, shape (n1, n2)
        False where the lines are parallel (no unique crossing).
    """
    a, b = N1[:, None, 0], N1[:, None, 1]
    cc, d = N2[None, :, 0], N2[None, :, 1]
    det = a * d - b * cc
    ok = np.abs(det) > 1e-12
    sdet = np.where(ok, det, 1.0)
    x = (c1[:, None] * d - b * c2[None, :]) / sdet
    y = (a * c2[None, :] - cc * c1[:, None]) / sdet
    return np.stack([x, y], axis=-1), ok


def clip_polygon(N: np.ndarray, c: np.ndarray, box: tuple[float, float, float, float]) -> np.ndarray:
    """Convex polygon ``{x : N x <= c}`` clipped to ``box = (xmin, ymin, xmax, ymax)``.

    Sutherland-Hodgman against each half-plane in turn.

    Parameters
    ----------
    N : ndarray, shape (m, 2)
        Outward normals of the half-planes.
    c : ndarray, shape (m,)
        Their offsets.
    box : (xmin, ymin, xmax, ymax)
        The clipping rectangle, in the frame and unit of the half-planes.

    Returns
    -------
    ndarray, shape (k, 2)
        The vertices counter-clockwise, shape (0, 2) when the intersection is
        empty.
    """
    x0, y0, x1, y1 = box
    poly = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], dtype=float)
    for n, cc in zip(N, c, strict=True):
        if len(poly) == 0:
            break
        s = poly @ n - cc
        inside = s <= 0
        if np.all(inside):
            continue
        out = []
        m = len(poly)
        for j in range(m):
            p, q = poly[j], poly[(j + 1) % m]
            sp, sq = s[j], s[(j + 1) % m]
            if sp <= 0:
                out.append(p)
            if (sp <= 0) != (sq <= 0):
                t = sp / (sp - sq)
                out.append(p + t * (q - p))
        poly = np.array(out) if out else np.zeros((0, 2))
    return poly
