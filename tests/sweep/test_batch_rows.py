"""The sweep's default path, the batch solver (:mod:`cams.batch`), gives the per-design path's rows.

The same grid through both paths of the engine (:func:`cams.sweep.run_grid`): every cell equal, or, for the sized
numbers, within what each path states (R0 within the sum of both error bounds; the blank's diameter, the batch's
own refined maximum of the pitch radius against the kernel's, to 1e-9 of it; the pressure angles to 1e-6 deg).
The batch must have taken the rows itself (it returns them), or the comparison would be of one path with itself.
"""

from __future__ import annotations

import math

import pytest

from cams.batch import size_batch
from cams.io.designfile import design_from_dict
from cams.io.document import read_toml
from cams.sweep import run_grid
from cams.sweep.grid import BaseFile, make_grid
from tests.conftest import EXAMPLES

CASES = {
    # a rocker by force closure; a rocker's groove with K_C (form closure: the blank is the outer wall's); a
    # translating follower
    "rocker_force.toml": [("follower.arm", [100.0, 140.0, 180.0]), ("limits.pressure_angle", [30.0, 40.0])],
    "rocker_form.toml": [("follower.roller_radius", [6.0, 10.0]), ("limits.pressure_angle", [40.0, 45.0])],
    "translating_force.toml": [("follower.roller_radius", [5.0, 8.0]), ("limits.pressure_angle", [30.0, 35.0])],
}


@pytest.fixture(scope="module", params=sorted(CASES))
def both(request):
    path = EXAMPLES / request.param
    if not path.exists():
        pytest.fail(f"the example {path.name} is missing")
    grid = make_grid([BaseFile("", read_toml(path))], CASES[request.param])
    per = run_grid(grid, workers=1, per_design=True).rows
    batch = run_grid(grid, workers=1).rows
    designs = [design_from_dict(grid.design_dict(i)[0]) for i in range(grid.size)]
    return per, batch, size_batch(designs)


def test_the_batch_takes_the_rows_itself(both):
    _, _, direct = both
    assert all(r is not None for r in direct)


def test_rows_equal_the_per_design_paths(both):
    per, batch, _ = both
    assert [r["index"] for r in per] == [r["index"] for r in batch]
    for p, b in zip(per, batch, strict=True):
        assert p.keys() == b.keys()
        assert (p["verified"], p["buildable"], p["failures"], p["error"]) == (True, True, None, None)
        assert (b["verified"], b["buildable"], b["failures"], b["error"]) == (True, True, None, None)
        assert abs(p["R0"] - b["R0"]) <= p["error_bound"] + b["error_bound"]
        assert b["blank_diameter"] == pytest.approx(p["blank_diameter"], rel=1e-9)
        for k in ("max_pressure_angle_rise", "max_pressure_angle_return"):
            assert b[k] == pytest.approx(p[k], abs=1e-6), k
        for k in ("L", "offset", "centre_x", "centre_y"):
            assert (p[k] is None) == (b[k] is None), k
            if p[k] is not None:
                assert math.isclose(p[k], b[k], rel_tol=1e-6, abs_tol=1e-6 * p["R0"]), k
        assert b["Ca_rise"] == p["Ca_rise"]
        for k in ("max_contact_stress", "residual_vibration"):
            assert p[k] is None and b[k] is None
