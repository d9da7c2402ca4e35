"""The spline space of the motion design: when it holds a law, and the laws it holds (issue 28, defect 4).

A free phase between dwells, of degree p on n equal spans with continuity c: its splines have p + 1 +
(n - 1)(p - c) coefficients, the ends take 2 c + 2 conditions (S(0) = 0, S(1) = 1, derivatives 1 to c zero), so a
law exists exactly when n (p - c) >= c + 1 (the Hermite conditions at the two ends are independent on a spline
space with that many coefficients). The space's own test (:meth:`Space.inconsistency`, the residual of its
equalities) must agree with that count, and a law projected on the space must meet the conditions when its
derivatives are evaluated on the law itself (one-sided at the knots), not through the equalities' matrix.
"""

from __future__ import annotations

import numpy as np
import pytest

from laws.program import Phase, Program
from laws.registry import get_law
from optimize.motion.space import CONSISTENT, Space

RAD = np.pi / 180


def _program(return_law: str = "cycloidal", dwell: bool = True) -> Program:
    phases = [Phase("rise", 120 * RAD, get_law("cycloidal"))]
    if dwell:
        phases.append(Phase("dwell", 30 * RAD))
    phases += [Phase("return", 120 * RAD, get_law(return_law)), Phase("dwell", (90 if dwell else 120) * RAD)]
    return Program(tuple(phases), lift=10.0)


@pytest.mark.parametrize(("p", "c"), [(p, c) for p in range(2, 12) for c in (1, 2, 3) if c < p])
def test_a_law_exists_exactly_when_the_count_allows(p, c):
    for n in range(1, 9):
        holds = Space(_program(), (0,), p, n, c).inconsistency() <= CONSISTENT
        assert holds == (n * (p - c) >= c + 1), (p, c, n)


@pytest.mark.parametrize(("p", "c", "n", "return_law", "dwell"), [
    (4, 3, 4, "cycloidal", True),      # the least spans: one law exactly
    (7, 3, 5, "cycloidal", True),
    (5, 2, 3, "harmonic", False),      # straight into a return that starts with an acceleration
    (6, 1, 2, "poly345", False),
])
def test_the_projected_law_meets_the_ends_and_joints(p, c, n, return_law, dwell):
    program = _program(return_law, dwell)
    space = Space(program, (0,), p, n, c)
    rng = np.random.default_rng(3)
    v = space.project(rng.normal(size=space.size))
    law = space.programme(v, "test").law_of(0)
    u = np.linspace(0.0, 1.0, 8001)
    dense = law.evaluate(u)
    size = [max(1.0, float(np.max(np.abs(dense[r])))) for r in range(4)]
    # the next derivative's size, from the law's own values (twice the largest slope between samples)
    slope = [2 * max(1.0, float(np.max(np.abs(np.diff(dense[r])))) / (u[1] - u[0])) for r in range(4)]
    ends = law.evaluate(np.array([0.0, 1.0]))
    assert abs(ends[0][0]) <= 1e-12 and abs(ends[0][1] - 1) <= 1e-12
    # the neighbours' derivatives at the joints, in the physical analogue s^(r) = sigma h S^(r) / beta^r
    beta, h = program.phases[0].angle, program.height_of(0)
    nxt = program.phases[1]
    for r in range(1, c + 1):
        after = 0.0
        if nxt.kind != "dwell":
            after = -program.height_of(1) * float(program.law_of(1).evaluate(0.0)[r]) / nxt.angle**r
        assert abs(ends[r][0]) <= 1e-9 * size[r]                                   # from the dwell before
        assert abs(h * ends[r][1] / beta**r - after) <= 1e-9 * size[r] * h / beta**r   # into the next phase
    eps = 1e-9
    for j in range(1, n):
        sides = law.evaluate(np.array([j / n - eps, j / n + eps]))
        for r in range(c + 1):
            assert abs(sides[r][1] - sides[r][0]) <= 4 * eps * slope[r] + 1e-9 * size[r], (j, r)


def test_projecting_on_an_empty_space_is_refused():
    space = Space(_program(), (0,), 4, 1, 3)
    assert space.inconsistency() > 1e-3
    with pytest.raises(ValueError, match="no law to project on"):
        space.project(np.zeros(space.size))
