"""Hertz's line contact of two cylinders (the cam's profile and its roller, or the cam and a flat face).

Units: lengths mm, forces N, stresses and moduli MPa (N/mm^2). Two long cylinders of radii of curvature ``rho1``,
``rho2`` pressed together by a force ``w`` per unit length (N/mm) touch over a strip of half-width ``b`` under the
elliptic pressure ``p(x) = p0 sqrt(1 - x^2/b^2)`` (K. L. Johnson, *Contact Mechanics*, section 4.2)::

    1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2          the contact modulus E* (this module's only modulus)
    1/R  = 1/rho1 + 1/rho2                           the effective radius
    b    = sqrt(4 w R / (pi E*)),   p0 = sqrt(w E* / (pi R)) = 2 w / (pi b)

Sign conventions: a radius of curvature is positive on a convex surface, negative on a concave one (the cam's
concave flank: ``rho1 < 0``); a plane (a flat face) has ``rho = inf``, ``1/rho = 0``. The EHL formulas
(:mod:`cams.strength.film`) use the **reduced modulus E' = 2 E*** of their literature: a factor of two is the
classic slip, so each function names which one it takes.

Below the surface the stresses are McEwen's closed form (Johnson eq. 4.49-4.50), plane strain
(``sigma_y = nu (sigma_x + sigma_z)``): the largest principal shear ``tau_1 = sqrt(((sigma_x - sigma_z)/2)^2 +
tau_xz^2)`` is 0.300 p0 at depth 0.786 b below the centre, the largest von Mises stress 0.5575 p0 at 0.7043 b for
nu = 0.3; :func:`subsurface_maxima` finds both on the field, not from these numbers.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from laws.search import grid_minimum

__all__ = [
    "contact_modulus",
    "effective_radius",
    "half_width",
    "max_pressure",
    "subsurface_field",
    "von_mises",
    "SubsurfaceMaxima",
    "subsurface_maxima",
]


def contact_modulus(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """The contact modulus E* (MPa): ``1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2`` (moduli in MPa).

    Not the EHL literature's E' = 2 E*. Steel on steel (206 GPa, 0.3): E* = 206e3 / (2 (1 - 0.09)) = 113187 MPa.
    """
    return float(1.0 / ((1.0 - nu1**2) / E1 + (1.0 - nu2**2) / E2))


def effective_radius(rho1, rho2) -> np.ndarray:
    """The effective radius R (mm): ``1/R = 1/rho1 + 1/rho2``, signed radii (negative concave, inf a plane).

    ``inf`` for two planes; NaN where ``1/R <= 0`` but not both planes (a concave face at least as sharp as the
    body in it: no line contact, the roller does not fit).
    """
    r1, r2 = np.asarray(rho1, float), np.asarray(rho2, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        k = 1.0 / r1 + 1.0 / r2
        planes = np.isinf(r1) & np.isinf(r2)
        return np.where(k > 0, 1.0 / np.where(k > 0, k, 1.0), np.where(planes, np.inf, np.nan))


def half_width(w, R, E_star: float) -> np.ndarray:
    """The contact's half-width ``b = sqrt(4 w R / (pi E*))`` (mm): force per length ``w`` (N/mm), effective
    radius ``R`` (mm), contact modulus ``E*`` (MPa)."""
    return np.sqrt(4.0 * np.asarray(w, float) * np.asarray(R, float) / (np.pi * E_star))


def max_pressure(w, R, E_star: float) -> np.ndarray:
    """The maximum (central) Hertz pressure ``p0 = sqrt(w E* / (pi R))`` (MPa): ``w`` in N/mm, ``R`` in mm, ``E*``
    the contact modulus in MPa. Scales as sqrt(force) and 1/sqrt(width)."""
    return np.sqrt(np.asarray(w, float) * E_star / (np.pi * np.asarray(R, float)))


def subsurface_field(x, z, b: float = 1.0, p0: float = 1.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """McEwen's stresses under the elliptic pressure of half-width ``b`` and peak ``p0`` (Johnson eq. 4.49-4.50).

    ``x`` along the surface from the strip's centre, ``z > 0`` the depth (lengths as ``b``). Returns
    ``sigma_x, sigma_z, tau_xz`` (as ``p0``; compression negative)::

        m^2 = [sqrt((b^2 - x^2 + z^2)^2 + 4 x^2 z^2) + (b^2 - x^2 + z^2)] / 2,   m the sign of z
        n^2 = [sqrt((b^2 - x^2 + z^2)^2 + 4 x^2 z^2) - (b^2 - x^2 + z^2)] / 2,   n the sign of x
        sigma_x = -(p0/b) [m (1 + (z^2 + n^2)/(m^2 + n^2)) - 2 z]
        sigma_z = -(p0/b) m (1 - (z^2 + n^2)/(m^2 + n^2))
        tau_xz  = -(p0/b) n (m^2 - z^2)/(m^2 + n^2)

    (``tau_xz``'s sign: that of the stress the surface pressure causes on planes of normal x, the same as a line
    load's, Flamant's ``-2 P x z^2 / (pi r^4)``.)
    """
    x = np.asarray(x, float)
    z = np.asarray(z, float)
    a = b * b - x * x + z * z
    root = np.sqrt(a * a + 4.0 * x * x * z * z)
    m = np.sign(z) * np.sqrt(np.maximum(0.5 * (root + a), 0.0))
    n = np.sign(x) * np.sqrt(np.maximum(0.5 * (root - a), 0.0))
    q = (z * z + n * n) / (m * m + n * n)
    k = p0 / b
    sx = -k * (m * (1.0 + q) - 2.0 * z)
    sz = -k * m * (1.0 - q)
    txz = -k * n * (m * m - z * z) / (m * m + n * n)
    return sx, sz, txz


def von_mises(sx, sz, txz, nu: float) -> np.ndarray:
    """The von Mises stress of the plane-strain state ``sigma_x, sigma_z, tau_xz`` with ``sigma_y = nu (sigma_x +
    sigma_z)`` (a long contact)."""
    sy = nu * (sx + sz)
    return np.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3.0 * txz**2)


@dataclass(frozen=True)
class SubsurfaceMaxima:
    """The largest subsurface stresses of a line contact, per ``p0``, and their depths, per ``b``.

    Attributes
    ----------
    shear, shear_depth : float
        The largest principal shear ``tau_1 / p0`` and its depth ``z / b`` (below the strip's centre).
    von_mises, von_mises_depth : float
        The largest von Mises stress ``/ p0`` (plane strain, Poisson's ratio ``nu``) and its depth ``z / b``.
    """

    shear: float
    shear_depth: float
    von_mises: float
    von_mises_depth: float


def _largest(f, lo: float, hi: float) -> tuple[float, float]:
    """The largest value of the unimodal ``f`` on ``[lo, hi]`` and where: a grid, then Brent's bounded search
    (:func:`laws.search.grid_minimum`) between the grid's neighbours of its best point."""
    z = np.linspace(lo, hi, 401)
    zm, neg = grid_minimum(lambda x: -float(f(np.array([x]))[0]), z, -f(z), xatol=1e-12)
    return -neg, zm


@lru_cache(maxsize=32)
def subsurface_maxima(nu: float) -> SubsurfaceMaxima:
    """The largest principal shear and von Mises stress below a line contact (per p0, depths per b), found on
    :func:`subsurface_field` below the strip's centre, where both peak (the field is symmetric and they fall off
    sideways: tested on a grid). Poisson's ratio ``nu`` enters von Mises only."""

    def shear(z):
        sx, sz, txz = subsurface_field(np.zeros_like(z), z)
        return np.sqrt((0.5 * (sx - sz)) ** 2 + txz**2)

    def vm(z):
        return von_mises(*subsurface_field(np.zeros_like(z), z), nu)

    s, sd = _largest(shear, 1e-6, 4.0)
    v, vd = _largest(vm, 1e-6, 4.0)
    return SubsurfaceMaxima(s, sd, v, vd)
