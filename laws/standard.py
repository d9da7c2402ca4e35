"""The classical closed-form rise laws.

Formulas: Norton, *Cam Design and Manufacturing Handbook*, ch. 3; every law
is normalized, ``S(0) = 0``, ``S(1) = 1``, ``u`` in [0, 1].
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from typing import ClassVar

import numpy as np

from laws.base import Law

__all__ = ["Linear", "Parabolic", "Harmonic", "Cycloidal", "Poly345", "Poly4567"]

PI = np.pi


@dataclass(frozen=True)
class Linear(Law):
    """Constant velocity: ``S = u`` (hard impacts at both ends)."""

    name: str = "linear"

    def _evaluate(self, u):
        z = np.zeros_like(u)
        return u.copy(), np.ones_like(u), z, z.copy()


@dataclass(frozen=True)
class Parabolic(Law):
    """Constant acceleration (parabolic): ``S = 2u^2`` then ``1 - 2(1-u)^2``."""

    name: str = "parabolic"
    breakpoints: ClassVar[tuple[float, ...]] = (0.5,)

    def _evaluate(self, u):
        first = u < 0.5
        w = 1.0 - u
        s = np.where(first, 2 * u * u, 1 - 2 * w * w)
        s1 = np.where(first, 4 * u, 4 * w)
        s2 = np.where(first, 4.0, -4.0)
        return s, s1, s2, np.zeros_like(u)


@dataclass(frozen=True)
class Harmonic(Law):
    """Simple harmonic: ``S = (1 - cos(pi u)) / 2``."""

    name: str = "harmonic"

    def _evaluate(self, u):
        c, s = np.cos(PI * u), np.sin(PI * u)
        return (1 - c) / 2, PI / 2 * s, PI**2 / 2 * c, -(PI**3) / 2 * s


@dataclass(frozen=True)
class Cycloidal(Law):
    """Cycloidal: ``S = u - sin(2 pi u) / (2 pi)``."""

    name: str = "cycloidal"

    def _evaluate(self, u):
        c, s = np.cos(2 * PI * u), np.sin(2 * PI * u)
        return u - s / (2 * PI), 1 - c, 2 * PI * s, 4 * PI**2 * c


@cache
def _derivative_matrix(coeffs: tuple[float, ...]) -> np.ndarray:
    """Power-basis coefficients of S and its first three derivatives, as columns (n, 4)."""
    p = np.polynomial.polynomial
    out = np.zeros((len(coeffs), 4))
    c = np.asarray(coeffs, dtype=float)
    for k in range(4):
        out[: len(c), k] = c
        c = p.polyder(c) if len(c) > 1 else np.zeros(1)
    out.setflags(write=False)
    return out


def _poly(coeffs: tuple[float, ...], u: np.ndarray):
    """Evaluate ``sum c_k u^k`` and its first three derivatives (one matrix product)."""
    C = _derivative_matrix(tuple(coeffs))
    # the powers u^0 .. u^(n-1) by repeated products (a power function per element is slower)
    U = np.empty((*u.shape, C.shape[0]))
    U[..., 0] = 1.0
    for k in range(1, C.shape[0]):
        U[..., k] = U[..., k - 1] * u if k > 1 else u
    Y = U @ C
    return Y[..., 0], Y[..., 1], Y[..., 2], Y[..., 3]


@dataclass(frozen=True)
class Poly345(Law):
    """3-4-5 polynomial: ``S = 10u^3 - 15u^4 + 6u^5``."""

    name: str = "poly345"

    def _evaluate(self, u):
        return _poly((0, 0, 0, 10, -15, 6), u)


@dataclass(frozen=True)
class Poly4567(Law):
    """4-5-6-7 polynomial: ``S = 35u^4 - 84u^5 + 70u^6 - 20u^7``."""

    name: str = "poly4567"

    def _evaluate(self, u):
        return _poly((0, 0, 0, 0, 35, -84, 70, -20), u)
