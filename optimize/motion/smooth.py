"""The second stage: among the laws within the optimum's value, the smoothest.

A law the first stage returns is one point of the set of laws that reach its
value; where that set is more than a point (a peak objective, a constraint
that binds on part of the phase only), the solver's point is an arbitrary
vertex and its derivatives may ring for no gain. The second stage keeps every
constraint of the first stage's conservative program (the caps and limits on
the Bernstein coefficients, so the laws it finds hold them at every cam angle,
and the cam of those laws is sized and checked as the first's), adds::

    objective <= (1 + slack) * value_found * (1 + SMOOTH_RTOL)

and minimizes the integral over ``u`` in [0, 1], summed over the free phases,
of the squared derivative after the last continuous one, ``S^(c+1)`` for
continuity ``c`` (the snap for C3, the jerk for C2): the first derivative
the space lets jump at its knots, so that its integral measures how sharply
``S^(c)`` turns. The integral is strictly convex in the law (``S^(c+1)``
fixes ``S`` once its end values are given), so the smoothest law is one law,
not a vertex; rest to rest between dwells, with no constraint binding, it is
the polynomial of degree ``2c + 1`` (Euler-Lagrange: ``S^(2c+2) = 0``; the
3-4-5 law for C2, the 4-5-6-7 law for C3).

``SMOOTH_RTOL`` is the room an interior-point solver needs at slack 0 (the
laws that reach the optimum's value exactly have no interior). The solver
meets the rows to its tolerance only, so the second stage's point is pulled
back toward the first's until the caps hold on the Bernstein coefficients
(:func:`pulled_back`). The caller then checks the second stage's value on its
laws against the first's within ``ACCEPT_RTOL`` and keeps the first stage's
laws when it is not met.
"""

from __future__ import annotations

import numpy as np

from optimize.motion.conic import Cone, ConicProgram
from optimize.motion.space import Space

__all__ = ["SMOOTH_RTOL", "ACCEPT_RTOL", "REST_TO_REST", "smoothing_derivative", "integral_factor",
           "allowance", "smoothing_program", "pulled_back"]

#: The room beyond the slack in the second stage's bound on the objective, relative to the value found.
SMOOTH_RTOL = 1e-8
#: The second stage's laws are kept when their checked value is at most (1 + slack) (1 + ACCEPT_RTOL) times
#: the first stage's checked value (else the first stage's laws are): room for SMOOTH_RTOL and the solver's
#: tolerance (the values found differ by 2e-8 at most, relative, on the designs of the tests).
ACCEPT_RTOL = 1e-6


def smoothing_derivative(space: Space) -> int:
    """The derivative whose squared integral the second stage minimizes: ``continuity + 1``."""
    return space.continuity + 1


def integral_factor(space: Space, r: int, n: int) -> np.ndarray:
    """``Q`` with ``|| Q v ||**2`` the sum over the free phases of ``integral_0^1 S_k^(r)(u)**2 du``."""
    return np.vstack([space.integral_factor(k, r, n) for k in range(len(space.free))])


def allowance(value: float, slack: float, root: bool = False) -> float:
    """The second stage's bound on a program's objective ``value``: ``value (1 + slack) (1 + SMOOTH_RTOL)``, or
    its square root's share when the program minimizes the root of an integral (``root``): the integral's share
    is the same. A value below 0 (the pressure iteration's slack) gets the same share of its size as room."""
    share = (1.0 + slack) * (1.0 + SMOOTH_RTOL)
    if root:
        share = float(np.sqrt(share))
    return float(value + abs(value) * (share - 1.0))


#: The least integral of ``S^(c+1)**2`` over the rest-to-rest laws of continuity ``c`` (dwells on both sides):
#: the polynomials of degree ``2c + 1``, ``3u^2 - 2u^3`` (12), the 3-4-5 law (720), the 4-5-6-7 law (100,800).
REST_TO_REST = {1: 12.0, 2: 720.0, 3: 100800.0}


def smoothing_program(prog: ConicProgram, space: Space, bound: float) -> ConicProgram:
    """The second stage of ``prog`` (a first stage's conservative program).

    Parameters
    ----------
    prog : ConicProgram
        The first stage's program: its rows, cones, equalities and box are kept.
    space : Space
        Its laws' space (the first ``space.size`` variables).
    bound : float
        ``prog.cost @ v <= bound`` is added (:func:`allowance` of the value found).

    Returns
    -------
    ConicProgram
        Over ``prog.n + 1`` variables, the last ``w >= || Q v ||`` minimized: :func:`integral_factor` of
        :func:`smoothing_derivative` over the root of :data:`REST_TO_REST` (one a free phase), so that ``w`` is
        of order 1 at the smoothest laws whatever the space (the solver's tolerances are absolute in it; the
        first stage's laws may be far rougher).
    """
    n = prog.n

    def pad(M: np.ndarray) -> np.ndarray:
        return np.hstack([M, np.zeros((M.shape[0], 1))])

    Q = integral_factor(space, smoothing_derivative(space), n) / np.sqrt(len(space.free)
                                                                         * REST_TO_REST[space.continuity])
    a = np.zeros(n + 1)
    a[-1] = 1.0
    cones = (*(Cone(np.append(c.a, 0.0), c.a0, pad(c.F), c.f) for c in prog.cones),
             Cone(a, 0.0, pad(Q), np.zeros(Q.shape[0])))
    enforce = np.zeros(n, bool) if prog.enforce is None else prog.enforce
    return ConicProgram(cost=a.copy(), G=np.vstack([pad(prog.G), np.append(prog.cost, 0.0)[None, :]]),
                        h=np.append(prog.h, bound), A=pad(prog.A), b=prog.b, lo=np.append(prog.lo, 0.0),
                        hi=np.append(prog.hi, 1e6), cones=cones, enforce=np.append(enforce, False))


def pulled_back(space: Space, caps: dict[tuple[int, int], float], first: np.ndarray, second: np.ndarray) -> np.ndarray:
    """The point of the segment from ``first`` to ``second`` (both on the space's equalities) nearest ``second``
    whose capped derivatives' Bernstein coefficients on every piece are within ``cap (1 - TIGHTEN / 2)``.

    The solver meets the second stage's rows to its tolerance only, and its laws ride the caps as the first
    stage's do; the caps are then met with half the first stage's margin (the rest for the rounding of the
    check on the laws). The programs' sets are convex, so the point stays within the second stage's bound on the
    objective as the two ends are. Rows that ``first`` itself does not meet so are left as they are.
    """
    from optimize.motion.translating import TIGHTEN

    n = first.size
    theta = 1.0
    for (k, r), cap in caps.items():
        R = space.rows(k, r, n)
        a, b = R @ first, R @ second
        top = cap * (1 - TIGHTEN / 2)
        for lim, sign in ((top, 1.0), (top, -1.0)):
            sa, sb = sign * a, sign * b
            over = (sb > lim) & (sa <= lim)
            if np.any(over):
                theta = min(theta, float(np.min((lim - sa[over]) / (sb[over] - sa[over]))))
    return second if theta == 1.0 else first + theta * (second - first)
