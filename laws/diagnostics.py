"""Impacts: jumps of velocity and acceleration in a law or a cycle program.

Vocabulary (Norton, *Cam Design and Manufacturing Handbook*, ch. 2; VDI 2143):

- a *hard impact* is a jump of the velocity analogue ``ds/dphi`` (infinite
  acceleration: constant velocity meeting a dwell);
- a *soft impact* is a jump of the acceleration analogue ``d2s/dphi2``
  (infinite jerk: simple harmonic or constant acceleration meeting a dwell,
  and constant acceleration at its own midpoint).

Jumps are taken from one-sided values: at a joint between phases, the end of
the earlier phase (``u = 1``) and the start of the later one (``u = 0``),
including the wrap from the last phase back to the first at ``phi = 0``; inside
a law, at the positions it declares in :attr:`laws.base.Law.breakpoints` and
wherever a scan of the law finds one.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from laws.base import Law
from laws.errors import InputError
from laws.program import TWO_PI, Program

__all__ = ["LawJump", "Impact", "law_jumps", "find_impacts"]

#: Half-width of the one-sided evaluation around a declared breakpoint.
_EPS = 1e-9
#: Samples of the scan for undeclared jumps.
_SCAN = 4096


@dataclass(frozen=True)
class LawJump:
    """A jump inside a normalized law.

    Attributes
    ----------
    u : float
        Position in the law (dimensionless, in (0, 1)).
    kind : {"hard", "soft"}
        ``"hard"``: ``S'`` jumps; ``"soft"``: ``S''`` jumps.
    size : float
        Right limit minus left limit of ``S'`` or ``S''`` (dimensionless).
    """

    u: float
    kind: str
    size: float


@dataclass(frozen=True)
class Impact:
    """A velocity or acceleration jump of a cycle program.

    Attributes
    ----------
    phi : float
        Cam angle of the jump, radians, in [0, 2 pi).
    kind : {"hard", "soft"}
        ``"hard"``: ``ds/dphi`` jumps; ``"soft"``: ``d2s/dphi2`` jumps.
    size : float
        Value after minus value before: lift unit per radian (hard) or per
        radian squared (soft).
    phase : int
        Index of the phase that starts at ``phi`` (a joint) or contains it.
    inside : bool
        True for a jump inside a phase's law, False for a joint between phases.
    """

    phi: float
    kind: str
    size: float
    phase: int
    inside: bool = False


def _refine(law: Law, k: int, a: float, b: float) -> tuple[float, float]:
    """Narrow ``[a, b]`` around a jump of derivative ``k``; return position and size."""
    for _ in range(60):
        m = 0.5 * (a + b)
        va, vm, vb = law.evaluate(np.array([a, m, b]))[k]
        if abs(vm - va) >= abs(vb - vm):
            b = m
        else:
            a = m
        if b - a < 4 * _EPS:
            break
    va, vb = law.evaluate(np.array([a, b]))[k]
    return 0.5 * (a + b), float(vb - va)


@lru_cache(maxsize=256)
def _law_jumps_cached(law: Law) -> tuple[LawJump, ...]:
    u = np.linspace(0.0, 1.0, _SCAN + 1)
    h = u[1] - u[0]
    d = law.evaluate(u)
    found: list[LawJump] = []
    for k, kind in ((1, "hard"), (2, "soft")):
        peak = max(1.0, float(np.max(np.abs(d[k]))))
        tol = 1e-6 * peak
        slope = float(np.max(np.abs(d[k + 1])))
        # declared breakpoints: one-sided values, 2 _EPS apart: a continuous derivative changes by up to
        # 2 _EPS times the next one's peak across them (the scan's, doubled for the peak between samples)
        for b in law.breakpoints:
            if not 0.0 < b < 1.0:
                continue
            lo, hi = law.evaluate(np.array([b - _EPS, b + _EPS]))[k]
            if abs(hi - lo) > tol + 4 * _EPS * slope:
                found.append(LawJump(float(b), kind, float(hi - lo)))
        # scan for jumps nobody declared: a change between neighbours much
        # larger than the next derivative allows
        step = np.abs(np.diff(d[k]))
        big = np.nonzero(step > max(20.0 * h * slope, 1e-3 * peak))[0]
        for i in big:
            if any(j.kind == kind and abs(j.u - u[i]) <= 2 * h for j in found):
                continue
            pos, size = _refine(law, k, float(u[i]), float(u[i + 1]))
            if abs(size) > tol and 0.0 < pos < 1.0:
                found.append(LawJump(pos, kind, size))
    return tuple(sorted(found, key=lambda j: (j.u, j.kind)))


def law_jumps(law: Law) -> tuple[LawJump, ...]:
    """Jumps of ``S'`` (hard) and ``S''`` (soft) strictly inside a law.

    Parameters
    ----------
    law : Law
        Normalized law, ``u`` in [0, 1].

    Returns
    -------
    tuple of LawJump
        Sorted by position; empty for a law smooth inside (0, 1). The ends
        are not included: what happens there depends on the neighbouring
        phases (see :func:`find_impacts`).

    Examples
    --------
    >>> from laws.registry import get_law
    >>> law_jumps(get_law("parabolic"))
    (LawJump(u=0.5, kind='soft', size=-8.0),)
    >>> law_jumps(get_law("cycloidal"))
    ()
    """
    if not isinstance(law, Law):
        raise InputError("law", f"must be a Law, got {type(law).__name__}")
    try:
        return _law_jumps_cached(law)
    except TypeError:  # an unhashable law: compute without the cache
        return _law_jumps_cached.__wrapped__(law)


def find_impacts(program: Program, *, rtol: float = 1e-6) -> list[Impact]:
    """Hard and soft impacts of a cycle program.

    Parameters
    ----------
    program : Program
        The cycle; cam angles in radians.
    rtol : float, keyword-only
        Jumps smaller than ``rtol`` times a reference are ignored (round-off).
        The references are the largest mean velocity ``h / beta`` (lift unit
        per radian) and ``h / beta**2`` (per radian squared) over the rise
        and return phases.

    Returns
    -------
    list of Impact
        Sorted by cam angle; at each joint (the wrap at 360 deg -> 0 included)
        and inside laws with internal jumps (constant acceleration at its
        midpoint).

    Examples
    --------
    >>> import numpy as np
    >>> from laws.program import Phase, Program
    >>> from laws.registry import get_law
    >>> q = np.pi / 2
    >>> p = Program((Phase("rise", q, get_law("harmonic")), Phase("dwell", q),
    ...              Phase("return", q, get_law("cycloidal")), Phase("dwell", q)), lift=1.0)
    >>> [(round(np.degrees(i.phi)), i.kind) for i in find_impacts(p)]
    [(0, 'soft'), (90, 'soft')]
    """
    if not isinstance(program, Program):
        raise InputError("program", f"must be a Program, got {type(program).__name__}")
    if not (np.isfinite(rtol) and rtol >= 0):
        raise InputError("rtol", f"must be a number >= 0, got {rtol!r}")
    moving = [i for i, p in enumerate(program.phases) if p.kind != "dwell"]
    v_ref = max(program.height_of(i) / program.phases[i].angle for i in moving)
    a_ref = max(program.height_of(i) / program.phases[i].angle ** 2 for i in moving)
    starts = program.starts
    n = len(program.phases)
    out: list[Impact] = []
    for j in range(n):
        before = program.evaluate_phase(j - 1 if j else n - 1, 1.0)
        after = program.evaluate_phase(j, 0.0)
        phi = float(starts[j])
        dv = float(after.ds - before.ds)
        da = float(after.d2s - before.d2s)
        if abs(dv) > rtol * v_ref:
            out.append(Impact(phi, "hard", dv, j))
        if abs(da) > rtol * a_ref:
            out.append(Impact(phi, "soft", da, j))
    for i in moving:
        p = program.phases[i]
        sign = 1.0 if p.kind == "rise" else -1.0
        h = program.height_of(i)
        for jump in law_jumps(program.law_of(i)):
            order = 1 if jump.kind == "hard" else 2
            size = sign * h * jump.size / p.angle**order
            if abs(size) > rtol * (v_ref if order == 1 else a_ref):
                phi = float(np.mod(starts[i] + jump.u * p.angle, TWO_PI))
                out.append(Impact(phi, jump.kind, size, i, inside=True))
    return sorted(out, key=lambda m: (m.phi, m.kind))
