"""The reference pressure angle (tests/validation/reference.py) against known answers.

The reference is built from positions only (kinematic inversion and finite
differences, see its module docstring); these tests pin it to textbook
closed forms before it is used to judge the solvers.

Translating follower, derivation of the offset formula in the product's frame
(origin at A0, Y along the rise, X to the right; offset e > 0 when the
follower axis lies on the +X side of the cam centre; cam sense eps = +1 CCW):
the cam centre is ``O = (-e, -d0)`` with ``d0 = sqrt(R0^2 - e^2)``, the roller
centre ``A = (0, s)``, ``r = A - O = (e, d0 + s)``. Per unit cam speed the cam
point under the roller moves with ``eps k x r = eps (-(d0 + s), e)``; the
roller's velocity relative to the cam is ``W = (0, s') - eps (-(d0 + s), e)
= (eps (d0 + s), s' - eps e)``. The contact normal is perpendicular to W and
the follower moves along Y, so the angle between normal and Y equals the
angle between W and X:

    tan(gamma) = |s' - eps e| / (sqrt(R0^2 - e^2) + s)

i.e. the textbook ``(ds/dphi -+ e)/(sqrt(R0^2 - e^2) + s)`` with the sign
``eps``: an axis on the +X side helps a CCW cam on the rise (the cam point
under the roller moves up with ``eps e``) and hurts it on the return.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.io.designfile import design_from_dict

from .designs import rocker, translating_dict
from .reference import ReferenceZone, max_pressure, path, pressure_angles, spec_of

STROKE = 20.0
RISE_DEG = 120.0


def _cv_design(rotation: str, law: str = "linear"):
    return design_from_dict(translating_dict(stroke=STROKE, rotation=rotation, rise=(law, RISE_DEG), dwell=60.0,
                                             ret=(law, RISE_DEG), closure="form"))


@pytest.mark.parametrize("rotation, eps", [("ccw", 1), ("cw", -1)])
@pytest.mark.parametrize("R0", [25.0, 40.0, 90.0])
def test_centric_constant_velocity_textbook(rotation, eps, R0):
    """Centric translating follower, constant-velocity rise and return: tan g = (ds/dphi)/(R0 + s).

    Independent: closed form of the textbook; the reference uses inverted
    positions only. Both cam senses (a centric cam is symmetric) and both
    phases (return: s measured from the near dwell, |ds/dphi| the same).
    """
    d = _cv_design(rotation)
    O = np.array([0.0, -R0])
    u = np.linspace(0.0, 1.0, 41)
    v = STROKE / np.radians(RISE_DEG)
    g_rise = pressure_angles(d, O, 0, u)
    g_ret = pressure_angles(d, O, 2, u)
    np.testing.assert_allclose(g_rise, np.arctan(v / (R0 + STROKE * u)), atol=1e-9, rtol=0)
    np.testing.assert_allclose(g_ret, np.arctan(v / (R0 + STROKE * (1 - u))), atol=1e-9, rtol=0)


@pytest.mark.parametrize("rotation, eps", [("ccw", 1), ("cw", -1)])
@pytest.mark.parametrize("e", [-12.0, -4.0, 4.0, 9.0, 12.0])
def test_offset_constant_velocity_sign_convention(rotation, eps, e):
    """Offset follower: tan g = |ds/dphi - eps e| / (sqrt(R0^2 - e^2) + s) (derived in the module docstring).

    Also checks that the other sign is wrong (it differs by far more than the
    tolerance), so the convention is pinned, and that on the rise an offset
    with ``eps e > 0`` lowers the angle below the centric one. ``e = 12``
    exceeds ds/dphi = 9.55: the signed tangent changes sign, gamma is its
    absolute value (the force still pushes).
    """
    d = _cv_design(rotation)
    R0 = 40.0
    d0 = np.sqrt(R0**2 - e**2)
    O = np.array([-e, -d0])
    u = np.linspace(0.0, 1.0, 41)
    s = STROKE * u
    v = STROKE / np.radians(RISE_DEG)
    g = pressure_angles(d, O, 0, u)
    expected = np.arctan(np.abs(v - eps * e) / (d0 + s))
    wrong = np.arctan(np.abs(v + eps * e) / (d0 + s))
    np.testing.assert_allclose(g, expected, atol=1e-9, rtol=0)
    assert np.min(np.abs(g - wrong)) > 1e-3
    # return: velocity -v, the other groove wall pushes
    g_ret = pressure_angles(d, O, 2, u)
    np.testing.assert_allclose(g_ret, np.arctan(np.abs(-v - eps * e) / (d0 + STROKE * (1 - u))), atol=1e-9, rtol=0)
    centric = np.arctan(v / (R0 + s))
    if eps * e > 0 and abs(e) < v:
        assert np.all(g < centric)


@pytest.mark.parametrize("law", ["cycloidal", "poly345", "harmonic", "parabolic"])
def test_centric_textbook_with_analytic_velocity(law):
    """Centric follower with curved laws: tan g = s'(phi)/(R0 + s), s' from the law's analytic derivative.

    Independent: the reference differentiates positions numerically (one-sided
    stencils at the phase ends); the expected value uses the law's analytic
    velocity. Checks the finite differences to 1e-8 rad over the whole phase,
    ends included.
    """
    d = _cv_design("ccw", law)
    R0 = 30.0
    u = np.linspace(0.0, 1.0, 201)
    m = d.program.evaluate_phase(0, u)
    g = pressure_angles(d, np.array([0.0, -R0]), 0, u)
    np.testing.assert_allclose(g, np.arctan(np.abs(m.ds) / (R0 + m.s)), atol=1e-8, rtol=0)


def test_cam_pulling_is_the_wrong_branch():
    """Cam centre on the far side (above the roller): gamma > 90 deg on the rise (the cam would pull)."""
    d = _cv_design("ccw", "cycloidal")
    g = pressure_angles(d, np.array([0.0, 60.0]), 0, np.linspace(0.05, 0.95, 19))
    assert np.all(g > np.pi / 2)


@pytest.mark.parametrize("rise_direction", ["cw", "ccw"])
@pytest.mark.parametrize("rotation", ["cw", "ccw"])
def test_rocker_at_rest_is_radial(rise_direction, rotation):
    """Rocker at the start of a cycloidal rise (psi' = 0): the normal is radial, gamma = angle(A0 - O, e0).

    Independent closed form: with no follower motion the relative velocity is
    the cam's rotation alone, the pitch curve is locally a circle about O and
    the force acts along A0 - O; e0 = (0, sigma) is A's direction of motion.
    """
    d = rocker(rise_direction=rise_direction, rotation=rotation)
    sigma = 1 if rise_direction == "ccw" else -1
    e0 = np.array([0.0, float(sigma)])
    A0 = path(spec_of(d), 0.0)
    rng = np.random.default_rng(7)
    for _ in range(10):
        O = A0 + rng.uniform(5, 80) * np.array([np.cos(a := rng.uniform(0, 2 * np.pi)), np.sin(a)])
        r = (A0 - O) / np.linalg.norm(A0 - O)
        expected = np.arccos(np.clip(r @ e0, -1, 1))
        assert pressure_angles(d, O, 0, [0.0])[0] == pytest.approx(expected, abs=1e-9)
        # end of the return (back at rest in A0): force -n and velocity -e0, the same angle
        assert pressure_angles(d, O, 2, [1.0])[0] == pytest.approx(expected, abs=1e-9)


def test_many_centres_version_matches_the_literal_one():
    """ReferenceZone (linear-in-O form of the same finite difference) agrees with pressure_angles point by point."""
    d = rocker(rise=("poly345", 110.0), ret=("harmonic", 95.0), closure="form", limit=40.0, return_limit=55.0)
    z = ReferenceZone(d, 50)
    rng = np.random.default_rng(3)
    C = np.array([125.0, 0.0]) + rng.uniform(-60, 60, size=(25, 2))
    u = np.linspace(0.0, 1.0, 51)
    lit = np.concatenate([pressure_angles(d, O, 0, u)[None] for O in C])
    lit_r = np.concatenate([pressure_angles(d, O, 2, u)[None] for O in C])
    vec = np.arccos(np.clip(z.cos_gamma(C), -1, 1))
    np.testing.assert_allclose(vec, np.hstack([lit, lit_r]), atol=1e-9, rtol=0)
    lims = np.r_[np.full(51, np.radians(40.0)), np.full(51, np.radians(55.0))]
    np.testing.assert_array_equal(z.admissible(C), np.all(vec <= lims, axis=1))


def test_step_size_does_not_matter(monkeypatch):
    """The finite-difference steps are converged: halving them changes gamma by < 1e-9 rad."""
    from . import reference

    d = rocker(rise=("poly4567", 90.0), ret=("cycloidal", 100.0), closure="form")
    O = np.array([130.0, 20.0])
    u = np.linspace(0.0, 1.0, 101)
    base = np.r_[pressure_angles(d, O, 0, u), pressure_angles(d, O, 2, u)]
    monkeypatch.setattr(reference, "H_PHI", reference.H_PHI / 2)
    monkeypatch.setattr(reference, "D_PATH", reference.D_PATH / 2)
    half = np.r_[pressure_angles(d, O, 0, u), pressure_angles(d, O, 2, u)]
    np.testing.assert_allclose(half, base, atol=1e-9, rtol=0)
    assert max(max_pressure(d, O).values()) >= np.max(base) - 1e-12
