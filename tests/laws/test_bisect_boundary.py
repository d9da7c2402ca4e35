"""``laws.search.bisect_boundary``: the boundary of a yes/no test, against closed forms and a count of halvings."""

from __future__ import annotations

import math

import pytest

from laws.search import bisect_boundary


@pytest.mark.parametrize("good, bad", [(0.0, 2.0), (2.0, 0.0)])
def test_the_boundary_of_a_test_to_the_tolerance_on_its_side(good, bad):
    """x^2 <= 2 holds up to sqrt(2), x^2 >= 2 from it: the point returned holds, within xtol of sqrt(2)."""
    seen = []

    def holds(x):
        seen.append(x)
        return (x * x <= 2.0) if good < bad else (x * x >= 2.0)

    x = bisect_boundary(holds, good, bad, xtol=1e-9)
    assert holds(x) and abs(x - math.sqrt(2.0)) <= 1e-9
    assert good not in seen[:-1] and bad not in seen  # the ends are taken as given, never evaluated
    assert len(seen) - 1 == math.ceil(math.log2(2.0 / 1e-9))  # one evaluation per halving: 2 -> under 1e-9


def test_max_steps_halvings_exactly():
    """With max_steps = k the last point that held among k midpoints of [0, 1] for x <= 1/3: by hand, the binary
    digits of 1/3 (0.0101...) cut after k places."""
    for k in range(1, 12):
        calls = []
        x = bisect_boundary(lambda t: calls.append(t) or t <= 1.0 / 3.0, 0.0, 1.0, max_steps=k)
        assert len(calls) == k and x == math.floor((1.0 / 3.0) * 2**k) / 2**k


def test_stops_at_the_floats_resolution_and_never_holds_nowhere():
    """xtol 0 and no step limit: the bracket closes to adjacent floats, the answer the last float that holds; a test
    that never holds gives the good end back."""
    x = bisect_boundary(lambda t: t <= 0.1, 0.0, 1.0)
    assert x <= 0.1 and math.nextafter(x, 1.0) > 0.1
    assert bisect_boundary(lambda t: False, 3.0, 4.0, xtol=1e-6) == 3.0
