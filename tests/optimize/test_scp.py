"""The trust-region loop of sequential convex programming on a problem whose optimum is known.

min (x0 - 1)^2 + (x1 + 2)^2 + x0 x1 / 2 over the box |x| <= 3: a convex quadratic whose optimum is the root of
its gradient (a 2x2 linear system; it lies inside the box). The model is the linearization within a box of the
trust radius (solved in closed form: each variable to its box's end against the gradient's sign), the exact
value the function itself.
"""

from __future__ import annotations

import numpy as np
import pytest

from optimize.motion.scp import Iterate, minimize, stationarity


def f(x: np.ndarray) -> float:
    return float((x[0] - 1) ** 2 + (x[1] + 2) ** 2 + 0.5 * x[0] * x[1])


def grad(x: np.ndarray) -> np.ndarray:
    return np.array([2 * (x[0] - 1) + 0.5 * x[1], 2 * (x[1] + 2) + 0.5 * x[0]])


def model(it: Iterate, trust: float):
    g = grad(it.v)
    x = np.clip(it.v - trust * np.sign(g), -3, 3)
    return it.value + float(g @ (x - it.v)), x


def exact(x: np.ndarray) -> Iterate:
    return Iterate(x, f(x), None)


def test_the_loop_reaches_the_known_optimum_and_its_measure_says_so():
    # the gradient's root: [[2, 0.5], [0.5, 2]] x = [2, -4]
    x_star = np.linalg.solve(np.array([[2.0, 0.5], [0.5, 2.0]]), np.array([2.0, -4.0]))
    start = exact(np.array([-2.5, 2.5]))
    out = minimize(start, model, exact)
    assert np.allclose(out.best.v, x_star, atol=1e-4)
    assert out.best.value == pytest.approx(f(x_star), abs=1e-7)
    assert all(b < a for a, b in zip(out.history, out.history[1:], strict=False))
    assert out.accepted == len(out.history) - 1
    # the measure: near 0 at the optimum, not at the start (the model predicts 1e-3 times the slope there)
    assert out.local_measure < 1e-5
    assert stationarity(model, start) > 1e-3 * np.abs(grad(start.v)).sum() / abs(start.value) * 0.99


def test_an_infeasible_model_shrinks_the_radius_and_keeps_the_start():
    start = exact(np.array([0.0, 0.0]))
    out = minimize(start, lambda it, trust: None, exact)
    assert out.best is start and out.accepted == 0 and out.local_measure == np.inf
