"""A piecewise polynomial rise law in Bernstein form (a spline given by its coefficients).

The law ``S(u)``, ``u`` in [0, 1], is a polynomial of one degree ``p`` on each
knot span ``[b_j, b_{j+1}]`` of the breaks ``0 = b_0 < b_1 < ... < b_n = 1``,
written in the span's local variable ``t = (u - b_j) / (b_{j+1} - b_j)`` as
``sum_i c_{j,i} B_{i,p}(t)`` (:mod:`laws.bernstein`). The spans meet with ``S``
continuous (the last coefficient of a span is the first of the next); higher
derivatives may jump at a break, and :attr:`SplineLaw.breakpoints` lists the
interior breaks so that the diagnostics take one-sided limits there.

``S', S'', S'''`` are the polynomials' own derivatives (exact, no numerical
differentiation), evaluated in Bernstein form: each span's ``k``-th derivative
has the coefficients ``p!/(p-k)! Delta^k c`` (forward differences, computed
once), summed against the degree ``p - k`` basis at ``t`` and divided by the
span's width to the power ``k``. The basis is a partition of unity with
nonnegative terms, so a value's rounding is a few units of its coefficients'
(the power form's Horner's rule was not: its coefficients are alternating sums
with binomial weights up to ``C(p, k) C(k, i)``; on 40 spans of degree 11 it
gave ``S''(1)`` as 1.4e-7 where the coefficients give 2e-11).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from math import comb

import numpy as np

from laws.base import Law
from laws.bernstein import derivative_chain
from laws.errors import InputError, check_numbers

__all__ = ["SplineLaw", "MAX_DEGREE"]

#: The largest degree of a span (the files' limit).
MAX_DEGREE = 15
#: Tolerance on the first and last break (0 and 1).
BREAK_TOL = 1e-12
#: Tolerance on ``S(0) = 0``, ``S(1) = 1`` and on the continuity of ``S``, times max(1, largest |coefficient|).
VALUE_TOL = 1e-9

#: ``C(q, i)`` for ``q`` up to MAX_DEGREE, one row each (the Bernstein basis's weights).
_BINOMIALS = tuple(np.array([comb(q, i) for i in range(q + 1)], float) for q in range(MAX_DEGREE + 1))

_BREAKS = "spline.breaks"
_COEFFS = "spline.coefficients"


@dataclass(frozen=True)
class SplineLaw(Law):
    """A piecewise polynomial rise ``S(u)`` given by Bernstein coefficients per knot span.

    Parameters
    ----------
    breaks : tuple of float
        ``0 = b_0 < b_1 < ... < b_n = 1``: the knot spans' ends, normalized
        position ``u`` (dimensionless); strictly increasing.
    coefficients : tuple of tuple of float
        ``n`` rows, one per span, each the ``p + 1`` Bernstein coefficients of
        ``S`` on that span in its local variable ``t = (u - b_j) / (b_{j+1} -
        b_j)`` (dimensionless normalized rise); the same degree ``p``, 1 to
        :data:`MAX_DEGREE`, on every span.
    name : str, keyword-only
        Name shown in tables.

    Attributes
    ----------
    breakpoints : tuple of float
        The interior breaks ``b_1 .. b_{n-1}``, where derivatives may jump.

    Raises
    ------
    InputError
        Field ``"spline.coefficients"``: not finite numbers, spans of
        different lengths, fewer than 2 or more than ``MAX_DEGREE + 1``
        coefficients a span, ``S(0) != 0`` or ``S(1) != 1`` (the first
        coefficient of the first span, the last of the last), ``S`` jumping at
        a break (to ``1e-9`` times the largest coefficient, at least 1).
        Field ``"spline.breaks"``: not finite numbers, not one more than the
        spans, not strictly increasing, not from 0 to 1 (to ``1e-12``).

    Examples
    --------
    The 3-4-5 polynomial ``10 u^3 - 15 u^4 + 6 u^5`` as one span of degree 5:

    >>> law = SplineLaw((0.0, 1.0), ((0, 0, 0, 1, 1, 1),), name="345")
    >>> law.degree, law.spans
    (5, 1)
    >>> float(law.evaluate(0.5)[1])
    1.875

    The constant-acceleration law as two spans of degree 2; ``S''`` jumps at
    the break:

    >>> law = SplineLaw.uniform([[0, 0, 0.5], [0.5, 1, 1]])
    >>> law.breaks, law.breakpoints
    ((0.0, 0.5, 1.0), (0.5,))
    >>> law.evaluate([0.25, 0.75])[2].tolist()
    [4.0, -4.0]
    """

    breaks: tuple[float, ...]
    coefficients: tuple[tuple[float, ...], ...]
    name: str = field(default="spline", kw_only=True)
    #: Per derivative k = 0..3 (up to the degree): each span's Bernstein coefficients of d^k S / dt^k in its
    #: local variable times the basis's weights C(degree - k, i), shape (spans, degree - k + 1).
    _derivatives: tuple[np.ndarray, ...] = field(init=False, repr=False, compare=False, hash=False)

    def __post_init__(self):
        c = self.coefficients
        if isinstance(c, (str, bytes)) or not isinstance(c, (Sequence, np.ndarray)) or len(c) == 0:
            raise InputError(_COEFFS, f"must be a non-empty sequence of spans (sequences of numbers), got {c!r}")
        rows = tuple(tuple(check_numbers(_COEFFS, r, f"span {j}").tolist()) for j, r in enumerate(c))
        size = len(rows[0])
        for j, r in enumerate(rows):
            if len(r) != size:
                raise InputError(_COEFFS, f"every span must have the same number of coefficients (degree + 1): "
                                 f"span 0 has {size}, span {j} has {len(r)}")
        if not 2 <= size <= MAX_DEGREE + 1:
            raise InputError(_COEFFS, f"a span takes 2 to {MAX_DEGREE + 1} coefficients (degree 1 to {MAX_DEGREE}), "
                             f"got {size}")
        b = tuple(check_numbers(_BREAKS, self.breaks, "breaks").tolist())
        if len(b) != len(rows) + 1:
            raise InputError(_BREAKS, f"needs one more break than spans: {len(rows)} span(s) need {len(rows) + 1} "
                             f"breaks, got {len(b)}")
        for j in range(len(rows)):
            if not b[j + 1] > b[j]:
                raise InputError(_BREAKS, f"must be strictly increasing, but breaks[{j + 1}] = {b[j + 1]!r} <= "
                                 f"breaks[{j}] = {b[j]!r}")
        if abs(b[0]) > BREAK_TOL or abs(b[-1] - 1.0) > BREAK_TOL:
            raise InputError(_BREAKS, f"must start at 0 and end at 1, got {b[0]!r} .. {b[-1]!r}")
        b = (0.0, *b[1:-1], 1.0)
        tol = VALUE_TOL * max(1.0, max(abs(x) for r in rows for x in r))
        s0, s1 = rows[0][0], rows[-1][-1]
        if abs(s0) > tol or abs(s1 - 1.0) > tol:
            raise InputError(_COEFFS, f"must give S(0) = 0 and S(1) = 1 (a normalized rise: the first coefficient "
                             f"of the first span and the last of the last), got S(0) = {s0!r}, S(1) = {s1!r}")
        for j in range(len(rows) - 1):
            before, after = rows[j][-1], rows[j + 1][0]
            if abs(after - before) > tol:
                raise InputError(_COEFFS, f"S must be continuous, but it jumps at the break u = {b[j + 1]!r}: "
                                 f"{before!r} at the end of span {j}, {after!r} at the start of span {j + 1}")
        coeffs = np.array(rows, float)
        derivs = []
        for k in range(min(3, size - 1) + 1):
            q = size - 1 - k
            d = coeffs @ derivative_chain(size - 1, k).T * _BINOMIALS[q]     # the basis's weights C(q, i) folded in
            d.setflags(write=False)
            derivs.append(d)
        object.__setattr__(self, "breaks", b)
        object.__setattr__(self, "coefficients", rows)
        object.__setattr__(self, "_derivatives", tuple(derivs))
        # the instance's own interior breaks, where laws.diagnostics and laws.characteristics look for jumps
        object.__setattr__(self, "breakpoints", b[1:-1])

    @classmethod
    def uniform(cls, coefficients, *, name: str = "spline") -> SplineLaw:
        """A spline law on equal knot spans.

        Parameters
        ----------
        coefficients : sequence of sequence of float
            One row of Bernstein coefficients per span (see the class).
        name : str, keyword-only
            Name shown in tables.

        Returns
        -------
        SplineLaw
            With breaks ``j / n``, ``j = 0 .. n`` for ``n`` spans.

        Raises
        ------
        InputError
            As the class (field ``"spline.coefficients"``).
        """
        if isinstance(coefficients, (str, bytes)) or not isinstance(coefficients, (Sequence, np.ndarray)) \
                or len(coefficients) == 0:
            raise InputError(_COEFFS, f"must be a non-empty sequence of spans (sequences of numbers), "
                             f"got {coefficients!r}")
        n = len(coefficients)
        return cls(tuple(j / n for j in range(n + 1)), tuple(coefficients), name=name)

    @property
    def degree(self) -> int:
        """Degree ``p`` of the polynomial on each span."""
        return len(self.coefficients[0]) - 1

    @property
    def spans(self) -> int:
        """Number of knot spans."""
        return len(self.coefficients)

    def _evaluate(self, u):
        b = np.asarray(self.breaks)
        flat = np.ravel(u)
        # a u on an interior break belongs to the later span, u = 1 to the last
        j = np.clip(np.searchsorted(b, flat, side="right") - 1, 0, self.spans - 1)
        h = b[j + 1] - b[j]
        t = (flat - b[j]) / h
        p = self.degree
        up = np.ones((flat.size, p + 1))                # t**i and (1 - t)**i, shared by the four bases
        down = np.ones((flat.size, p + 1))
        for i in range(1, p + 1):
            up[:, i] = up[:, i - 1] * t
            down[:, i] = down[:, i - 1] * (1.0 - t)
        out = np.zeros((4, flat.size))
        for k, d in enumerate(self._derivatives):      # a derivative above the degree is 0
            q = p - k
            out[k] = np.einsum("ni,ni,ni->n", d[j], up[:, :q + 1], down[:, q::-1]) / h**k
        return tuple(row.reshape(np.shape(u)) for row in out)
