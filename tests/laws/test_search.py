"""The numpy golden-section search and bracketed root (laws.search) against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from laws.search import bracketed_root, golden_minimum


def test_golden_minimum_finds_each_brackets_minimum():
    # f(x) = (x - c)^2 + 1 per bracket: interior minimum at c, or the nearer end when c lies outside
    a = np.array([0.0, 0.5, -2.0])
    b = np.array([1.0, 1.0, -1.0])
    x, fx = golden_minimum(lambda t: (t - 0.3) ** 2 + 1.0, a, b, xatol=1e-12)
    # an interior minimum's place is known to sqrt(eps) (f is flat there to rounding), an end's exactly
    assert x[0] == pytest.approx(0.3, abs=1e-7) and x[1] == 0.5 and x[2] == -1.0
    assert fx == pytest.approx([1.0, 1.04, 2.69], rel=1e-15, abs=1e-15)


def test_golden_minimum_of_a_law_like_peak():
    # -|sin(2 pi u)| has its least value -1 at u = 1/4 on [0.2, 0.3]: the value to rounding, u to sqrt(eps)
    x, fx = golden_minimum(lambda u: -np.abs(np.sin(2 * np.pi * u)), [0.2], [0.3], xatol=1e-12)
    assert fx[0] == pytest.approx(-1.0, abs=1e-15)
    assert x[0] == pytest.approx(0.25, abs=1e-7)


@pytest.mark.parametrize("f, a, b, root", [
    (lambda x: math.cos(x) - x, 0.0, 1.0, 0.7390851332151607),  # the Dottie number
    (lambda x: x**3 - 2.0, 0.0, 5.0, 2.0 ** (1 / 3)),
    (lambda x: math.copysign(abs(x - 0.3) ** 0.2, x - 0.3), 0.0, 5.0, 0.3),  # flat at the root: bisection steps
    (lambda x: math.exp(x) - 1e-3, -20.0, 0.0, math.log(1e-3)),
])
def test_bracketed_root_against_closed_forms(f, a, b, root):
    assert bracketed_root(f, a, b, xtol=1e-14) == pytest.approx(root, abs=1e-13)


def test_bracketed_root_ends_and_refusal():
    assert bracketed_root(lambda x: x - 1.0, 1.0, 2.0) == 1.0
    with pytest.raises(ValueError, match="differ in sign"):
        bracketed_root(lambda x: x * x + 1.0, -1.0, 1.0)
