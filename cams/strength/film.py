"""The lubricant film of a line contact: entrainment velocity, minimum film thickness, film parameter.

Units: SI inside the formulas (m, m/s, Pa, Pa s, 1/Pa); the functions say what they take and give.

Entrainment velocity ``u = (u1 + u2) / 2``: the mean of the two surfaces' velocities relative to the contact,
along the profile (m/s). A roller **rolls**: both surfaces move at the speed at which the contact travels along the
cam, ``u = omega |dW/dphi|`` (``W`` the working profile, cam frame). A flat face **slides**: its surface moves
relative to the contact at the contact's travel along the face, the cam's at its travel along the cam
(:func:`flat_entrainment`); their mean can pass through zero -- there the film is squeezed, not entrained.

Minimum film thickness of an elastohydrodynamic (EHL) line contact, with the dimensionless groups of the EHL
literature, which use the **reduced modulus E' = 2 E*** (``1/E' = [(1 - nu1^2)/E1 + (1 - nu2^2)/E2] / 2``)::

    U = eta0 u / (E' R),   G = alpha E',   W = w / (E' R)     (w: force per length, N/m; R: effective radius, m)

* D. Dowson, G. R. Higginson, *Elasto-hydrodynamic Lubrication* (SI edition, 1977): ``h_min / R = 2.65 U^0.70
  G^0.54 W^-0.13`` (:func:`dowson_higginson`, the one the product reports);
* B. J. Hamrock's form, from his *Fundamentals of Fluid Film Lubrication* (P. Pan, B. J. Hamrock, "Simple formulas
  for performance parameters used in elastohydrodynamically lubricated line contacts", J. Tribology 111, 1989):
  ``h_min / R = 1.714 W^-0.128 U^0.694 G^0.568`` (:func:`hamrock`).

The film parameter ``Lambda = h_min / sqrt(Rq1^2 + Rq2^2)`` (the surfaces' composite RMS roughness): below about 1
the asperities carry the load (boundary lubrication), above about 3 the film separates the surfaces.
"""

from __future__ import annotations

import numpy as np

__all__ = ["dowson_higginson", "hamrock", "composite_roughness", "film_parameter", "flat_entrainment", "zero_crossings"]


def _groups(u, R, w, E_prime: float, viscosity: float, pressure_viscosity: float):
    U = viscosity * np.abs(np.asarray(u, float)) / (E_prime * np.asarray(R, float))
    G = pressure_viscosity * E_prime
    W = np.asarray(w, float) / (E_prime * np.asarray(R, float))
    return U, G, W


def dowson_higginson(u, R, w, E_prime: float, viscosity: float, pressure_viscosity: float) -> np.ndarray:
    """Minimum film thickness (m) by Dowson and Higginson: ``h = 2.65 R U^0.7 G^0.54 W^-0.13``.

    ``u`` entrainment velocity (m/s, its size), ``R`` effective radius (m), ``w`` force per length (N/m),
    ``E_prime`` the reduced modulus E' = 2 E* (Pa), ``viscosity`` eta0 (Pa s), ``pressure_viscosity`` alpha
    (1/Pa). Zero where ``u = 0``.
    """
    U, G, W = _groups(u, R, w, E_prime, viscosity, pressure_viscosity)
    return 2.65 * np.asarray(R, float) * U**0.7 * G**0.54 * W**-0.13


def hamrock(u, R, w, E_prime: float, viscosity: float, pressure_viscosity: float) -> np.ndarray:
    """Minimum film thickness (m) by Hamrock's form (Pan and Hamrock): ``h = 1.714 R W^-0.128 U^0.694 G^0.568``;
    the arguments as :func:`dowson_higginson`'s."""
    U, G, W = _groups(u, R, w, E_prime, viscosity, pressure_viscosity)
    return 1.714 * np.asarray(R, float) * W**-0.128 * U**0.694 * G**0.568


def composite_roughness(rq1: float, rq2: float) -> float:
    """The composite RMS roughness ``sqrt(Rq1^2 + Rq2^2)`` (the unit of the two)."""
    return float(np.hypot(rq1, rq2))


def film_parameter(h_min, rq1: float, rq2: float) -> np.ndarray:
    """The film parameter ``Lambda = h_min / sqrt(Rq1^2 + Rq2^2)`` (``h_min`` and the roughnesses in one unit)."""
    return np.asarray(h_min, float) / composite_roughness(rq1, rq2)


def flat_entrainment(cam_travel, face_travel) -> np.ndarray:
    """A sliding contact's entrainment velocity from the contact's travel along each surface.

    ``cam_travel``: the contact's velocity along the cam's surface relative to the cam, ``face_travel`` along the
    face relative to the face, both along the same direction (any unit of velocity). Each surface moves relative to
    the contact at minus its travel, so ``u = -(cam_travel + face_travel) / 2``. A translating face with cam angle
    rate omega has ``cam_travel = eps omega rho`` (rho = R0 + s + s'' the cam's radius of curvature) and
    ``face_travel = eps omega s''``: ``u = -eps omega (R0 + s + 2 s'') / 2`` (:mod:`cams.strength.along`).
    """
    return -0.5 * (np.asarray(cam_travel, float) + np.asarray(face_travel, float))


def zero_crossings(phi: np.ndarray, u: np.ndarray) -> list[float]:
    """The cam angles (radians) where the periodic samples ``u`` at ``phi`` (increasing over one turn) change sign
    or vanish, linearly interpolated between samples; a run of zeros counts once, at its start."""
    phi = np.asarray(phi, float)
    u = np.asarray(u, float)
    out: list[float] = []
    n = len(u)
    for i in range(n):
        j = (i + 1) % n
        a, c = u[i], u[j]
        if a == 0.0 and u[i - 1] != 0.0:
            out.append(float(phi[i]))
        elif a * c < 0.0:
            pj = phi[j] if j else phi[0] + 2.0 * np.pi
            out.append(float(phi[i] + (pj - phi[i]) * a / (a - c)) % (2.0 * np.pi))
    return sorted(out)
