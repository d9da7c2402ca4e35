"""The three solvers against each other, against the definition, and in every mode."""

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.solve import solve
from laws.errors import InfeasibleError, InputError
from optimize.diagnose import admissible_L_range
from tests.conftest import rocker_dict

SEED_FORCE = rocker_dict()
SEED_FORM = rocker_dict(limits={"closure": "form", "pressure_angle": 45, "return_pressure_angle": 40})
SAME_SENSE_FORCE = rocker_dict(cam={"rotation": "cw"})


def _d(dct, **solve):
    d = design_from_dict(dct)
    return d.with_(**solve) if solve else d


@pytest.mark.parametrize("dct", [SEED_FORCE, SEED_FORM], ids=["force", "form"])
def test_exhaustive_and_convex_give_the_same_apex(dct):
    """Where the apex is the nearest point both sampled methods find it to round-off."""
    d = _d(dct, samples=120)
    a = solve(d, method="exhaustive")
    b = solve(d, method="convex")
    assert len(a.binding) == 2
    assert np.allclose(a.centre, b.centre, rtol=0, atol=1e-9 * 125)
    assert a.R0 == pytest.approx(b.R0, rel=1e-10)


def test_nearest_point_on_an_edge_beats_the_seed_apex():
    """Same senses, force closure: the nearest admissible point lies on one line.

    The seed's candidates alone (every t-t line crossed with every t1-t1
    line, the nearest admissible one: computed here with the planar
    primitives) miss it; the exhaustive method, completed with the feet of the
    perpendicular, finds the convex method's point on the edge.
    """
    from optimize.planar import feasible_mask, line_crossings
    from optimize.zone import sample_wedges

    d = _d(SAME_SENSE_FORCE, samples=120)
    ex = solve(d, method="exhaustive")
    cv = solve(d, method="convex")
    exact = solve(d, method="exact")
    W = sample_wedges(d, 120)
    P, ok = line_crossings(W.normals[:, 0], W.offsets[:, 0], W.normals[:, 1], W.offsets[:, 1])
    P = P[ok]
    N, c = W.lines()
    A0 = d.follower.position(0.0)
    seed_apex = np.min(np.linalg.norm(P[feasible_mask(P, N, c, 1e-9 * 125)] - A0, axis=1))
    assert cv.R0 < seed_apex - 1e-3
    assert ex.R0 == pytest.approx(cv.R0, rel=1e-10)
    assert len(ex.binding) == 1
    assert len(exact.binding) == 1
    assert cv.R0 <= exact.R0 + 1e-12
    assert exact.pressure.ok


@pytest.mark.parametrize("dct", [SEED_FORCE, SEED_FORM, SAME_SENSE_FORCE], ids=["force", "form", "same-sense"])
def test_sampled_answers_converge_to_exact_from_below(dct):
    """Sampling relaxes the constraint: R0(N) <= R0 exact, and the gap shrinks like 1/N^2."""
    exact = solve(_d(dct), method="exact")
    assert exact.pressure.ok and exact.error_bound < 1e-9 * 125
    gaps = []
    for n in (30, 60, 120, 240):
        r = solve(_d(dct, samples=n), method="convex").R0
        assert r <= exact.R0 + exact.error_bound
        gaps.append(exact.R0 - r)
    gaps = np.array(gaps)
    assert np.all(gaps >= -1e-12)
    assert gaps[-1] < gaps[0] / 20  # 8x the samples: ~64x smaller, allow odd grids


def test_exact_is_tight():
    """Moving the exact centre towards A0 breaks the limit somewhere (the optimum is tight)."""
    from cams.verify.pressure import check_pressure

    d = _d(SEED_FORM)
    r = solve(d)
    A0 = d.follower.position(0.0)
    step = (A0 - r.centre) / np.linalg.norm(A0 - r.centre)
    assert not check_pressure(d, r.centre + 1e-4 * step).ok


def test_fixed_centre_distance_in_range():
    """Seed 3.23-3.25: the centre lies on the circle of radius L with the least R0 there."""
    free = solve(_d(SEED_FORCE))
    lo, hi = admissible_L_range(_d(SEED_FORCE))
    assert lo < free.L
    for L in (lo + 0.3 * (free.L - lo), free.L, free.L + 20):
        r = solve(_d(rocker_dict(limits={"centre_distance": L})))
        assert r.mode == "fixed_L"
        assert np.linalg.norm(r.centre) == pytest.approx(L, rel=1e-12)
        assert r.pressure.ok
        assert r.R0 >= free.R0 - 1e-9
    r = solve(_d(rocker_dict(limits={"centre_distance": free.L})))
    assert r.R0 == pytest.approx(free.R0, abs=1e-7)


def test_fixed_centre_distance_out_of_range_names_the_range():
    lo, _ = admissible_L_range(_d(SEED_FORCE))
    with pytest.raises(InfeasibleError, match=r"limits.centre_distance.*admissible L from"):
        solve(_d(rocker_dict(limits={"centre_distance": 0.5 * lo})))


def test_constructive_floor_places_centre_inside_with_margin():
    free = solve(_d(SEED_FORM))
    floor = free.R0 * 1.5
    r = solve(_d(rocker_dict(limits={"closure": "form", "return_pressure_angle": 40, "min_base_radius": floor})))
    assert r.mode == "floor_R0"
    assert r.R0 == pytest.approx(floor, rel=1e-12)
    assert r.margin > 0
    assert r.pressure.ok and r.pressure.rise < r.pressure.rise_limit
    low = solve(_d(rocker_dict(limits={"min_base_radius": 1.0})))
    assert low.mode == "min_R0" and any("not binding" in n for n in low.notes)


def test_objective_L_gives_smaller_L():
    a = solve(_d(SEED_FORCE))
    b = solve(_d(SEED_FORCE), objective="L")
    assert b.L <= a.L + 1e-12 and b.R0 >= a.R0 - 1e-12 and b.pressure.ok


def test_mirror_invariance():
    """Flipping both senses mirrors the centre in X and keeps R0."""
    a = solve(_d(SEED_FORM))
    b = solve(_d(rocker_dict(limits={"closure": "form", "return_pressure_angle": 40},
                             follower={"rise_direction": "ccw"}, cam={"rotation": "cw"})))
    assert b.R0 == pytest.approx(a.R0, rel=1e-11)
    assert np.allclose(b.centre, a.centre * [1, -1], atol=1e-9)


def test_safety_factor_increases_size_and_margin():
    a = solve(_d(SEED_FORM))
    b = solve(_d(rocker_dict(limits={"closure": "form", "return_pressure_angle": 40, "safety_factor": 1.2})))
    assert b.R0 > a.R0
    assert b.pressure.rise < a.pressure.rise_limit - 1e-3


TRANSLATING = {
    "follower": {"kind": "translating", "stroke": 30.0, "roller_radius": 5.0},
    "cam": {"rotation": "ccw"},
    "motion": [
        {"phase": "rise", "law": "poly345", "angle": 150},
        {"phase": "dwell", "angle": 30},
        {"phase": "return", "law": "cycloidal", "angle": 120},
        {"phase": "dwell"},
    ],
    "limits": {"pressure_angle": 30},
}


def test_translating_free_offset_beats_centric_and_matches_sampled():
    free = solve(design_from_dict(TRANSLATING))
    centric = solve(design_from_dict({**TRANSLATING, "follower": {**TRANSLATING["follower"], "offset": 0.0}}))
    assert free.R0 < centric.R0
    assert centric.offset == 0.0 and centric.mode == "fixed_offset"
    assert free.pressure.ok and centric.pressure.ok
    for m in ("convex", "exhaustive"):
        s = solve(design_from_dict(TRANSLATING).with_(samples=400), method=m)
        assert s.R0 <= free.R0 + 1e-9 and s.R0 == pytest.approx(free.R0, rel=1e-4)


def test_centric_translating_constant_velocity_textbook():
    """Centric translating follower: tan(gamma) = s'/(R0 + s); linear rise -> s'=h/beta constant.

    The largest pressure angle of a linear rise sits at s = 0, so R0 = (h/beta)/tan(gamma).
    """
    h, beta, g = 20.0, np.radians(90), np.radians(30)
    dct = {
        "follower": {"kind": "translating", "stroke": h, "offset": 0.0},
        "motion": [{"phase": "rise", "law": "linear", "angle": 90}, {"phase": "dwell", "angle": 90},
                   {"phase": "return", "law": "linear", "angle": 90}, {"phase": "dwell"}],
        "limits": {"pressure_angle": 30},
    }
    r = solve(design_from_dict(dct))
    assert r.R0 == pytest.approx((h / beta) / np.tan(g), rel=1e-12)


def test_empty_zone_is_an_infeasible_error():
    """A swing far beyond twice the limit leaves no common cone: a clear error, no NaN."""
    d = _d(rocker_dict(follower={"swing": 150.0}, limits={"closure": "form", "pressure_angle": 10}))
    with pytest.raises(InfeasibleError):
        solve(d)


def test_unknown_method_and_objective():
    with pytest.raises(InputError, match="solve.method"):
        solve(_d(SEED_FORCE), method="newton")
    with pytest.raises(InputError, match="solve.objective"):
        solve(_d(SEED_FORCE), objective="area")


def test_exhaustive_refuses_runs_that_cannot_fit_in_memory():
    """The all-pairs method's memory grows with the square of the samples: a clear error, not a crash."""
    d = _d(SEED_FORM, samples=50000)
    with pytest.raises(InputError, match="solve.samples.*GB"):
        solve(d, method="exhaustive")
