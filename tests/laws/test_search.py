"""The bracket searches of laws.search (Brent's minimum, the Illinois root) against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from laws.search import bounded_minimum, bracketed_root, grid_minimum


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


def test_grid_minimum_refines_between_the_best_samples_neighbours():
    # f(x) = cos(x) + 0.5 cos(2x) on [0, pi]: f' = -sin x (1 + 2 cos x) vanishes at 0, pi and at 2 pi / 3
    # (cos x = -1/2), the least, f = -1/2 - 1/4 = -3/4 (f(0) = 3/2, f(pi) = -1/2); 2 pi / 3 is not a sample
    f = lambda x: math.cos(x) + 0.5 * math.cos(2 * x)  # noqa: E731
    grid = np.linspace(0.0, math.pi, 17)
    x, fx = grid_minimum(f, grid, np.array([f(t) for t in grid]), xatol=1e-12)
    assert x == pytest.approx(2 * math.pi / 3, abs=1e-7)
    assert fx == pytest.approx(-0.75, abs=1e-14)


def test_grid_minimum_across_a_periodic_grids_ends():
    # cos(x - 0.01) is least at pi + 0.01; shifted to x = 0.01 by a phase of pi it lies between the last sample
    # (2 pi - step) and the first (0), found only by a bracket that crosses the period's end
    f = lambda x: -math.cos(x - 0.01)  # noqa: E731
    grid = np.linspace(0.0, 2 * math.pi, 8, endpoint=False)
    x, fx = grid_minimum(f, grid, np.array([f(t) for t in grid]), xatol=1e-12, period=2 * math.pi)
    assert x == pytest.approx(0.01, abs=1e-7)
    assert fx == pytest.approx(-1.0, abs=1e-14)
    # without the period, the search stays on the grid's side of 0: the end sample's bracket is [0, step]
    x, _ = grid_minimum(f, grid, np.array([f(t) for t in grid]), xatol=1e-12)
    assert 0.0 <= x <= grid[1]


def test_grid_minimum_keeps_the_sample_when_the_bracket_holds_nothing_better():
    # a minimum at a grid's end (f increasing): the answer is that end, the sample itself or a point whose value
    # is no larger; and a grid of one point is its own answer
    grid = np.linspace(1.0, 2.0, 5)
    x, fx = grid_minimum(lambda t: t**2, grid, grid**2, xatol=1e-12)
    assert fx <= 1.0 and x == pytest.approx(1.0, abs=1e-7)
    assert grid_minimum(lambda t: t**2, np.array([3.0]), np.array([9.0]), xatol=1e-12) == (3.0, 9.0)
