"""Floors on R0 and fixed centre distances: tolerances follow the numbers computed, not the follower's size.

* the same design at unit scales x1e-3, x1 and x1e3 gives proportional answers (relative 1e-9) in the modes
  floor_R0, fixed_L, fixed_L_and_R0 and a fixed offset with a floor, also with floors and L far above the
  follower's size (1e5 x);
* a floor equal to the largest R0 of the admissible arc of a fixed-L circle is met exactly, also where the
  circle is 1e6 times the follower's size (the crossing of two nearly concentric circles): before, a fixed
  tolerance of 1e-9 x the follower's size refused it;
* an admissible arc wider than a quarter turn, seeded at one of its ends, is not taken for the whole circle.
"""

from __future__ import annotations

import copy

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.solve import solve
from cams.verify.pressure import check_pressure
from optimize.circle import admissible_arcs, best_on_circle, violation_function
from tests.conftest import rocker_dict

SCALES = (1e-3, 1.0, 1e3)


def _translating(**limits) -> dict:
    return {
        "name": "translating",
        "follower": {"kind": "translating", "stroke": 30.0, "roller_radius": 8.0},
        "cam": {"rotation": "ccw"},
        "motion": [{"phase": "rise", "law": "cycloidal", "angle": 120}, {"phase": "dwell", "angle": 30},
                   {"phase": "return", "law": "cycloidal", "angle": 120}, {"phase": "dwell"}],
        "limits": {"pressure_angle": 30, "closure": "force", **limits},
        "solve": {"method": "exact"},
    }


def _rocker(**limits) -> dict:
    d = rocker_dict()
    d["limits"] = {**d["limits"], **limits}
    return d


def _scaled(d: dict, k: float) -> dict:
    d = copy.deepcopy(d)
    for key in ("arm", "stroke", "roller_radius", "offset"):
        if key in d["follower"]:
            d["follower"][key] *= k
    for key in ("min_base_radius", "centre_distance"):
        if key in d["limits"]:
            d["limits"][key] *= k
    return d


ARM, STROKE = 125.0, 30.0
#: name: (design, mode, unit scales); lengths are capped at 1e9 mm, so the 1e5 x cases stop at x1
CASES = {
    "rocker floor 1.5 x arm": (_rocker(min_base_radius=1.5 * ARM), "floor_R0", SCALES),
    "rocker floor 5e3 x arm": (_rocker(min_base_radius=5e3 * ARM), "floor_R0", SCALES),
    "rocker floor 1e5 x arm": (_rocker(min_base_radius=1e5 * ARM), "floor_R0", SCALES[:2]),
    "rocker form floor 5e3 x arm": (_rocker(closure="form", min_base_radius=5e3 * ARM), "floor_R0", SCALES),
    "rocker L 10 x arm": (_rocker(centre_distance=10 * ARM), "fixed_L", SCALES),
    "rocker L 5e3 x arm": (_rocker(centre_distance=5e3 * ARM), "fixed_L", SCALES),
    "rocker L 1e5 x arm": (_rocker(centre_distance=1e5 * ARM), "fixed_L", SCALES[:2]),
    "rocker L and floor 5e3 x arm": (_rocker(centre_distance=5e3 * ARM, min_base_radius=5e3 * ARM), "fixed_L_and_R0",
                                     SCALES),
    "rocker L and floor 1e5 x arm": (_rocker(centre_distance=1e5 * ARM, min_base_radius=1e5 * ARM), "fixed_L_and_R0",
                                     SCALES[:2]),
    "translating floor 1e4 x stroke": (_translating(min_base_radius=1e4 * STROKE), "floor_R0", SCALES),
    "translating form floor 1e5 x stroke": (_translating(closure="form", min_base_radius=1e5 * STROKE), "floor_R0",
                                            SCALES[:2]),
}


@pytest.mark.parametrize("name", list(CASES))
@pytest.mark.parametrize("method", ["exact", "convex"])
def test_floor_and_fixed_L_scale_with_the_units(name, method):
    d, mode, scales = CASES[name]
    d = copy.deepcopy(d)
    d["solve"] = {**d.get("solve", {}), "method": method}
    ref = solve(design_from_dict(d))
    assert ref.mode == mode and ref.pressure.ok
    floor = d["limits"].get("min_base_radius")
    if mode in ("floor_R0", "fixed_L_and_R0"):
        assert ref.R0 == pytest.approx(floor, rel=1e-12)  # a floor far above the minimum is met exactly
    for k in scales:
        r = solve(design_from_dict(_scaled(d, k)))
        assert r.mode == mode and r.pressure.ok
        assert r.R0 / k == pytest.approx(ref.R0, rel=1e-9)
        np.testing.assert_allclose(r.centre / k, ref.centre, rtol=1e-9, atol=1e-9 * ref.R0)
        if r.L is not None:
            assert r.L / k == pytest.approx(ref.L, rel=1e-9)


@pytest.mark.parametrize("k", SCALES)
def test_fixed_offset_with_a_far_floor_scales(k):
    d = _translating(min_base_radius=1e4 * STROKE)
    d["follower"]["offset"] = 5.0
    ref = solve(design_from_dict(d))
    r = solve(design_from_dict(_scaled(d, k)))
    assert ref.mode == r.mode == "floor_R0" and r.pressure.ok
    assert ref.R0 == pytest.approx(1e4 * STROKE, rel=1e-12)
    assert r.R0 / k == pytest.approx(ref.R0, rel=1e-9) and r.offset / k == pytest.approx(5.0, rel=1e-12)


@pytest.mark.parametrize("ratio", [10.0, 1e3, 1e6])
@pytest.mark.parametrize("closure", ["force", "form"])
@pytest.mark.parametrize("k", [1e-3, 1.0])
def test_floor_at_the_largest_R0_of_the_L_arc_is_met(ratio, closure, k):
    """The admissible arc's largest R0 (maximized over the arc, another path than the crossing) is a valid floor."""
    D = design_from_dict(_scaled(_rocker(closure=closure, centre_distance=ratio * ARM), k))
    f = D.follower
    A0, L = f.position(0.0), D.limits.centre_distance
    least = solve(D)
    rel = least.centre - f.pivot
    seed = float(np.arctan2(rel[1], rel[0]) % (2 * np.pi))
    far = best_on_circle(D, f.pivot, L, lambda O: -float(np.linalg.norm(O - A0)), seeds=(seed,))
    top = float(np.linalg.norm(far - A0))
    assert top > least.R0 and check_pressure(D, far).ok  # the independent check accepts the farthest centre
    lim = D.limits
    r = solve(D.with_(limits=type(lim)(**{**lim.__dict__, "min_base_radius": top})))
    assert r.mode == "fixed_L_and_R0" and r.pressure.ok
    assert r.R0 == pytest.approx(top, rel=1e-12) and r.L == pytest.approx(L, rel=1e-12)
    from laws.errors import InfeasibleError

    with pytest.raises(InfeasibleError):
        solve(D.with_(limits=type(lim)(**{**lim.__dict__, "min_base_radius": top * (1 + 1e-6)})))


def test_a_wide_arc_seeded_at_its_end_is_not_the_whole_circle():
    D = design_from_dict(_rocker(centre_distance=1e3 * ARM))
    f = D.follower
    L = D.limits.centre_distance
    (a, b), = admissible_arcs(D, f.pivot, L)  # from the scan alone
    assert b - a > np.pi / 4
    G = violation_function(D, None)
    for seed in (a, b, a - 1e-15, b + 1e-15):
        arcs = admissible_arcs(D, f.pivot, L, seeds=(seed % (2 * np.pi),))
        assert (0.0, 2 * np.pi) not in arcs
        # the middle of the arc's complement is outside the zone, and on no returned arc
        out = (b + (2 * np.pi - (b - a)) / 2) % (2 * np.pi)
        assert G(f.pivot + L * np.array([np.cos(out), np.sin(out)])) > 0
        assert not any((out - s) % (2 * np.pi) <= e - s for s, e in arcs)
