"""``--vary KEY=a:b:n``: every part a number (nan and inf included) makes a range, checked once: finite ends and
count, then the count's form; anything else is a list of values."""

from __future__ import annotations

import numpy as np
import pytest

from cams.sweep.grid import parse_vary
from laws.errors import InputError


@pytest.mark.parametrize("rng", ["nan:120:3", "1:2:1e400", "-Infinity:1:2"])
def test_a_range_of_non_finite_numbers_is_refused(rng):
    with pytest.raises(InputError, match="a range a:b:n takes finite numbers$"):
        parse_vary(f"k={rng}")


@pytest.mark.parametrize("rng", ["nan:1", "1:2", "1:2:3:4", "1:2:0", "1:2:2.5"])
def test_a_range_without_three_parts_and_a_whole_count_is_refused(rng):
    with pytest.raises(InputError, match="a range is a:b:n with a count n >= 1$"):
        parse_vary(f"k={rng}")


def test_a_range_and_what_is_not_one():
    key, vals = parse_vary("k= 1 : 2e0 : 5 ")
    assert key == "k" and np.array_equal(vals, [1.0, 1.25, 1.5, 1.75, 2.0])  # steps of (2 - 1) / 4
    assert np.array_equal(parse_vary("k=.5:-.5:2")[1], [0.5, -0.5])
    # a part that is no number as a listed value reads ("1_0", a word): one word, refused later by the schema
    assert parse_vary("k=1_0:nan:3") == ("k", ("1_0:nan:3",))
    # two signs are no number float reads: one word too, never float's ValueError
    assert parse_vary("k=--inf:1:3") == ("k", ("--inf:1:3",))
    assert parse_vary("k=+-nan:1:3") == ("k", ("+-nan:1:3",))
    assert parse_vary("k=a:b:c") == ("k", ("a:b:c",))
