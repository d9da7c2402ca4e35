"""cams.checks.profile: jamming from the profile, undercut and sharp points, polygon validity, bore."""

from __future__ import annotations

import json

import numpy as np
import pytest

from cams.checks.profile import (
    RECOMMENDED_ROLLER_FRACTION,
    check_profile,
    check_solution,
    curvature_extremes,
    pressure_from_profile,
)
from cams.kinematics.inversion import pitch_curve
from cams.model.options import ProfileOptions
from cams.solve import check_design
from cams.verify.pressure import check_pressure, pressure_angle
from laws.errors import InputError

ALL = ("rocker_force", "rocker_form", "translating_force", "translating_form_centric")
CHECK_KEYS = {"name", "passed", "worst", "at_deg", "limit", "unit"}


@pytest.fixture(scope="module")
def reports(solved):
    return {n: check_profile(d, O) for n, (d, O) in solved.items()}


@pytest.mark.parametrize("name", ALL)
def test_examples_pass_every_check(reports, name):
    rep = reports[name]
    assert rep.passed, [c for c in rep.checks if not c.passed]
    names = [c.name for c in rep.checks]
    form = name in ("rocker_form", "translating_form_centric")
    expected = ["jamming_rise"] + (["jamming_return"] if form else []) + ["undercut"] + \
        (["undercut_outer"] if form else []) + ["profile_polygon"] + (["outer_polygon"] if form else [])
    assert names == expected
    assert all(c.worst == 0 for c in rep.checks if c.name.endswith("polygon"))


@pytest.mark.parametrize("name", ALL)
def test_jamming_from_profile_agrees_with_the_pressure_module(solved, reports, name):
    """Two independent computations (pitch-curve tangent here, relative velocity there) agree."""
    design, O = solved[name]
    for i, p in enumerate(design.program.phases):
        if p.kind == "dwell":
            continue
        u = np.linspace(0, 1, 101)
        assert np.allclose(pressure_from_profile(design, O, i, u), pressure_angle(design, O, i, u), atol=1e-7)
    ref = check_pressure(design, O)
    rise = reports[name]["jamming_rise"]
    assert rise.worst == pytest.approx(np.degrees(ref.rise), abs=1e-6)
    assert rise.limit == pytest.approx(np.degrees(design.limits.pressure_angle))
    if design.limits.closure == "form":
        ret = reports[name]["jamming_return"]
        assert ret.worst == pytest.approx(np.degrees(ref.ret), abs=1e-6)
        assert ret.to_dict()["at_deg"] == pytest.approx(np.degrees(ref.ret_at), abs=1e-3)


def test_jamming_fails_for_a_centre_inside_the_zone_edge(solved):
    design, O = solved["translating_force"]
    A0 = design.follower.position(0.0)
    small = A0 + 0.8 * (O - A0)  # a smaller cam: steeper pressure angles
    rep = check_profile(design, small)
    j = rep["jamming_rise"]
    assert not j.passed and j.worst > j.limit and not rep.passed


def _dense_min_convex_rho(design, O, n=200_000):
    """Smallest convex radius of curvature by finite differences on the analytic pitch curve (tests only)."""
    h = 2 * np.pi / n
    phi = np.arange(n) * h
    P = pitch_curve(design, O, phi).point
    d1 = (np.roll(P, -1, 0) - np.roll(P, 1, 0)) / (2 * h)
    d2 = (np.roll(P, -1, 0) - 2 * P + np.roll(P, 1, 0)) / h**2
    k = -design.cam_sense * (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
    j = int(np.argmax(k))
    return 1 / k[j], np.degrees(phi[j]), -1 / np.min(k)


def test_roller_too_large_is_undercut_at_the_right_angle(solved, design_with):
    design, O = solved["rocker_form"]
    rho_min, at, _ = _dense_min_convex_rho(design, O)
    assert 170 < at < 180  # inside the return, not on a dwell: the angle is well defined
    big = design_with("rocker_form", follower={"roller_radius": 28.0})  # same pitch curve, same centre
    rep = check_profile(big, O)
    u = rep["undercut"]
    assert not u.passed and not rep.passed
    assert u.worst == pytest.approx(rho_min, rel=1e-6)
    assert u.to_dict()["at_deg"] == pytest.approx(at, abs=0.05)
    assert u.limit == 28.0
    assert rep.largest_roller_radius == pytest.approx(rho_min, rel=1e-6)
    assert rep.recommended_roller_radius == pytest.approx(RECOMMENDED_ROLLER_FRACTION * rho_min, rel=1e-6)
    # the working profile crosses itself there (a swallowtail spanning some degrees round it)
    poly = rep["profile_polygon"]
    assert not poly.passed and poly.worst >= 1 and poly.limit == 0
    assert poly.to_dict()["at_deg"] == pytest.approx(at, abs=15.0)
    # just below the limit: no undercut
    ok = check_profile(design_with("rocker_form", follower={"roller_radius": 0.99 * rho_min}), O)
    assert ok["undercut"].passed and ok["profile_polygon"].passed


def test_outer_wall_undercut_of_a_groove(solved, design_with):
    design, O = solved["rocker_form"]
    ext = curvature_extremes(design, O)
    _, _, concave = _dense_min_convex_rho(design, O)
    assert ext.concave == pytest.approx(concave, rel=1e-6)
    d = design_with("rocker_form", follower={"roller_radius": 1.05 * ext.concave})
    rep = check_profile(d, O)
    assert not rep["undercut_outer"].passed
    assert rep["undercut_outer"].to_dict()["at_deg"] == pytest.approx(np.degrees(ext.concave_at))
    assert rep.largest_roller_radius == pytest.approx(min(ext.convex, ext.concave))


def test_user_minimum_radius_of_curvature(solved):
    design, O = solved["rocker_form"]
    ext = curvature_extremes(design, O)
    r = design.follower.roller_radius
    for minimum, passed in ((ext.convex - r - 1, True), (ext.convex - r + 1, False)):
        rep = check_profile(design, O, options=ProfileOptions(min_curvature_radius=minimum))
        c = rep["min_curvature_radius"]
        assert c.passed is passed and c.worst == pytest.approx(ext.convex - r) and c.limit == minimum


def test_bore_is_checked_only_when_given(solved):
    """The default bore is derived to fit the profile: no check that cannot fail is listed."""
    design, O = solved["rocker_form"]
    assert "bore" not in [c.name for c in check_profile(design, O).checks]
    assert check_profile(design, O, options=ProfileOptions(bore_radius=5.0))["bore"].passed


def test_bore_too_large_fails(solved):
    design, O = solved["rocker_form"]
    rep = check_profile(design, O, options=ProfileOptions(bore_radius=19.0))
    b = rep["bore"]
    assert not b.passed and b.limit == 19.0 and b.worst == pytest.approx(rep.profile.min_work_radius)
    assert b.worst == pytest.approx(rep.profile.R0 - design.follower.roller_radius, abs=1e-3)


def test_knife_edge_has_no_sharp_point(solved, design_with):
    _, O = solved["rocker_force"]
    d = design_with("rocker_force", follower={"roller_radius": 0.0})
    rep = check_profile(d, O)
    assert rep["undercut"].passed and rep["undercut"].limit == 0.0
    assert rep["profile_polygon"].passed


def test_linear_rise_has_a_sharp_point_at_its_convex_end(design_with):
    """Constant velocity: a velocity jump gives the pitch curve corners; the convex one is a sharp point."""
    d = design_with("translating_force", motion=[
        {"phase": "rise", "law": "linear", "angle": 150}, {"phase": "dwell", "angle": 30},
        {"phase": "return", "law": "cycloidal", "angle": 120}, {"phase": "dwell"}])
    rep = check_profile(d, np.array([-5.0, -60.0]))
    u = rep["undercut"]
    assert not u.passed and u.worst == 0.0 and u.to_dict()["at_deg"] == pytest.approx(150.0)


@pytest.mark.parametrize("name", ["rocker_form", "translating_force"])
def test_report_json(reports, name):
    rep = reports[name].to_dict()
    text = json.dumps(rep, allow_nan=False)
    back = json.loads(text)
    assert back["passed"] is True and isinstance(back["checks"], list)
    for c in back["checks"]:
        assert set(c) == CHECK_KEYS
    assert back["points"] == len(reports[name].profile)
    assert back["largest_roller_radius"] > back["recommended_roller_radius"] > 0


def test_check_design_solves_first_and_rejects_bad_tolerance(solved):
    design, O = solved["translating_form_centric"]
    rep = check_design(design, tolerance=1e-2)
    assert rep.passed and np.allclose(rep.profile.centre, O)
    assert rep.profile.tolerance == 1e-2
    with pytest.raises(InputError, match="--tolerance"):
        check_design(design, tolerance=-1.0)


def test_check_solution_takes_a_solve_result(solved):
    from cams.solve import solve

    design, _ = solved["translating_force"]
    res = solve(design)
    rep = check_solution(res, tolerance=5e-3)
    assert rep.passed and rep.profile.tolerance == 5e-3
