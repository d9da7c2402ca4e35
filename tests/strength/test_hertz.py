"""Hertz's line contact against the references: closed forms derived here in another notation, McEwen's subsurface
field against a direct integration of the line-load (Flamant) kernel over the elliptic pressure, the known maxima of
the subsurface shear and von Mises stress, and the scaling of p0 with the width and the force."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate

from cams.strength import hertz

E, NU = 206e3, 0.3  # MPa, steel
F, WIDTH = 2000.0, 10.0  # N, mm


def _norton_p0(F: float, L: float, R1: float, R2: float, E1=E, nu1=NU, E2=E, nu2=NU) -> float:
    """Norton's notation (Machine Design, cylinders in contact): m = (1 - nu^2)/E per body, B = (1/R1 + 1/R2)/2,
    half-width a = sqrt(2 F (m1 + m2) / (pi L B)), p_max = 2 F / (pi a L). A plane: 1/R = 0."""
    m1, m2 = (1 - nu1**2) / E1, (1 - nu2**2) / E2
    B = 0.5 * (1.0 / R1 + 1.0 / R2)
    a = np.sqrt(2 * F * (m1 + m2) / (np.pi * L * B))
    return 2 * F / (np.pi * a * L)


@pytest.mark.parametrize("cam_radius, p0", [(30.0, 980.18), (-60.0, 774.90), (np.inf, 848.86)])
def test_the_issue_s_references(cam_radius, p0):
    """Steel on steel, 2000 N over 10 mm, roller 10 mm on a convex 30 mm, a concave -60 mm and a plane."""
    Es = hertz.contact_modulus(E, NU, E, NU)
    R = hertz.effective_radius(cam_radius, 10.0)
    got = float(hertz.max_pressure(F / WIDTH, R, Es))
    assert got == pytest.approx(p0, abs=0.006)
    assert got == pytest.approx(_norton_p0(F, WIDTH, cam_radius, 10.0), rel=1e-12)


def test_the_contact_modulus_is_e_star_not_e_prime():
    """1/E* = sum (1 - nu^2)/E: steel on steel 206e3 / 1.82; different materials as the sum of compliances."""
    assert hertz.contact_modulus(E, NU, E, NU) == pytest.approx(206e3 / 1.82, rel=1e-14)
    assert hertz.contact_modulus(100e3, 0.25, 200e3, 0.3) == pytest.approx(1 / (0.9375 / 100e3 + 0.91 / 200e3))


def test_the_pressure_carries_the_force_and_the_radius_signs():
    """The elliptic pressure integrates to the force per length; a concave cam face enlarges R, a plane gives the
    roller's radius, a concave face as sharp as the roller no line contact (NaN), two planes inf."""
    Es = hertz.contact_modulus(E, NU, E, NU)
    w, R = F / WIDTH, 7.5
    b = float(hertz.half_width(w, R, Es))
    p0 = float(hertz.max_pressure(w, R, Es))
    total, _ = integrate.quad(lambda x: p0 * np.sqrt(1 - (x / b) ** 2), -b, b)
    assert total == pytest.approx(w, rel=1e-9)
    assert float(hertz.effective_radius(30.0, 10.0)) == pytest.approx(7.5)
    assert float(hertz.effective_radius(-60.0, 10.0)) == pytest.approx(12.0)
    assert float(hertz.effective_radius(np.inf, 10.0)) == 10.0
    assert np.isnan(hertz.effective_radius(-10.0, 10.0)) and np.isnan(hertz.effective_radius(-8.0, 10.0))
    assert np.isinf(hertz.effective_radius(np.inf, np.inf))


def _flamant(x: float, z: float, b: float = 1.0, p0: float = 1.0) -> tuple[float, float, float]:
    """The stresses at (x, z) of the elliptic pressure as a sum of line loads p(s) ds at s (Flamant's solution:
    sigma_x = -2 P (x-s)^2 z / (pi r^4), sigma_z = -2 P z^3 / (pi r^4), tau_xz = -2 P (x-s) z^2 / (pi r^4))."""

    def kern(s, which):
        dx = x - s
        r4 = (dx * dx + z * z) ** 2
        P = p0 * np.sqrt(max(1 - (s / b) ** 2, 0.0))
        num = {"x": dx * dx * z, "z": z**3, "xz": dx * z * z}[which]
        return -2 * P * num / (np.pi * r4)

    return tuple(
        integrate.quad(
            kern, -b, b, args=(k,), points=[x] if -b < x < b else None, limit=400, epsabs=1e-12, epsrel=1e-11
        )[0]
        for k in ("x", "z", "xz")
    )


@pytest.mark.parametrize(
    "x, z", [(0.0, 0.786), (0.0, 0.3), (0.0, 2.0), (0.5, 0.5), (-0.8, 0.3), (1.5, 0.7), (0.9, 0.05)]
)
def test_mcewen_s_field_is_the_line_loads_summed(x, z):
    sx, sz, txz = hertz.subsurface_field(np.array([x]), np.array([z]))
    fx, fz, fxz = _flamant(x, z)
    assert float(sx[0]) == pytest.approx(fx, abs=1e-7)
    assert float(sz[0]) == pytest.approx(fz, abs=1e-7)
    assert float(txz[0]) == pytest.approx(fxz, abs=1e-7)


def test_the_largest_subsurface_stresses():
    """0.300283 p0 at 0.786151 b (the principal shear) and 0.5575 p0 at 0.7043 b (von Mises, nu = 0.3), found on
    the field; a brute-force grid over (x, z) finds nothing larger off the axis."""
    m = hertz.subsurface_maxima(0.3)
    assert m.shear == pytest.approx(0.300283, abs=5e-7)
    assert m.shear_depth == pytest.approx(0.786151, abs=5e-6)
    assert m.von_mises == pytest.approx(0.5575, abs=5e-5)
    assert m.von_mises_depth == pytest.approx(0.7043, abs=5e-5)
    x, z = np.meshgrid(np.linspace(-2, 2, 401), np.linspace(0.01, 2.5, 250))
    sx, sz, txz = hertz.subsurface_field(x, z)
    tau1 = np.sqrt((0.5 * (sx - sz)) ** 2 + txz**2)
    assert tau1.max() <= m.shear + 1e-9
    assert hertz.von_mises(sx, sz, txz, 0.3).max() <= m.von_mises + 1e-9
    # the shear's maximum does not depend on nu; von Mises' does
    assert hertz.subsurface_maxima(0.25).shear == pytest.approx(m.shear, abs=1e-12)
    assert hertz.subsurface_maxima(0.25).von_mises != pytest.approx(m.von_mises, abs=1e-4)


def test_p0_scales_as_one_over_root_width_and_root_force():
    """A forum's 331,228 -> 306,658 -> 286,852 psi at 3/8, 7/16, 1/2 in follows 1/sqrt(width) exactly; doubling the
    force multiplies p0 by sqrt(2)."""
    Es = hertz.contact_modulus(E, NU, E, NU)
    widths = np.array([3 / 8, 7 / 16, 1 / 2]) * 25.4
    p = hertz.max_pressure(F / widths, 7.5, Es)
    forum = np.array([331228.0, 306658.0, 286852.0])
    assert p / p[0] == pytest.approx(forum / forum[0], abs=2e-6)
    assert float(hertz.max_pressure(2 * F / WIDTH, 7.5, Es)) == pytest.approx(
        np.sqrt(2) * float(hertz.max_pressure(F / WIDTH, 7.5, Es)), rel=1e-14
    )
