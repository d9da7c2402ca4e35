"""Helpers for the linkage tests: numerical derivatives of positions (tests only)."""

from __future__ import annotations

import numpy as np


def numeric_derivatives(pos, phi, h=1e-3):
    """First and second derivatives of ``pos(phi)`` per radian, by fourth-order central differences.

    ``pos`` maps an array of crank angles to an array (complex or real) of positions.
    """
    phi = np.asarray(phi, dtype=float)
    p0 = pos(phi)
    pp, pm, pp2, pm2 = (pos(phi + k * h) - p0 for k in (1, -1, 2, -2))
    d1 = (8 * (pp - pm) - (pp2 - pm2)) / (12 * h)
    d2 = (16 * (pp + pm) - (pp2 + pm2)) / (12 * h**2)
    return d1, d2


def numeric_angle_derivatives(theta, phi, h=1e-3):
    """As :func:`numeric_derivatives` for an angle, differences wrapped into (-pi, pi]."""
    phi = np.asarray(phi, dtype=float)
    t0 = theta(phi)
    w = lambda x: np.angle(np.exp(1j * (x - t0)))  # noqa: E731
    tp, tm, tp2, tm2 = (w(theta(phi + k * h)) for k in (1, -1, 2, -2))
    d1 = (8 * (tp - tm) - (tp2 - tm2)) / (12 * h)
    d2 = (16 * (tp + tm) - (tp2 + tm2)) / (12 * h**2)
    return d1, d2


def assert_close(a, b, *, rel=1e-6, scale=None):
    """|a - b| <= rel * scale (scale defaults to max |b|)."""
    a, b = np.asarray(a), np.asarray(b)
    s = float(np.max(np.abs(b))) if scale is None else scale
    err = float(np.max(np.abs(a - b)))
    assert err <= rel * max(s, 1e-300), f"max error {err:.3g} > {rel:g} * {s:.3g}"
