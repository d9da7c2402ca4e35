"""The classical laws: boundary values, derivatives against finite differences, continuity."""

from __future__ import annotations

import numpy as np
import pytest

from laws.registry import LAWS, get_law
from laws.standard import Parabolic

NAMES = list(LAWS)
# smooth interiors, away from the breakpoints of the piecewise laws
U = np.linspace(0.013, 0.987, 157)


def test_registry_order():
    assert NAMES == [
        "linear", "parabolic", "harmonic", "cycloidal", "poly345", "poly4567",
        "modified_trapezoid", "modified_sine", "modified_cycloid",
    ]


@pytest.mark.parametrize("name", NAMES)
def test_boundary_values(name):
    s = get_law(name).evaluate(np.array([0.0, 1.0]))
    assert s[0] == pytest.approx([0.0, 1.0], abs=1e-12)


@pytest.mark.parametrize("name", NAMES)
def test_evaluate_shape_and_clipping(name):
    law = get_law(name)
    assert law.evaluate(0.3).shape == (4,)
    assert law.evaluate(np.zeros((2, 3))).shape == (4, 2, 3)
    # outside [0, 1] the values are those at the nearest end
    np.testing.assert_allclose(law.evaluate(-0.5), law.evaluate(0.0))
    np.testing.assert_allclose(law.evaluate(1.5), law.evaluate(1.0))


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("k", [0, 1, 2])
def test_derivatives_match_finite_differences(name, k, central_difference):
    law = get_law(name)
    bps = np.asarray(law.breakpoints)
    u = U[np.all(np.abs(U[:, None] - bps[None, :]) > 1e-4, axis=1)] if bps.size else U
    fd = central_difference(lambda x: law.evaluate(x)[k], u)
    exact = law.evaluate(u)[k + 1]
    scale = max(1.0, np.abs(exact).max())
    np.testing.assert_allclose(fd, exact, atol=2e-6 * scale * 10 ** k)


@pytest.mark.parametrize("name", NAMES)
def test_point_symmetric(name):
    # every named law is symmetric: S(u) = 1 - S(1 - u)
    law = get_law(name)
    np.testing.assert_allclose(law.evaluate(U)[0], 1 - law.evaluate(1 - U)[0], atol=1e-12)


@pytest.mark.parametrize(
    "name, v0, a0",
    [
        ("linear", 1.0, 0.0),
        ("parabolic", 0.0, 4.0),
        ("harmonic", 0.0, np.pi**2 / 2),
        ("cycloidal", 0.0, 0.0),
        ("poly345", 0.0, 0.0),
        ("poly4567", 0.0, 0.0),
    ],
)
def test_end_derivatives(name, v0, a0):
    d = get_law(name).evaluate(np.array([0.0, 1.0]))
    assert d[1] == pytest.approx([v0, v0], abs=1e-12)
    assert d[2] == pytest.approx([a0, -a0], abs=1e-12)


def test_parabolic_continuity_and_jump():
    law = Parabolic()
    left, right = law.evaluate(np.array([0.5 - 1e-12, 0.5])).T
    assert left[0] == pytest.approx(right[0]) and left[1] == pytest.approx(right[1])
    assert (left[2], right[2]) == (4.0, -4.0)


def test_poly4567_jerk_zero_at_ends():
    d = get_law("poly4567").evaluate(np.array([0.0, 1.0]))
    assert d[3] == pytest.approx([0.0, 0.0], abs=1e-9)


def test_laws_are_immutable():
    law = get_law("cycloidal")
    with pytest.raises(AttributeError):
        law.name = "other"
