"""The bracket searches of laws.search (Brent's minimum, the Illinois root) against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from laws.search import bounded_minimum, bracketed_root


@pytest.mark.parametrize("a, b, x_min, f_min", [(0.0, 1.0, 0.3, 1.0), (0.5, 1.0, 0.5, 1.04), (-2.0, -1.0, -1.0, 2.69)])
def test_bounded_minimum_of_a_parabola(a, b, x_min, f_min):
    # f(x) = (x - 0.3)^2 + 1: the minimum at 0.3 inside the bracket, else at the nearer end (to the tolerance)
    x, fx = bounded_minimum(lambda t: (t - 0.3) ** 2 + 1.0, a, b, xatol=1e-12)
    # the method stops within sqrt(eps) |x| + xatol / 3 of the minimum (an end's too): f there within the slope
    # times that (2.6 x 1.5e-8 at the end -1), and at an interior minimum, where f is flat, to rounding
    assert x == pytest.approx(x_min, abs=1e-7)
    assert fx == pytest.approx(f_min, abs=1e-7 if x_min in (a, b) else 1e-15)


def test_bounded_minimum_of_a_law_like_peak():
    # -|sin(2 pi u)| has its least value -1 at u = 1/4 on [0.2, 0.3]: the value to rounding, u to sqrt(eps)
    x, fx = bounded_minimum(lambda u: -abs(math.sin(2 * math.pi * u)), 0.2, 0.3, xatol=1e-12)
    assert fx == pytest.approx(-1.0, abs=1e-15)
    assert x == pytest.approx(0.25, abs=1e-7)


@pytest.mark.parametrize(
    "f, a, b, root",
    [
        (lambda x: math.cos(x) - x, 0.0, 1.0, 0.7390851332151607),  # the Dottie number
        (lambda x: x**3 - 2.0, 0.0, 5.0, 2.0 ** (1 / 3)),
        (lambda x: math.copysign(abs(x - 0.3) ** 0.2, x - 0.3), 0.0, 5.0, 0.3),  # flat at the root: bisection steps
        (lambda x: math.exp(x) - 1e-3, -20.0, 0.0, math.log(1e-3)),
    ],
)
def test_bracketed_root_against_closed_forms(f, a, b, root):
    assert bracketed_root(f, a, b, xtol=1e-14) == pytest.approx(root, abs=1e-13)


def test_bracketed_root_ends_and_refusal():
    assert bracketed_root(lambda x: x - 1.0, 1.0, 2.0) == 1.0
    with pytest.raises(ValueError, match="differ in sign"):
        bracketed_root(lambda x: x * x + 1.0, -1.0, 1.0)


def test_the_same_answers_as_scipy_to_the_last_digit():
    """Both searches take the steps of scipy's brentq and bounded minimize_scalar (which the product used before):
    on random smooth functions their answers are the same floats, so no figure the product prints moved."""
    from scipy.optimize import brentq, minimize_scalar

    rng = np.random.default_rng(7)
    for _ in range(200):
        c = rng.normal(size=4)
        r = rng.uniform(-1.0, 1.0)

        def f(x, c=c, r=r):
            return math.tanh(c[0] * (x - r)) * (1 + c[1] ** 2) + 1e-3 * c[2] * math.sin(7 * x)

        def g(x, c=c, r=r):
            return (x - r) ** 2 * (1 + c[3] ** 2) + 0.1 * c[2] * math.cos(3 * x)

        if f(-2.0) * f(2.0) < 0:
            assert bracketed_root(f, -2.0, 2.0, xtol=1e-14) == brentq(
                f, -2.0, 2.0, xtol=1e-14, rtol=4 * np.finfo(float).eps
            )
        m = minimize_scalar(g, bounds=(-2.0, 2.0), method="bounded", options={"xatol": 1e-12})
        assert bounded_minimum(g, -2.0, 2.0, xatol=1e-12) == (m.x, m.fun)
