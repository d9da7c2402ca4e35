"""Piecewise "modified" rise laws built from sine pulses.

Every law here is normalized (``S(0) = 0``, ``S(1) = 1``, ``u`` in [0, 1]),
starts and ends with zero velocity and acceleration, and is point-symmetric
about ``(1/2, 1/2)``: ``S(u) = 1 - S(1 - u)``. Each is defined by its
acceleration over the first half; velocity and displacement are its exact
integrals (closed form, no numerical differentiation or quadrature), and the
peak acceleration ``A`` follows from ``S(1/2) = 1/2``.

Sources
-------
Modified trapezoid and modified sine: Norton, *Cam Design and Manufacturing
Handbook*, ch. 3 (the SCCA family, b = 1/4, c = 1/2, d = 1/4 and
b = 1/4, c = 0, d = 3/4); Rothbart, *Cam Design Handbook*, ch. 3 (the modified
sine displacement is ``(pi u - sin(4 pi u) / 4) / (4 + pi)`` on [0, 1/8]);
VDI 2143. Closed forms derived here: modified trapezoid ``A = 8 pi / (pi + 2)``
(Ca 4.8881, Cv 2, Cj = 4 pi A = 61.426); modified sine ``A = 4 pi^2 / (pi + 4)``
(Ca 5.5280, Cv = 4 pi / (pi + 4) = 1.7596, Cj = 4 pi A = 69.466).

The modified cycloid is the cycloid split at its velocity peak with a
constant-velocity segment inserted; see :class:`ModifiedCycloid` for why this
form and what is not verified about it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from laws.base import Law

__all__ = ["ModifiedTrapezoid", "ModifiedSine", "ModifiedCycloid"]

PI = np.pi
_W = 4.0 * PI  # angular rate of the 1/8-wide quarter-sine pulses


def _mirror(first_half, u: np.ndarray):
    """Evaluate a point-symmetric law from its first half.

    ``first_half(x)`` returns ``S, S', S'', S'''`` for ``x`` in [0, 1/2];
    for ``u > 1/2`` the law is ``S(u) = 1 - S(1 - u)``, hence
    ``S' (u) = S'(1 - u)``, ``S''(u) = -S''(1 - u)``, ``S'''(u) = S'''(1 - u)``.
    """
    second = u > 0.5
    x = np.where(second, 1.0 - u, u)
    s, s1, s2, s3 = first_half(x)
    s = np.where(second, 1.0 - s, s)
    s2 = np.where(second, -s2, s2)
    return s, s1, s2, s3


def _quarter_pulse(x):
    """Unit quarter-sine acceleration ``sin(4 pi x)`` on [0, 1/8] and its integrals (zero start)."""
    c, s = np.cos(_W * x), np.sin(_W * x)
    return x / _W - s / _W**2, (1 - c) / _W, s, _W * c


# values of the unit pulse at x = 1/8 (end of the first piece)
_S1 = 1.0 / (8 * _W) - 1.0 / _W**2
_V1 = 1.0 / _W


@dataclass(frozen=True)
class ModifiedTrapezoid(Law):
    """Modified trapezoid: quarter-sine acceleration pulses and constant acceleration.

    Acceleration over the first half, with ``A = 8 pi / (pi + 2)``:
    ``A sin(4 pi u)`` on [0, 1/8], ``A`` on [1/8, 3/8],
    ``A cos(4 pi (u - 3/8))`` on [3/8, 1/2]; the second half mirrors it
    with opposite sign. Characteristic values Cv 2, Ca 4.888, Cj 61.43
    (Norton's handbook, ch. 3; VDI 2143). ``u`` dimensionless.
    """

    name: str = "modified_trapezoid"
    breakpoints: ClassVar[tuple[float, ...]] = (0.125, 0.375, 0.5, 0.625, 0.875)
    #: Peak acceleration ``S''`` (dimensionless).
    A: ClassVar[float] = 8 * PI / (PI + 2)

    def _evaluate(self, u):
        return _mirror(self._half, u)

    @classmethod
    def _half(cls, x):
        A = cls.A
        p = _quarter_pulse(x)
        t2 = x - 0.125
        v2 = _V1 + 0.25
        s2_end = _S1 + _V1 * 0.25 + 0.25**2 / 2
        t3 = x - 0.375
        c3, n3 = np.cos(_W * t3), np.sin(_W * t3)
        middle = (_S1 + _V1 * t2 + t2**2 / 2, _V1 + t2, 1.0, 0.0)
        last = (s2_end + v2 * t3 + (1 - c3) / _W**2, v2 + n3 / _W, c3, -_W * n3)
        first, second = x <= 0.125, x <= 0.375
        return tuple(A * np.where(first, p[k], np.where(second, middle[k], last[k])) for k in range(4))


@dataclass(frozen=True)
class ModifiedSine(Law):
    """Modified sine: quarter-sine pulses over the first and last 1/8, a half sine over the middle 3/4.

    Acceleration, with ``A = 4 pi^2 / (pi + 4)``: ``A sin(4 pi u)`` on
    [0, 1/8], ``A cos(4 pi / 3 (u - 1/8))`` on [1/8, 7/8], then
    ``-A sin(4 pi (1 - u))`` on [7/8, 1]. Characteristic values Cv 1.760,
    Ca 5.528, Cj 69.47 (Norton's handbook, ch. 3; Rothbart, ch. 3; VDI 2143).
    ``u`` dimensionless.
    """

    name: str = "modified_sine"
    breakpoints: ClassVar[tuple[float, ...]] = (0.125, 0.875)
    #: Peak acceleration ``S''`` (dimensionless).
    A: ClassVar[float] = 4 * PI**2 / (PI + 4)

    def _evaluate(self, u):
        return _mirror(self._half, u)

    @classmethod
    def _half(cls, x):
        A = cls.A
        k = 4 * PI / 3
        p = _quarter_pulse(x)
        t = x - 0.125
        c, n = np.cos(k * t), np.sin(k * t)
        middle = (_S1 + _V1 * t + (1 - c) / k**2, _V1 + n / k, c, -k * n)
        first = x <= 0.125
        return tuple(A * np.where(first, p[i], middle[i]) for i in range(4))


@dataclass(frozen=True)
class ModifiedCycloid(Law):
    """Modified cycloid: the cycloid split at its velocity peak, constant velocity in between.

    Acceleration: a half sine ``A sin(4 pi u)`` on [0, 1/4] (the first half of
    a cycloid of duration 1/2), zero on [1/4, 3/4] (constant velocity
    ``S' = 4/3``), and ``-A sin(4 pi (1 - u))`` on [3/4, 1], with
    ``A = 8 pi / 3``. Closed-form characteristic values derived here:
    Cv = 4/3, Ca = 8 pi / 3 = 8.3776, Cj = 32 pi^2 / 3 = 105.28.

    Notes
    -----
    The issue asked for Wildt's modified cycloid as given by Norton and
    Rothbart. Neither text could be consulted while writing this, and the
    name is used for different curves in the literature, so this class
    implements the form stated above (the cycloid "modified" by a
    constant-velocity middle, which lowers Cv and so the pressure angle);
    its test values are derived, not quoted. Replace the definition if the
    published Wildt form differs.
    """

    name: str = "modified_cycloid"
    breakpoints: ClassVar[tuple[float, ...]] = (0.25, 0.75)
    #: Peak acceleration ``S''`` (dimensionless).
    A: ClassVar[float] = 8 * PI / 3

    def _evaluate(self, u):
        return _mirror(self._half, u)

    @classmethod
    def _half(cls, x):
        w = 0.25  # width of the acceleration pulse
        k = PI / w
        v = 1.0 / (1.0 - w)  # constant velocity of the middle, from S(1/2) = 1/2
        A = cls.A  # = k v / 2
        c, n = np.cos(k * x), np.sin(k * x)
        pulse = (A / k * (x - n / k), A / k * (1 - c), A * n, A * k * c)
        cv = (v * w / 2 + v * (x - w), np.full_like(x, v), np.zeros_like(x), np.zeros_like(x))
        first = x <= w
        return tuple(np.where(first, pulse[i], cv[i]) for i in range(4))
