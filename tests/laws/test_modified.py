"""The modified laws: ends, continuity across breakpoints, closed-form constants, published shapes."""

from __future__ import annotations

import numpy as np
import pytest

from laws.modified import ModifiedCycloid, ModifiedSine, ModifiedTrapezoid

LAWS = [ModifiedTrapezoid(), ModifiedSine(), ModifiedCycloid()]
IDS = [law.name for law in LAWS]


@pytest.mark.parametrize("law", LAWS, ids=IDS)
def test_ends_meet_dwells(law):
    d = law.evaluate(np.array([0.0, 1.0]))
    np.testing.assert_allclose(d[0], [0.0, 1.0], atol=1e-14)
    np.testing.assert_allclose(d[1], [0.0, 0.0], atol=1e-14)
    np.testing.assert_allclose(d[2], [0.0, 0.0], atol=1e-13)


@pytest.mark.parametrize("law", LAWS, ids=IDS)
def test_continuous_up_to_acceleration_at_breakpoints(law):
    eps = 1e-10
    for b in law.breakpoints:
        left, right = law.evaluate(np.array([b - eps, b + eps])).T
        # S, S', S'' continuous: their change over 2 eps is bounded by the next derivative
        np.testing.assert_allclose(left[:3], right[:3], atol=1e-7)


@pytest.mark.parametrize("law", LAWS, ids=IDS)
def test_monotone_rise(law):
    d = law.evaluate(np.linspace(0, 1, 2001))
    assert np.all(d[1] >= -1e-15)
    assert np.all(np.diff(d[0]) >= -1e-15)


def test_modified_sine_displacement_published_form():
    # Rothbart, Cam Design Handbook (McGraw-Hill, 2004), p. 75, as quoted in a
    # public forum thread (the book itself not at hand):
    # y/h = (pi x - sin(4 pi x) / 4) / (4 + pi) on [0, 1/8],
    # y/h = (2 + pi x - 9/4 sin(4 pi x / 3 + pi / 3)) / (4 + pi) on [1/8, 7/8],
    # y/h = (4 + pi x - sin(4 pi x) / 4) / (4 + pi) on [7/8, 1].
    x = np.linspace(0, 1, 801)
    pi = np.pi
    ref = np.select(
        [x <= 1 / 8, x <= 7 / 8],
        [pi * x - np.sin(4 * pi * x) / 4, 2 + pi * x - 9 / 4 * np.sin(4 * pi * x / 3 + pi / 3)],
        4 + pi * x - np.sin(4 * pi * x) / 4,
    ) / (4 + pi)
    np.testing.assert_allclose(ModifiedSine().evaluate(x)[0], ref, atol=1e-13)


def test_modified_trapezoid_constant_acceleration_segment():
    # Norton: constant acceleration over [1/8, 3/8] and -A over [5/8, 7/8]
    law = ModifiedTrapezoid()
    d = law.evaluate(np.array([0.2, 0.3, 0.7, 0.8]))
    np.testing.assert_allclose(d[2], [law.A, law.A, -law.A, -law.A])
    np.testing.assert_allclose(d[3], 0.0, atol=1e-12)
    assert law.A == pytest.approx(8 * np.pi / (np.pi + 2))


def test_modified_sine_acceleration_peaks_at_one_eighth():
    law = ModifiedSine()
    d = law.evaluate(np.array([1 / 8, 7 / 8]))
    np.testing.assert_allclose(d[2], [law.A, -law.A])


def test_modified_cycloid_constant_velocity_middle():
    d = ModifiedCycloid().evaluate(np.linspace(0.25, 0.75, 11))
    np.testing.assert_allclose(d[1], 4 / 3)
    np.testing.assert_allclose(d[2], 0.0, atol=1e-12)


def test_half_is_half():
    for law in LAWS:
        assert float(law.evaluate(0.5)[0]) == pytest.approx(0.5, abs=1e-14)
