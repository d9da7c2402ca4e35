"""One-dimensional searches on a bracket: a minimum and a root, both by Brent's methods, and a grid's best
sample refined by the former.

For the few places that refine an extremum or a crossing on a small bracket (a law's peak, the best point and
the ends of an arc), and the boundary of a yes/no test (where a zone empties, the least proven ratio, the
deepest keyway): plain Python and numpy, no derivative; ``scipy.optimize`` costs 0.3 s to import, more than
the work it would do here.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

__all__ = ["bounded_minimum", "grid_minimum", "bracketed_root", "bisect_boundary"]


def bounded_minimum(
    f: Callable[[float], float], a: float, b: float, xatol: float = 1e-5, max_evaluations: int = 500
) -> tuple[float, float]:
    """Minimize ``f`` on ``[a, b]`` by Brent's method (golden-section steps and parabolic interpolation).

    The algorithm of Forsythe, Malcolm and Moler, *Computer Methods for Mathematical Computations* (1977),
    procedure ``fmin``, as the usual bounded scalar minimizers implement it (the same steps and tolerances, so
    the same answers to the last digit): a point is accepted within ``sqrt(eps) |x| + xatol / 3`` of the
    minimum of a unimodal ``f``.

    Parameters
    ----------
    f : callable
        ``f(x) -> float``.
    a, b : float
        The bracket, ``a <= b`` (the unit of ``x``).
    xatol : float
        The absolute tolerance on ``x``.
    max_evaluations : int
        A bound on the evaluations of ``f``.

    Returns
    -------
    x, fx : float
        The best point found and ``f`` there.
    """
    sqrt_eps = (2.2e-16) ** 0.5
    golden_mean = 0.5 * (3.0 - 5.0**0.5)
    fulc = a + golden_mean * (b - a)
    nfc, xf = fulc, fulc
    rat = e = 0.0
    fx = f(xf)
    evaluations = 1
    ffulc = fnfc = fx
    xm = 0.5 * (a + b)
    tol1 = sqrt_eps * abs(xf) + xatol / 3.0
    tol2 = 2.0 * tol1
    while abs(xf - xm) > (tol2 - 0.5 * (b - a)):
        golden = True
        if abs(e) > tol1:  # a parabola through the three best points, when its step is acceptable
            golden = False
            r = (xf - nfc) * (fx - ffulc)
            q = (xf - fulc) * (fx - fnfc)
            p = (xf - fulc) * q - (xf - nfc) * r
            q = 2.0 * (q - r)
            if q > 0.0:
                p = -p
            q = abs(q)
            r = e
            e = rat
            if abs(p) < abs(0.5 * q * r) and p > q * (a - xf) and p < q * (b - xf):
                rat = (p + 0.0) / q
                x = xf + rat
                if (x - a) < tol2 or (b - x) < tol2:
                    rat = tol1 * (_sign(xm - xf) + ((xm - xf) == 0))
            else:
                golden = True
        if golden:
            e = a - xf if xf >= xm else b - xf
            rat = golden_mean * e
        x = xf + (_sign(rat) + (rat == 0)) * max(abs(rat), tol1)
        fu = f(x)
        evaluations += 1
        if fu <= fx:
            if x >= xf:
                a = xf
            else:
                b = xf
            fulc, ffulc = nfc, fnfc
            nfc, fnfc = xf, fx
            xf, fx = x, fu
        else:
            if x < xf:
                a = x
            else:
                b = x
            if fu <= fnfc or nfc == xf:
                fulc, ffulc = nfc, fnfc
                nfc, fnfc = x, fu
            elif fu <= ffulc or fulc == xf or fulc == nfc:
                fulc, ffulc = x, fu
        xm = 0.5 * (a + b)
        tol1 = sqrt_eps * abs(xf) + xatol / 3.0
        tol2 = 2.0 * tol1
        if evaluations >= max_evaluations:
            break
    return float(xf), float(fx)


def grid_minimum(
    f: Callable[[float], float],
    grid: ArrayLike,
    values: ArrayLike,
    *,
    xatol: float,
    period: float | None = None,
) -> tuple[float, float]:
    """The least value of ``f`` sampled on a grid, refined between the best sample's neighbours.

    The best sample (the first, at a tie) brackets the minimum with its two neighbours; :func:`bounded_minimum`
    searches that bracket and its answer replaces the sample when it is no larger. For a unimodal ``f`` between
    the neighbours this is the minimum to ``xatol``; elsewhere it is never worse than the grid.

    Parameters
    ----------
    f : callable
        ``f(x) -> float``, the function sampled (the unit of ``x``).
    grid : array_like, shape (n,)
        Increasing sample points.
    values : array_like, shape (n,)
        ``f`` at ``grid`` (sampled by the caller, vectorized or not).
    xatol : float
        The refinement's absolute tolerance on ``x``.
    period : float or None
        None: the grid's ends bound the search (an end sample's outer neighbour is itself). Else ``grid`` is
        ``n`` equal steps over one period of a periodic ``f`` (no end repeated) and the bracket is the best
        sample plus or minus ``period / n``, across the grid's ends if need be.

    Returns
    -------
    x, fx : float
        The best point and ``f`` there.
    """
    grid = np.asarray(grid, float)
    values = np.asarray(values, float)
    k = int(np.argmin(values))
    if period is None:
        lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
    else:
        h = period / len(grid)
        lo, hi = grid[k] - h, grid[k] + h
    best = (float(grid[k]), float(values[k]))
    if not hi > lo:  # a grid of one point
        return best
    x, fx = bounded_minimum(f, float(lo), float(hi), xatol=xatol)
    return (x, fx) if fx <= best[1] else best


def _sign(x: float) -> float:
    return 1.0 if x > 0 else -1.0 if x < 0 else 0.0


def bracketed_root(
    f: Callable[[float], float],
    a: float,
    b: float,
    xtol: float = 2e-12,
    rtol: float = 4 * np.finfo(float).eps,
    max_steps: int = 100,
) -> float:
    """A root of the continuous ``f`` between ``a`` and ``b``, where ``f(a)`` and ``f(b)`` differ in sign.

    Brent's method (R. P. Brent, *Algorithms for Minimization without Derivatives*, 1973, ch. 4: inverse
    quadratic interpolation or the secant, a bisection step whenever they would not shrink the bracket enough),
    with the steps and the stopping rule of the usual implementation, so the same root to the last digit: the
    bracket is within ``xtol + rtol |x|`` (the unit of ``x``) or ``f`` is exactly 0 (or after ``max_steps``).

    Raises
    ------
    ValueError
        ``f(a)`` and ``f(b)`` have the same sign.
    """
    xpre, xcur = float(a), float(b)
    xblk = fblk = spre = scur = 0.0
    fpre, fcur = float(f(xpre)), float(f(xcur))
    if fpre == 0:
        return xpre
    if fcur == 0:
        return xcur
    if math.copysign(1.0, fpre) == math.copysign(1.0, fcur):
        raise ValueError("f(a) and f(b) must differ in sign")
    for _ in range(max_steps):
        if fpre != 0 and fcur != 0 and math.copysign(1.0, fpre) != math.copysign(1.0, fcur):
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):  # the best point is xcur
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2
        sbis = (xblk - xcur) / 2
        if fcur == 0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:  # the secant
                stry = -fcur * (xcur - xpre) / (fcur - fpre)
            else:  # inverse quadratic interpolation
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2 * abs(stry) < min(abs(spre), 3 * abs(sbis) - delta):
                spre, scur = scur, stry
            else:
                spre = scur = sbis
        else:
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0 else -delta)
        fcur = float(f(xcur))
    return xcur


def bisect_boundary(
    holds: Callable[[float], bool],
    good: float,
    bad: float,
    *,
    xtol: float = 0.0,
    max_steps: int | None = None,
) -> float:
    """Where a yes/no test stops holding, by bisection: the last point found at which it holds.

    ``holds(good)`` is true and ``holds(bad)`` false (neither is evaluated; ``good`` may lie on either side of
    ``bad``). The midpoint of the bracket replaces the end with its answer until the bracket is no wider than
    ``xtol`` (the unit of x), after ``max_steps`` halvings (None: no limit), or when the midpoint rounds to an
    end (no float lies between them).

    Parameters
    ----------
    holds : callable
        The test, ``float -> bool``; evaluated once per halving, at the midpoint only.
    good, bad : float
        The bracket's ends: where the test holds, where it does not.
    xtol : float
        The bracket's width at which to stop, >= 0 (0: only ``max_steps`` or the floats' resolution stop it).
    max_steps : int or None
        The most halvings.

    Returns
    -------
    float
        The end of the final bracket where the test holds (``good`` itself when no midpoint held).

    Examples
    --------
    >>> bisect_boundary(lambda x: x * x <= 2.0, 0.0, 2.0, xtol=1e-12)  # doctest: +ELLIPSIS
    1.41421356237...
    >>> bisect_boundary(lambda x: x >= 0.3, 1.0, 0.0, max_steps=2)  # 0.5, then 0.25 (fails)
    0.5
    """
    steps = 0
    while abs(good - bad) > xtol and (max_steps is None or steps < max_steps):
        mid = 0.5 * (good + bad)
        if mid in (good, bad):
            break
        if holds(mid):
            good = mid
        else:
            bad = mid
        steps += 1
    return good
