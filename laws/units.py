"""Unit conversions and the full turn, shared by every layer (laws is the bottom package).

Angles are radians inside the code (degrees only at the interface); one turn is
:data:`TWO_PI`. Speeds of cams and cranks are given in rev/min (``rpm``) in design and machine
files and used in rad/s (``omega``) in the formulas: ``omega = 2 pi n / 60 =
pi n / 30``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["TWO_PI", "LENGTH_UNITS", "rpm_to_omega", "omega_to_rpm", "turn_degrees"]

#: One turn, radians: the one home of ``2 pi`` for every layer.
TWO_PI = 2.0 * np.pi

LENGTH_UNITS = {"mm": 1e-3}
"""Metres per length unit of a design or machine file: mm, the only unit the files take."""


def rpm_to_omega(rpm: float) -> float:
    """Angular speed in rad/s from a speed in rev/min: ``omega = pi n / 30``.

    Parameters
    ----------
    rpm : float
        Speed n, rev/min. Not checked: a sign is kept (a signed speed gives a
        signed omega).

    Returns
    -------
    float
        Angular speed omega, rad/s.

    Examples
    --------
    >>> round(rpm_to_omega(77.0), 4)
    8.0634
    >>> round(rpm_to_omega(60.0) / np.pi, 12)
    2.0
    """
    return float(np.pi * rpm / 30.0)


def omega_to_rpm(omega: float) -> float:
    """Speed in rev/min from an angular speed in rad/s: ``n = 30 omega / pi``.

    Parameters
    ----------
    omega : float
        Angular speed, rad/s; a sign is kept.

    Returns
    -------
    float
        Speed n, rev/min.

    Examples
    --------
    >>> round(omega_to_rpm(2 * np.pi), 12)
    60.0
    >>> round(omega_to_rpm(rpm_to_omega(123.4)), 12)
    123.4
    """
    return float(omega * 30.0 / np.pi)


def turn_degrees(angle):
    """An angle in radians (a cam angle, any number of turns, or negative) in degrees within one turn, [0, 360).

    The one way every output states where on the cam something lies: ``np.degrees(angle) % 360``, so the
    float is the same wherever it is printed or written. (As with any floating modulo, an angle a rounding
    below 0 gives 360.0.)

    Parameters
    ----------
    angle : float or ndarray
        Radians.

    Returns
    -------
    numpy float or ndarray
        Degrees, the shape of ``angle``.

    Examples
    --------
    >>> float(turn_degrees(-np.pi / 2))
    270.0
    >>> float(turn_degrees(5 * np.pi))
    180.0
    """
    return np.degrees(angle) % 360.0
