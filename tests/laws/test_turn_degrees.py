"""``laws.units.turn_degrees``: where on the cam, in degrees within one turn, for every output."""

from __future__ import annotations

import math

import numpy as np

from laws.units import turn_degrees


def test_turn_degrees_is_the_same_direction_within_one_turn():
    """Against the definition, computed another way: the angle in [0, 360) whose direction (cos, sin) is the
    given angle's, a whole number of turns from it; by hand at the quarter turns."""
    rng = np.random.default_rng(7)
    angles = np.concatenate([rng.uniform(-40.0, 40.0, 2000), [0.0, math.pi, -math.pi / 2, 2 * math.pi, 7.5 * math.pi]])
    got = turn_degrees(angles)
    assert got.shape == angles.shape and np.all(got >= 0.0) and np.all(got < 360.0)
    back = np.radians(got)
    assert np.allclose(np.cos(back), np.cos(angles), atol=1e-12) and np.allclose(
        np.sin(back), np.sin(angles), atol=1e-12
    )
    turns = (math.degrees(1.0) * angles - got) / 360.0
    assert np.allclose(turns, np.round(turns), atol=1e-9)
    assert [float(turn_degrees(a)) for a in (0.0, math.pi, -math.pi / 2, 2 * math.pi, 7.5 * math.pi)] == [
        0.0,
        180.0,
        270.0,
        0.0,
        270.0,
    ]
