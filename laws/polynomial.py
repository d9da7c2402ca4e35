"""Polynomial rise laws from boundary conditions.

The polynomial ``S(u) = sum_k c_k u^k`` is fixed by ``S(0) = 0``, ``S(1) = 1``
and any of the first three derivatives (velocity, acceleration, jerk, taken
with respect to ``u``) at either end; its degree is the number of conditions
minus one, and the coefficients solve the linear system of the conditions
exactly (Norton, *Cam Design and Manufacturing Handbook*, ch. 3, the
"polynomial functions" method). With zero velocity and acceleration at both
ends it is the 3-4-5 polynomial, with zero jerk as well the 4-5-6-7.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from math import factorial

import numpy as np

from laws.base import Law
from laws.errors import InputError

__all__ = ["PolynomialLaw"]

_DERIVS = ("velocity", "acceleration", "jerk")


def _conditions(field: str, values) -> list[tuple[int, float]]:
    """``[(order, value), ...]`` from a sequence of up to three optional derivatives."""
    if values is None:
        return []
    if isinstance(values, (str, bytes)) or not isinstance(values, Sequence):
        raise InputError(field, f"must be a sequence (velocity, acceleration, jerk) of numbers or None, got {values!r}")
    if len(values) > 3:
        raise InputError(field, f"takes at most 3 values (velocity, acceleration, jerk), got {len(values)}")
    out = []
    for k, v in enumerate(values, start=1):
        if v is None:
            continue
        try:
            x = float(v)
        except (TypeError, ValueError):
            raise InputError(f"{field}[{k - 1}]", f"{_DERIVS[k - 1]} must be a number or None, got {v!r}") from None
        if not np.isfinite(x):
            raise InputError(f"{field}[{k - 1}]", f"{_DERIVS[k - 1]} must be finite, got {v!r}")
        out.append((k, x))
    return out


@dataclass(frozen=True)
class PolynomialLaw(Law):
    """A polynomial rise ``S(u) = sum_k c_k u^k``, ``u`` in [0, 1].

    Parameters
    ----------
    coefficients : tuple of float
        ``c_0, c_1, ...`` in increasing powers of ``u`` (dimensionless);
        they must give ``S(0) = 0`` and ``S(1) = 1``.
    name : str
        Name shown in tables.

    Raises
    ------
    InputError
        Coefficients that are not finite numbers or miss ``S(0) = 0``,
        ``S(1) = 1`` (field ``"polynomial.coefficients"``).

    Examples
    --------
    >>> law = PolynomialLaw.from_boundary(start=(0, 0), end=(0, 0))
    >>> [round(c, 9) for c in law.coefficients]
    [0.0, 0.0, 0.0, 10.0, -15.0, 6.0]
    """

    coefficients: tuple[float, ...]
    name: str = "polynomial"

    def __post_init__(self):
        field = "polynomial.coefficients"
        try:
            c = tuple(float(x) for x in self.coefficients)
        except (TypeError, ValueError):
            raise InputError(field, f"must be a sequence of numbers, got {self.coefficients!r}") from None
        if not c or not all(np.isfinite(c)):
            raise InputError(field, f"must be a non-empty sequence of finite numbers, got {self.coefficients!r}")
        scale = max(1.0, max(abs(x) for x in c))
        if abs(c[0]) > 1e-9 * scale or abs(sum(c) - 1.0) > 1e-9 * scale:
            raise InputError(field, f"must give S(0) = 0 and S(1) = 1, got S(0) = {c[0]:.6g}, S(1) = {sum(c):.6g}")
        object.__setattr__(self, "coefficients", c)

    @classmethod
    def from_boundary(cls, *, start=(), end=(), name: str = "polynomial") -> PolynomialLaw:
        """Solve the polynomial fixed by end conditions.

        Parameters
        ----------
        start, end : sequence of (float or None)
            ``(velocity, acceleration, jerk)`` at ``u = 0`` and ``u = 1``, each
            optional: a shorter sequence or ``None`` leaves the rest free.
            Derivatives with respect to ``u`` (dimensionless); divide the
            physical analogue by ``h / beta^k`` to get them.
        name : str, keyword-only
            Name shown in tables.

        Returns
        -------
        PolynomialLaw
            Of degree ``n - 1`` for ``n`` conditions (2 + the given ones).

        Raises
        ------
        InputError
            A condition that is not a finite number (field ``"start[k]"``
            or ``"end[k]"``), or conditions that leave the polynomial
            undetermined (a jerk given without the acceleration, say).

        Examples
        --------
        >>> law = PolynomialLaw.from_boundary(start=(0, 0, 0), end=(0, 0, 0))
        >>> [round(c, 9) for c in law.coefficients[4:]]
        [35.0, -84.0, 70.0, -20.0]
        """
        first = _conditions("start", start)
        last = [(0, 1.0), *_conditions("end", end)]
        n = 1 + len(first) + len(last)
        # conditions at u = 0 fix c_k = S^(k)(0) / k! directly; the rest solve
        # the conditions at u = 1: sum_p p!/(p-k)! c_p = S^(k)(1)
        coeffs = np.zeros(n)
        known = [0] + [k for k, _ in first]
        if max(known) >= n:
            raise InputError(
                "start",
                "these end conditions do not fix a unique polynomial (a higher derivative given without the "
                "lower ones); give the lower derivatives too",
            )
        for k, v in first:
            coeffs[k] = v / factorial(k)
        free = [p for p in range(n) if p not in known]
        a = np.array([[factorial(p) // factorial(p - k) if p >= k else 0 for p in range(n)] for k, _ in last], float)
        b = np.array([v for _, v in last]) - a[:, known] @ coeffs[known]
        af = a[:, free]
        if np.linalg.matrix_rank(af) < len(free):
            raise InputError(
                "end",
                "these end conditions do not fix a unique polynomial (a higher derivative given without the "
                "lower ones); give the lower derivatives too",
            )
        coeffs[free] = np.linalg.solve(af, b)
        return cls(tuple(float(c) for c in coeffs), name=name)

    @property
    def degree(self) -> int:
        """Degree of the polynomial."""
        return len(self.coefficients) - 1

    def _evaluate(self, u):
        p = np.polynomial.polynomial
        c = np.asarray(self.coefficients)
        out = []
        for _ in range(4):
            out.append(p.polyval(u, c) if c.size else np.zeros_like(u))
            c = p.polyder(c) if c.size > 1 else np.zeros(1)
        return tuple(out)
