"""Polynomial laws from boundary conditions."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from laws.errors import InputError
from laws.polynomial import PolynomialLaw
from laws.registry import get_law

U = np.linspace(0, 1, 101)


def test_345_and_4567_reproduced():
    p345 = PolynomialLaw.from_boundary(start=(0, 0), end=(0, 0))
    p4567 = PolynomialLaw.from_boundary(start=(0, 0, 0), end=(0, 0, 0))
    np.testing.assert_allclose(p345.coefficients, [0, 0, 0, 10, -15, 6], atol=1e-12)
    np.testing.assert_allclose(p4567.coefficients, [0, 0, 0, 0, 35, -84, 70, -20], atol=1e-11)
    np.testing.assert_allclose(p345.evaluate(U), get_law("poly345").evaluate(U), atol=1e-11)
    np.testing.assert_allclose(p4567.evaluate(U), get_law("poly4567").evaluate(U), atol=1e-10)


def test_no_conditions_is_linear():
    law = PolynomialLaw.from_boundary()
    assert law.coefficients == (0.0, 1.0)
    assert law.degree == 1


def test_partial_conditions_leave_the_rest_free():
    law = PolynomialLaw.from_boundary(start=(0, None, 0), end=[None, 0])
    assert law.degree == 4
    d = law.evaluate(np.array([0.0, 1.0]))
    assert d[0] == pytest.approx([0, 1], abs=1e-12)
    assert d[1][0] == pytest.approx(0, abs=1e-12)
    assert d[3][0] == pytest.approx(0, abs=1e-12)
    assert d[2][1] == pytest.approx(0, abs=1e-12)


finite = st.floats(-20, 20, allow_nan=False)
triple = st.lists(st.one_of(st.none(), finite), max_size=3)


@settings(settings.get_profile("laws"))
@given(start=triple, end=triple)
def test_conditions_hold(start, end):
    try:
        law = PolynomialLaw.from_boundary(start=start, end=end)
    except InputError as e:
        # only a higher derivative given without a lower one may be undetermined
        assert e.field in ("start", "end")
        return
    d = law.evaluate(np.array([0.0, 1.0]))
    assert d[0] == pytest.approx([0, 1], abs=1e-9)
    for at, conds in ((0, start), (1, end)):
        for k, v in enumerate(conds, start=1):
            if v is not None:
                assert d[k][at] == pytest.approx(v, abs=1e-7 * max(1, abs(v)))


def test_derivatives_consistent(central_difference):
    law = PolynomialLaw.from_boundary(start=(0.5, 1.0), end=(0, -2, 3))
    u = np.linspace(0.01, 0.99, 50)
    for k in range(3):
        fd = central_difference(lambda x: law.evaluate(x)[k], u)
        np.testing.assert_allclose(fd, law.evaluate(u)[k + 1], atol=1e-5 * 10**k)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        (dict(start="abc"), "start"),
        (dict(start=(0, 0, 0, 0)), "start"),
        (dict(end=(0, "x")), "end[1]"),
        (dict(end=(float("nan"),)), "end[0]"),
        (dict(start=(None, None, 1.0)), "start"),
    ],
)
def test_bad_conditions(kwargs, field):
    with pytest.raises(InputError) as e:
        PolynomialLaw.from_boundary(**kwargs)
    assert e.value.field == field


def test_coefficients_must_normalize():
    with pytest.raises(InputError, match="S\\(1\\) = 1") as e:
        PolynomialLaw((0.0, 2.0))
    assert e.value.field == "polynomial.coefficients"
    with pytest.raises(InputError):
        PolynomialLaw((0.0, float("inf")))


def test_frozen_and_hashable():
    law = PolynomialLaw.from_boundary(start=(0, 0), end=(0, 0))
    with pytest.raises(AttributeError):
        law.coefficients = (0.0, 1.0)
    assert hash(law) == hash(PolynomialLaw.from_boundary(start=(0, 0), end=(0, 0)))
