"""Bounded one-dimensional minimization by golden-section search, in numpy.

For the few places that refine an extremum on a small bracket (a law's peak, the best point of an arc): the
search needs no derivative and no import beyond numpy (``scipy.optimize`` costs 0.3 s to import, more than the
work it would do here). Many brackets are searched together, one evaluation of the function per step for all.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

__all__ = ["golden_minimum", "bracketed_root"]

#: The golden section's inner fraction, (3 - sqrt 5) / 2.
_G = (3.0 - 5.0**0.5) / 2.0


def golden_minimum(
    f: Callable[[np.ndarray], np.ndarray], a, b, xatol: float = 1e-12, max_steps: int = 200
) -> tuple[np.ndarray, np.ndarray]:
    """Minimize ``f`` on each bracket ``[a_i, b_i]`` by golden-section search.

    Parameters
    ----------
    f : callable
        ``f(x) -> values`` evaluated elementwise on an array of the brackets' shape.
    a, b : array_like
        The brackets' ends (``a <= b``), same shape.
    xatol : float
        The bracket's width at which the search stops (the unit of ``x``).
    max_steps : int
        A bound on the steps (each shrinks the brackets by 0.618).

    Returns
    -------
    x, fx : ndarray
        The best point found in each bracket (its ends included) and ``f`` there. On a unimodal ``f`` the point
        is within ``xatol`` of the bracket's minimum; on any ``f`` the value is one ``f`` takes in the bracket.
    """
    a = np.array(a, float, copy=True, ndmin=1)
    b = np.array(b, float, copy=True, ndmin=1)
    a, b = np.broadcast_arrays(a, b)
    a, b = a.copy(), b.copy()
    # the ends are candidates too: a minimum at an end is found exactly
    best_x = np.concatenate([a, b]).reshape(2, -1)
    best_f = np.asarray(f(best_x.ravel()), float).reshape(2, -1)
    pick = np.argmin(best_f, axis=0)
    bx = best_x[pick, np.arange(a.size)]
    bf = best_f[pick, np.arange(a.size)]
    c = a + _G * (b - a)
    d = b - _G * (b - a)
    fc, fd = (np.asarray(v, float) for v in np.split(np.asarray(f(np.concatenate([c, d])), float), 2))
    for x, fx in ((c, fc), (d, fd)):
        better = fx < bf
        bx, bf = np.where(better, x, bx), np.where(better, fx, bf)
    for _ in range(max_steps):
        if np.all(b - a <= xatol):
            break
        left = fc <= fd  # the minimum is in [a, d]: d becomes the new b, c the new d
        b = np.where(left, d, b)
        a = np.where(left, a, c)
        new = np.where(left, a + _G * (b - a), b - _G * (b - a))
        fnew = np.asarray(f(new), float)
        c, d, fc, fd = (
            np.where(left, new, d),
            np.where(left, c, new),
            np.where(left, fnew, fd),
            np.where(left, fc, fnew),
        )
        better = fnew < bf
        bx, bf = np.where(better, new, bx), np.where(better, fnew, bf)
    return bx, bf


def bracketed_root(
    f: Callable[[float], float],
    a: float,
    b: float,
    xtol: float = 1e-14,
    rtol: float = 4 * np.finfo(float).eps,
    max_steps: int = 200,
) -> float:
    """A root of the continuous ``f`` between ``a`` and ``b``, where ``f(a)`` and ``f(b)`` differ in sign.

    The Illinois variant of regula falsi (the false position, its retained end's value halved when that end
    stays twice), with a bisection step whenever it does not shrink the bracket by half in two steps: it
    converges superlinearly on a smooth ``f`` and never slower than bisection. Stops when the bracket is within
    ``xtol + rtol |x|`` (the unit of ``x``) or ``f`` is exactly 0.
    """
    fa, fb = float(f(a)), float(f(b))
    if fa == 0.0:
        return float(a)
    if fb == 0.0:
        return float(b)
    if fa * fb > 0:
        raise ValueError("f(a) and f(b) must differ in sign")
    side = 0
    width = abs(b - a)
    for step in range(max_steps):
        if abs(b - a) <= xtol + rtol * max(abs(a), abs(b)):
            break
        x = b - fb * (b - a) / (fb - fa) if step % 3 != 2 or abs(b - a) < 0.5 * width else 0.5 * (a + b)
        if step % 3 == 2:
            width = abs(b - a)
        if not (min(a, b) < x < max(a, b)):
            x = 0.5 * (a + b)
        fx = float(f(x))
        if fx == 0.0:
            return float(x)
        if fx * fb < 0:  # the root is between x and b: a takes b's place
            a, fa = b, fb
            side = 0
        else:  # a stays: halve its value when it stays again (Illinois)
            if side == -1:
                fa *= 0.5
            side = -1
        b, fb = x, fx
    return float(b if abs(fb) <= abs(fa) else a)
