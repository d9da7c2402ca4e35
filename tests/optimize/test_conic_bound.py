"""The proven lower bound of optimize.motion.conic: a bound whatever the multipliers, tight at good ones.

Reference: minimize ||(x, y)|| subject to x + y >= 1 has the optimum 1/sqrt(2) at (1/2, 1/2) (the distance
from the origin to the line), computed by hand.
"""

from __future__ import annotations

import numpy as np
import pytest

from optimize.motion.conic import Cone, ConicProgram, Solution, lower_bound, solve

OPT = 1 / np.sqrt(2)


def _program() -> ConicProgram:
    # v = (x, y, t): minimize t, t >= ||(x, y)||, -x - y <= -1, box |v| <= 10
    return ConicProgram(cost=np.array([0.0, 0.0, 1.0]), G=np.array([[-1.0, -1.0, 0.0]]), h=np.array([-1.0]),
                        A=np.zeros((0, 3)), b=np.zeros(0), lo=np.full(3, -10.0), hi=np.full(3, 10.0),
                        cones=(Cone(np.array([0.0, 0.0, 1.0]), 0.0, np.array([[1.0, 0, 0], [0, 1.0, 0]]),
                                    np.zeros(2)),))


def test_solver_multipliers_give_a_tight_bound():
    prog = _program()
    sol = solve(prog)
    lb = lower_bound(prog, sol)
    assert lb <= OPT and lb == pytest.approx(OPT, abs=1e-7)


@pytest.mark.parametrize("seed", range(20))
def test_any_multipliers_give_a_bound(seed):
    """Multipliers off by up to 30 %, or of the wrong sign: never a bound above the optimum."""
    rng = np.random.default_rng(seed)
    prog = _program()
    good = solve(prog)
    lam = good.lam * (1 + 0.3 * rng.standard_normal(good.lam.shape))
    mu = tuple((m0 * (1 + 0.3 * rng.standard_normal()), m * (1 + 0.3 * rng.standard_normal(m.shape)))
               for m0, m in good.mu)
    bad = Solution("optimal", good.v, good.value, lam, good.nu, mu)
    assert lower_bound(prog, bad) <= OPT
