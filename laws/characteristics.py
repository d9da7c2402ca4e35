"""Characteristic values Cv, Ca, Cj of the normalized laws.

For a normalized law ``S(u)`` (rise 1 over ``u`` in [0, 1]):
``Cv = max |S'|``, ``Ca = max |S''|``, ``Cj = max |S'''|`` (Norton, *Cam Design
and Manufacturing Handbook*, ch. 3; VDI 2143). The physical peaks of a phase of
rise ``h`` over cam angle ``beta`` (radians) at cam speed ``omega`` (rad/s) are
``Cv h omega / beta``, ``Ca h omega^2 / beta^2``, ``Cj h omega^3 / beta^3``.

Convention: the law is used between dwells. So

- ``Ca`` is infinite when ``S'(0)`` or ``S'(1)`` is not 0 or ``S'`` jumps
  inside (the velocity jumps: hard impact, e.g. constant velocity);
- ``Cj`` is infinite when ``Ca`` is, when ``S''(0)`` or ``S''(1)`` is not 0,
  or when ``S''`` jumps inside (soft impact, e.g. simple harmonic, constant
  acceleration).

The maxima are found by dense sampling (with one-sided values at the law's
breakpoints) and local refinement of the largest samples by Brent's bounded
minimization (:func:`laws.search.bounded_minimum`); results are cached per law.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from laws.base import Law
from laws.diagnostics import law_jumps
from laws.errors import InputError
from laws.search import bounded_minimum

__all__ = ["Characteristics", "characteristics", "law_table"]

#: Uniform samples before refinement.
_SAMPLES = 4096
#: Local maxima refined per derivative.
_REFINE = 4
#: An end derivative counts as zero below this (times max(1, the peak)).
END_TOL = 1e-9


@dataclass(frozen=True)
class Characteristics:
    """Characteristic values of a normalized law (dimensionless).

    Attributes
    ----------
    name : str
        The law's name.
    cv, ca, cj : float
        ``max |S'|``, ``max |S''|``, ``max |S'''|``; ``math.inf`` where the
        law meets a dwell with a jump (see the module's convention).
    """

    name: str
    cv: float
    ca: float
    cj: float

    def as_dict(self) -> dict:
        """``{"name", "Cv", "Ca", "Cj"}`` with ``None`` for an infinite value (JSON-ready)."""

        def fin(x: float) -> float | None:
            return None if math.isinf(x) else float(x)

        return {"name": self.name, "Cv": fin(self.cv), "Ca": fin(self.ca), "Cj": fin(self.cj)}


def _peak(law: Law, k: int) -> float:
    """``max |S^(k)|`` over [0, 1], one-sided limits at breakpoints included."""
    eps = 1e-12
    extra = [x for b in law.breakpoints for x in (b - eps, b + eps) if 0.0 < b < 1.0]
    u = np.unique(np.concatenate([np.linspace(0.0, 1.0, _SAMPLES + 1), extra]))
    f = np.abs(law.evaluate(u)[k])
    best = float(f.max())
    # local maxima of the samples, largest first
    inner = np.nonzero((f[1:-1] >= f[:-2]) & (f[1:-1] >= f[2:]))[0] + 1
    for i in inner[np.argsort(f[inner])[::-1][:_REFINE]]:
        _, neg = bounded_minimum(lambda x: -abs(float(law.evaluate(x)[k])), u[i - 1], u[i + 1], xatol=1e-12)
        best = max(best, -neg)
    return best


@lru_cache(maxsize=256)
def _characteristics_cached(law: Law) -> Characteristics:
    cv, ca, cj = (_peak(law, k) for k in (1, 2, 3))
    ends = law.evaluate(np.array([0.0, 1.0]))
    jumps = law_jumps(law)
    # an end value is zero within END_TOL of the law's own scale there: the derivative and the next one's peak
    # (a designed spline's ends carry the rounding of its many spans' integration, of the size of the latter)
    hard = any(abs(v) > END_TOL * max(1.0, cv, ca) for v in ends[1]) or any(j.kind == "hard" for j in jumps)
    soft = hard or any(abs(a) > END_TOL * max(1.0, ca, cj) for a in ends[2]) or any(j.kind == "soft" for j in jumps)
    return Characteristics(law.name, cv, math.inf if hard else ca, math.inf if soft else cj)


def characteristics(law: Law) -> Characteristics:
    """Cv, Ca, Cj of a normalized law.

    Parameters
    ----------
    law : Law
        Normalized law (dimensionless ``S(u)``, ``u`` in [0, 1]).

    Returns
    -------
    Characteristics
        Dimensionless peaks; infinite values follow the module's convention
        (the law is used between dwells). Cached per law.

    Examples
    --------
    >>> from laws.registry import get_law
    >>> c = characteristics(get_law("cycloidal"))
    >>> round(c.cv, 6), round(c.ca, 6), round(c.cj, 4)
    (2.0, 6.283185, 39.4784)
    >>> characteristics(get_law("harmonic")).cj
    inf
    """
    if not isinstance(law, Law):
        raise InputError("law", f"must be a Law, got {type(law).__name__}")
    try:
        return _characteristics_cached(law)
    except TypeError:  # an unhashable law: compute without the cache
        return _characteristics_cached.__wrapped__(law)


def law_table() -> list[dict]:
    """Characteristic values of every named law, in the order of :data:`laws.registry.LAWS`.

    Returns
    -------
    list of dict
        ``{"name": str, "Cv": float, "Ca": float or None, "Cj": float or None}``,
        dimensionless; ``None`` where the value is infinite.

    Examples
    --------
    >>> rows = law_table()
    >>> rows[0]
    {'name': 'linear', 'Cv': 1.0, 'Ca': None, 'Cj': None}
    """
    from laws.registry import LAWS

    return [characteristics(law).as_dict() for law in LAWS.values()]
