"""Polynomials in Bernstein form: the linear maps a spline law and its design need.

A polynomial of degree ``p`` on one knot span is written in the span's local
variable ``t`` in [0, 1] as ``sum_j b_j B_{j,p}(t)``, with the Bernstein basis
``B_{j,p}(t) = C(p, j) t^j (1 - t)^(p - j)`` (Farouki, "The Bernstein
polynomial basis: a centennial retrospective", CAGD 29, 2012). Two of its
properties carry the motion design:

- *convex hull*: the polynomial lies between the least and the largest of its
  coefficients on the whole span, so a bound on the coefficients bounds the
  polynomial at every point (conservatively);
- *linearity*: derivatives, degree elevation, subdivision of the span, the power
  form and the integral of a product are all linear maps of the coefficients,
  given here as matrices that act on the last axis of a coefficient array
  (``coefficients @ M.T``).

Every matrix is for the local variable ``t``; a span of width ``h`` in the
law's variable ``u`` scales the ``k``-th derivative by ``h**-k``.
"""

from __future__ import annotations

from functools import lru_cache
from math import comb

import numpy as np

__all__ = [
    "to_power",
    "from_power",
    "derivative",
    "derivative_chain",
    "basis",
    "coefficient_bound",
    "elevation",
    "subdivision",
    "gram",
]


def _frozen(a: np.ndarray) -> np.ndarray:
    a.setflags(write=False)
    return a


@lru_cache(maxsize=64)
def to_power(p: int) -> np.ndarray:
    """``(p+1, p+1)`` matrix ``M`` with power coefficients ``a = M @ b`` (``a_k`` of ``t**k``).

    ``B_{j,p}(t) = sum_{k >= j} C(p, j) C(p - j, k - j) (-1)**(k - j) t**k``.

    Examples
    --------
    >>> to_power(2) @ np.array([0.0, 0.5, 1.0])   # the line t in Bernstein form
    array([0., 1., 0.])
    """
    m = np.zeros((p + 1, p + 1))
    for j in range(p + 1):
        for k in range(j, p + 1):
            m[k, j] = comb(p, j) * comb(p - j, k - j) * (-1) ** (k - j)
    return _frozen(m)


@lru_cache(maxsize=64)
def from_power(p: int) -> np.ndarray:
    """``(p+1, p+1)`` matrix with Bernstein coefficients ``b = M @ a`` from power ones: ``b_j = sum_{i <= j}
    C(j, i) / C(p, i) a_i`` (the inverse of :func:`to_power`)."""
    m = np.zeros((p + 1, p + 1))
    for j in range(p + 1):
        for i in range(j + 1):
            m[j, i] = comb(j, i) / comb(p, i)
    return _frozen(m)


@lru_cache(maxsize=64)
def derivative(p: int) -> np.ndarray:
    """``(p, p+1)`` matrix: the derivative's Bernstein coefficients (degree ``p - 1``), ``p (b_{j+1} - b_j)``."""
    m = np.zeros((max(p, 0), p + 1))
    for j in range(p):
        m[j, j], m[j, j + 1] = -p, p
    return _frozen(m)


@lru_cache(maxsize=64)
def derivative_chain(p: int, r: int) -> np.ndarray:
    """``(p-r+1, p+1)`` matrix: the ``r``-th derivative's Bernstein coefficients (:func:`derivative`, ``r`` times)."""
    m = np.eye(p + 1)
    for k in range(r):
        m = derivative(p - k) @ m
    return _frozen(m)


def basis(p: int, t: np.ndarray) -> np.ndarray:
    """``(len(t), p+1)``: the degree-``p`` Bernstein basis ``B_{j,p}(t)`` at local positions ``t``."""
    t = np.asarray(t, float)[:, None]
    j = np.arange(p + 1)[None, :]
    c = np.array([comb(p, i) for i in range(p + 1)], float)[None, :]
    return c * t**j * (1 - t) ** (p - j)


@lru_cache(maxsize=64)
def coefficient_bound(p: int) -> float:
    """A bound ``K`` with ``max_j |b_j| <= K max_{t in [0,1]} |sum_j b_j B_{j,p}(t)|`` for every degree-``p``
    polynomial.

    The coefficients are ``b = V^-1 y`` for the values ``y`` at any ``p + 1`` distinct points (``V`` the
    basis there), so ``max |b| <= ||V^-1||_inf max |y|`` and ``max |y|`` is at most the polynomial's largest
    absolute value on [0, 1]. The points are the Chebyshev extrema mapped to [0, 1] (ends included: ``K = 1``
    for a line, 3 for a parabola); a little is added for the rounding of the inverse.

    Examples
    --------
    >>> round(coefficient_bound(1), 9), round(coefficient_bound(2), 9)
    (1.0, 3.0)
    """
    if p == 0:
        return 1.0
    t = (1 - np.cos(np.pi * np.arange(p + 1) / p)) / 2
    k = float(np.abs(np.linalg.inv(basis(p, t))).sum(axis=1).max())
    return k * (1 + 1e-12 * (p + 1) ** 2)


@lru_cache(maxsize=64)
def elevation(p: int, q: int) -> np.ndarray:
    """``(q+1, p+1)`` matrix: the same polynomial's coefficients at degree ``q >= p``.

    ``b'_i = sum_j C(p, j) C(q - p, i - j) / C(q, i) b_j``.
    """
    if q < p:
        raise ValueError(f"cannot elevate degree {p} to {q}")
    m = np.zeros((q + 1, p + 1))
    for i in range(q + 1):
        for j in range(max(0, i - (q - p)), min(p, i) + 1):
            m[i, j] = comb(p, j) * comb(q - p, i - j) / comb(q, i)
    return _frozen(m)


@lru_cache(maxsize=64)
def subdivision(p: int, pieces: int) -> np.ndarray:
    """``(pieces, p+1, p+1)``: the coefficients on each of ``pieces`` equal parts of the span.

    Piece ``k`` covers ``t`` in ``[k/pieces, (k+1)/pieces]``, in its own local
    variable. The convex-hull bound of the pieces is tighter than the span's:
    the coefficients approach the polynomial's values as the square of the
    piece's width.
    """
    out = np.empty((pieces, p + 1, p + 1))
    for k in range(pieces):
        # a(t) at t = (k + tau) / pieces: power coefficients in tau
        sub = np.zeros((p + 1, p + 1))
        for i in range(p + 1):          # t**i = ((k + tau)/pieces)**i
            for r in range(i + 1):
                sub[r, i] = comb(i, r) * float(k) ** (i - r) / float(pieces) ** i
        out[k] = from_power(p) @ sub @ to_power(p)
    return _frozen(out)


@lru_cache(maxsize=64)
def gram(p: int) -> np.ndarray:
    """``(p+1, p+1)`` matrix ``G`` with ``integral_0^1 f g dt = b_f @ G @ b_g`` for two degree-``p`` polynomials.

    ``G_ij = C(p, i) C(p, j) / ((2p + 1) C(2p, i + j))``.
    """
    g = np.empty((p + 1, p + 1))
    for i in range(p + 1):
        for j in range(p + 1):
            g[i, j] = comb(p, i) * comb(p, j) / ((2 * p + 1) * comb(2 * p, i + j))
    return _frozen(g)
