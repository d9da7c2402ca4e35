"""cams.kinematics.extremum: the one vectorized extremum search, on functions with known maxima."""

from __future__ import annotations

import numpy as np
import pytest

from cams.kinematics.extremum import MAX_STEPS, maximize, phase_positions
from laws.program import Phase, Program
from laws.registry import get_law


def test_maximize_finds_known_maxima_in_few_steps():
    """Two functions on [0, 2]: ``sin(7x) exp(-x)`` and a rising line.

    The first has local maxima at ``(atan 7 + 2 k pi) / 7``, k = 0, 1, 2, all
    three refined together, one array of the open brackets a step, the
    largest kept; the line's maximum is the end of the grid.
    """
    calls = []

    def fun(x):
        calls.append(len(x))
        e = np.exp(-x)
        return (np.array([np.sin(7 * x) * e, x]),
                np.array([(7 * np.cos(7 * x) - np.sin(7 * x)) * e, np.ones_like(x)]))

    best, at = maximize(fun, np.linspace(0.0, 2.0, 101))
    x0 = np.arctan(7.0) / 7  # the largest peak
    assert at[0] == pytest.approx(x0, abs=1e-12)
    assert best[0] == pytest.approx(np.sin(7 * x0) * np.exp(-x0), rel=1e-15)
    assert (best[1], at[1]) == (2.0, 2.0)
    assert calls[0] == 101 and calls[1] == 3 and all(n <= 3 for n in calls[2:])
    assert len(calls) - 1 <= 8


def test_maximize_batches_many_functions_and_returns_the_largest_peak_of_each():
    """``q`` shifted cosines ``cos(x - c_q) + a_q x`` on a coarse grid: every peak refined, one array a step."""
    c = np.linspace(0.3, 5.9, 9)
    a = np.linspace(-0.05, 0.05, 9)
    calls = []

    def fun(x):
        calls.append(np.shape(x))
        x = np.broadcast_to(x, (len(c), len(x)))
        return np.cos(x - c[:, None]) + a[:, None] * x, -np.sin(x - c[:, None]) + a[:, None]

    best, at = maximize(fun, np.linspace(0.0, 2 * np.pi, 13))
    # the maximum of cos(x - c) + a x is where sin(x - c) = a: x = c + arcsin(a) (inside the interval here)
    want = c + np.arcsin(a)
    assert np.allclose(at, want, atol=1e-11)
    assert np.allclose(best, np.cos(want - c) + a * want, rtol=0, atol=1e-15)
    assert len(calls) - 1 < MAX_STEPS


def test_maximize_without_refinement_is_the_grids_best():
    u = np.linspace(0.0, 1.0, 11)
    best, at = maximize(lambda x: (np.array([-(x - 0.33) ** 2]), np.array([-2 * (x - 0.33)])), u, refine=False)
    assert at[0] == pytest.approx(0.3) and best[0] == pytest.approx(-(0.03**2))


def test_maximize_keeps_a_maximum_at_the_end_of_the_interval():
    """A function still rising at the right end: the end is the maximum, no bracket is opened."""
    best, at = maximize(lambda x: (np.exp(x)[None], np.exp(x)[None]), np.linspace(0.0, 1.0, 5))
    assert (best[0], at[0]) == (np.e, 1.0)


def test_phase_positions_hold_both_sides_of_a_breakpoint():
    """A piecewise law's breakpoints are on the grid with their neighbours one rounding step either side."""
    law = get_law("modified_trapezoid")
    prog = Program((Phase("rise", np.pi, law), Phase("dwell", 0.5 * np.pi), Phase("return", 0.5 * np.pi, law)), 10.0)
    u = phase_positions(prog, 0, 10)
    assert u[0] == 0.0 and u[-1] == 1.0 and np.all(np.diff(u) > 0)
    for b in law.breakpoints:
        if 0 < b < 1:
            assert b in u and np.nextafter(b, 0.0) in u and np.nextafter(b, 1.0) in u
    assert phase_positions(prog, 1, 10).tolist() == [0.0, 1.0]
