"""The spline space of the free phases: variables, joints and the linear maps of the constraints.

Each free phase ``k`` (a rise or return of the program) gets a normalized law
``S_k(u)``, ``u`` in [0, 1], a polynomial of degree ``p`` on each of ``spans``
equal knot spans, written by its Bernstein coefficients in the span's local
variable (:mod:`laws.bernstein`). The variables of all free phases come first
in the vector ``v`` of the programs, one block per phase, spans in order.

The space's equalities: ``S(0) = 0``, ``S(1) = 1``; derivatives 0 to
``continuity`` equal on both sides of every knot; derivatives 1 to
``continuity`` at the phase's ends equal the neighbouring phases' (a dwell's
are 0; a fixed law's are its own; two free phases share theirs), in the
physical analogue ``s^(r)(phi) = sigma h S^(r)(u) / beta^r`` (``sigma`` +1 on a
rise, -1 on a return; ``h`` the phase's height; ``beta`` its angle, radians).

Two ways to impose an inequality on a span's polynomial: on its Bernstein
coefficients after subdividing the span into ``pieces`` parts (every ``u``,
conservatively: the convex-hull property) or at sample points (a relaxation).
:meth:`Space.rows` gives either, as the same rows of a matrix acting on ``v``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from laws import bernstein
from laws.program import Program

__all__ = ["Space", "PIECES", "CONSISTENT"]

#: Subdivisions of each span for the conservative (every-angle) constraints.
PIECES = 4
#: The space's equalities count as solvable when :meth:`Space.inconsistency` is at most this: their rows have
#: unit norm and a solvable system's residual is rounding, an unsolvable one's of the order of the joints' values
#: (over degrees 2 to 11, continuity 1 to 3, 1 to 8, 20 and 40 spans (100 to degree 7), one or two free phases
#: between dwells, fixed phases and each other: at most 3e-14 and at least 8e-3).
CONSISTENT = 1e-9


@dataclass(frozen=True)
class Space:
    """The free phases' spline space in a program.

    The variables of free phase ``k``, span by span: the Bernstein
    coefficients of its ``continuity``-th derivative ``S^(c)`` on the span
    (degree ``p - c``), then ``S^(r)`` at the span's start for ``r = 0 ..
    c-1``; the lower derivatives follow by integration inside the span, and
    equalities join the spans. So every map has entries of the size of the
    quantity it gives (no high differences of nearly equal coefficients: the
    programs stay well conditioned as the spans shrink) and touches one span's
    variables (sparse).

    Parameters
    ----------
    program : Program
        The cycle; its free phases' laws are the starting point only.
    free : tuple of int
        Indices of the free phases (rises and returns), increasing.
    degree, spans, continuity : int
        The space (see :class:`cams.model.motiondesign.MotionDesignSpec`).
    pieces : int
        Subdivisions per span of the conservative constraints.
    """

    program: Program
    free: tuple[int, ...]
    degree: int
    spans: int
    continuity: int
    pieces: int = PIECES

    @property
    def top(self) -> int:
        """Degree of the variables' polynomials (of ``S^(c)``)."""
        return self.degree - self.continuity

    @property
    def block(self) -> int:
        """Variables per span: ``S^(c)``'s coefficients, then ``S^(r)`` at the span's start, ``r < c``."""
        return self.top + 1 + self.continuity

    @property
    def per_phase(self) -> int:
        """Variables per free phase."""
        return self.spans * self.block

    @property
    def size(self) -> int:
        """Variables of all free phases."""
        return len(self.free) * self.per_phase

    @cached_property
    def breaks(self) -> np.ndarray:
        """The knots in ``u``, ``spans + 1`` of them from 0 to 1."""
        return np.arange(self.spans + 1) / self.spans     # as laws.spline.SplineLaw.uniform

    @property
    def h(self) -> float:
        """Width of a span in ``u``."""
        return 1.0 / self.spans

    def offset(self, k: int) -> int:
        """First variable of free phase ``k`` (the ``k``-th of :attr:`free`)."""
        return k * self.per_phase

    def phase_scale(self, i: int) -> tuple[float, float, float]:
        """``(sigma h, beta, level)`` of program phase ``i``: ``s = level + sigma h S``, ``s' = sigma h S'/beta``."""
        return (self.program.signed_height(i), float(self.program.phases[i].angle),
                float(self.program.levels[i]))

    def bounds(self, caps: dict[tuple[int, int], float] | None = None) -> np.ndarray:
        """Half-widths of the box on all the free phases' variables.

        A capped derivative's variables need no box of their own: every law that meets the cap on the whole
        span has them within it (the coefficients of ``S^(c)`` within :func:`laws.bernstein.coefficient_bound`
        times its cap; the values ``S^(r)`` at the knots within the cap itself), so the box restricts nothing
        and the proven lower bound holds for the whole space. An uncapped one's box is declared, part of the
        space: ``10**(c + 2)`` on ``S^(c)``'s coefficients, ``10**(r + 1)`` on ``S^(r)`` at the knots (a
        program notes it if its answer ever touches it). The lower bound pays for the solver's residual at the
        box's corners: the tighter the box, the tighter the bound.

        Parameters
        ----------
        caps : dict of (int, int) to float, optional
            ``(k, r) -> cap`` on ``|S_k^(r)|`` (free phase ``k``).
        """
        caps = caps or {}
        c = self.continuity
        rounding = 1 + 1e-12
        out = []
        for k in range(len(self.free)):
            top = caps.get((k, c))
            one = np.full(self.block, bernstein.coefficient_bound(self.top) * top * rounding if top is not None
                          else 10.0 ** (c + 2))
            for r in range(c):
                cap = caps.get((k, r))
                one[self.top + 1 + r] = cap * rounding if cap is not None else 10.0 ** (r + 1)
            out.append(np.tile(one, self.spans))
        return np.concatenate(out) if out else np.zeros(0)

    def declared(self, caps: dict[tuple[int, int], float] | None = None) -> np.ndarray:
        """Which variables' box is declared (uncapped), not implied by the caps (:meth:`bounds`)."""
        caps = caps or {}
        c = self.continuity
        out = []
        for k in range(len(self.free)):
            one = np.full(self.block, (k, c) not in caps)
            for r in range(c):
                one[self.top + 1 + r] = (k, r) not in caps
            out.append(np.tile(one, self.spans))
        return np.concatenate(out) if out else np.zeros(0, bool)

    @cached_property
    def _levels(self) -> tuple[np.ndarray, ...]:
        """Per derivative ``r`` from 0 to ``c``: ``(p-r+1, block)``, a span's Bernstein coefficients of ``S^(r)``
        as a map of that span's variables (integration in the span from its start values)."""
        c, q, h = self.continuity, self.top, self.h
        top = np.zeros((q + 1, self.block))
        top[:, :q + 1] = np.eye(q + 1)
        levels = [top]
        for r in range(c - 1, -1, -1):
            above = levels[-1]                          # S^(r+1), degree p-r-1
            deg = above.shape[0] - 1
            # integral in t of a degree-deg Bernstein polynomial: I_i = sum_{l<i} b_l / (deg+1), degree deg+1
            integ = np.tril(np.ones((deg + 2, deg + 1)), -1) / (deg + 1)
            start = np.zeros(self.block)
            start[q + 1 + r] = 1.0                      # S^(r) at the span's start, a variable
            levels.append(start[None, :] + h * (integ @ above))
        return tuple(reversed(levels))

    def _local(self, r: int) -> np.ndarray:
        """``(p-r+1, block)``: the Bernstein coefficients of ``S^(r)`` on a span, from its variables."""
        c = self.continuity
        if r <= c:
            return self._levels[r]
        return bernstein.derivative_chain(self.top, r - c) / self.h ** (r - c) @ self._levels[c]

    def _place(self, k: int, j: int, local: np.ndarray, n: int) -> np.ndarray:
        """Rows over ``n`` variables with ``local`` (acting on span ``j`` of free phase ``k``) in place."""
        out = np.zeros((local.shape[0], n))
        o = self.offset(k) + j * self.block
        out[:, o:o + self.block] = local
        return out

    def coefficients(self, v: np.ndarray, k: int) -> np.ndarray:
        """``(spans, degree+1)`` Bernstein coefficients of ``S_k`` from the variable vector ``v``."""
        o = self.offset(k)
        blocks = np.asarray(v[o:o + self.per_phase], float).reshape(self.spans, self.block)
        return blocks @ self._levels[0].T

    def rows(self, k: int, r: int, n: int, *, samples: np.ndarray | None = None,
             elevate: bool = False) -> np.ndarray:
        """Rows giving ``S_k^(r)`` over the whole phase: Bernstein coefficients per piece, or values at samples.

        Parameters
        ----------
        k : int
            Free phase (index into :attr:`free`).
        r : int
            Derivative order, 0 to the degree.
        n : int
            Length of the variable vector.
        samples : ndarray or None
            ``u`` in [0, 1]: the rows are the values there (a relaxation).
            None: the Bernstein coefficients on every piece of every span
            (``spans * pieces`` blocks, conservative).
        elevate : bool
            Give the coefficients at degree ``p`` (so that they combine with
            another derivative's term by term); only for the coefficient rows.

        Returns
        -------
        ndarray, shape (rows, n)
        """
        p = self.degree
        loc = self._local(r)
        q = p - r
        if samples is None:
            sub = bernstein.subdivision(q, self.pieces)
            if elevate and q < p:
                sub = np.einsum("ab,kbc->kac", bernstein.elevation(q, p), sub)
            one = np.einsum("kab,bm->kam", sub, loc).reshape(-1, self.block)
            return np.vstack([self._place(k, j, one, n) for j in range(self.spans)])
        u = np.asarray(samples, float)
        j = np.minimum((u * self.spans).astype(int), self.spans - 1)
        t = u * self.spans - j
        vals = bernstein.basis(q, t) @ loc               # (len(u), block)
        out = np.zeros((u.size, n))
        cols = self.offset(k) + j[:, None] * self.block + np.arange(self.block)[None, :]
        np.put_along_axis(out, cols, vals, axis=1)
        return out

    def end_rows(self, k: int, r: int, n: int, end: int) -> np.ndarray:
        """``(1, n)``: ``S_k^(r)`` at ``u = 0`` (``end = 0``) or ``u = 1`` (``end = 1``)."""
        loc = self._local(r)
        if end == 0:
            return self._place(k, 0, loc[[0]], n)
        return self._place(k, self.spans - 1, loc[[-1]], n)

    # -- the space's equalities -------------------------------------------------
    def equalities(self, n: int) -> tuple[np.ndarray, np.ndarray]:
        """``(A, b)``: the ends, the knots and the joints of the module notes, over ``n`` variables."""
        rows, rhs = [], []
        c = self.continuity
        index = {i: k for k, i in enumerate(self.free)}
        for k in range(len(self.free)):
            rows += [self.end_rows(k, 0, n, 0), self.end_rows(k, 0, n, 1)]
            rhs += [0.0, 1.0]
            for j in range(self.spans - 1):             # S^(0..c) continuous at the knots
                for r in range(c + 1):
                    loc = self._local(r)
                    rows.append(self._place(k, j, loc[[-1]], n) - self._place(k, j + 1, loc[[0]], n))
                    rhs.append(0.0)
        # joints between consecutive phases (cyclic), derivatives 1..c in the physical analogue
        phases = self.program.phases
        m = len(phases)
        for a in range(m):
            bph = (a + 1) % m
            if a not in index and bph not in index:
                continue
            for r in range(1, c + 1):
                row = np.zeros((1, n))
                val = 0.0
                for ph, end, sign in ((a, 1, 1.0), (bph, 0, -1.0)):   # left - right = 0
                    if phases[ph].kind == "dwell":
                        continue
                    sh, beta, _ = self.phase_scale(ph)
                    factor = sign * sh / beta**r
                    if ph in index:
                        row += factor * self.end_rows(index[ph], r, n, end)
                    else:
                        val -= factor * float(self.program.law_of(ph).evaluate(float(end))[r])
                rows.append(row)
                rhs.append(val)
        if not rows:                                    # no free phase
            return np.zeros((0, n)), np.zeros(0)
        return np.vstack(rows), np.asarray(rhs)

    # -- the space's integrals ----------------------------------------------------
    def integral_factor(self, k: int, r: int, n: int) -> np.ndarray:
        """``Q`` with ``|| Q v ||**2 = integral_0^1 S_k^(r)(u)**2 du`` (exactly: the Bernstein Gram matrix)."""
        g = bernstein.gram(self.degree - r)
        R = np.linalg.cholesky(g).T       # the Gram matrix is positive definite: the basis is independent
        one = R @ self._local(r) * np.sqrt(self.h)    # the span's width in u is the measure
        return np.vstack([self._place(k, j, one, n) for j in range(self.spans)])

    def inconsistency(self) -> float:
        """How far the space's equalities are from having a solution: the largest residual of their least-squares
        solution, each row scaled to unit norm (dimensionless; 0 to rounding when some law of the space meets
        the ends and the joints, of the order of the joints' values when none does).

        A law exists exactly when the right-hand side lies in the range of the equalities' matrix; the
        least-squares solution's residual is the distance from it (rows of unit norm: it does not depend on
        the phases' heights or angles). Compare it with :data:`CONSISTENT`.
        """
        A, b = self.equalities(self.size)
        if not A.shape[0]:
            return 0.0
        norms = _row_norms(A)
        return _residual(A, b, np.linalg.lstsq(A / norms[:, None], b / norms, rcond=None)[0])

    def project(self, v: np.ndarray) -> np.ndarray:
        """The least change of ``v`` that satisfies the space's equalities to rounding (the joints and ends
        exactly, not to a solver's tolerance); the variables after the coefficients are left as they are.

        Raises
        ------
        ValueError
            The equalities have no solution (:meth:`inconsistency`; the motion design refuses such a space
            first, so this is a programming error, not the user's).
        """
        A, b = self.equalities(v.size)
        out = v - np.linalg.lstsq(A, A @ v - b, rcond=None)[0]
        if A.shape[0] and _residual(A, b, out) > CONSISTENT:
            raise ValueError("the space's equalities have no solution: no law to project on")
        return out

    def programme(self, v: np.ndarray, name: str) -> Program:
        """The program with each free phase's law the spline of ``v`` (:class:`laws.spline.SplineLaw`)."""
        from dataclasses import replace

        from laws.spline import SplineLaw

        laws = {}
        for k, i in enumerate(self.free):
            coeffs = self.coefficients(v, k)
            coeffs[0, 0], coeffs[-1, -1] = 0.0, 1.0
            laws[i] = SplineLaw.uniform([[float(x) for x in row] for row in coeffs], name=name)
        phases = tuple(replace(p, law=laws.get(i, p.law)) for i, p in enumerate(self.program.phases))
        return Program(phases, self.program.lift)


def _row_norms(A: np.ndarray) -> np.ndarray:
    """Euclidean norms of the rows of ``A`` (1 for a zero row)."""
    n = np.linalg.norm(A, axis=1)
    return np.where(n > 0, n, 1.0)


def _residual(A: np.ndarray, b: np.ndarray, x: np.ndarray) -> float:
    """The largest residual of ``A x = b`` with every row scaled to unit norm, relative to the larger of 1, the
    scaled right-hand side and the products' terms (dimensionless)."""
    norms = _row_norms(A)
    An, bn = A / norms[:, None], b / norms
    scale = max(1.0, float(np.max(np.abs(bn))), float(np.max(np.abs(x[:An.shape[1]]))))
    return float(np.max(np.abs(An @ x[:An.shape[1]] - bn))) / scale
