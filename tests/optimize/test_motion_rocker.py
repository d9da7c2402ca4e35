"""The rocker roller's motion design (sequential convex programming around the exact zone).

Independent references: the kernel's inversion for the pressure angle at dense cam angles, the laws' own
derivatives for the caps, the exact sizing of a law written to a file for the value, finite differences for the
linearization's rates.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from cams.io.designfile import design_from_dict, load_design
from cams.io.document import read_toml
from cams.io.lawtable import law_to_table
from cams.kinematics.inversion import invert_at, pressure_angle
from cams.solve import solve
from laws.errors import InputError
from optimize.zone import phase_wedges, side_terms

FORCE = "examples/rocker_force.toml"
FORM = "examples/rocker_form.toml"


def test_side_terms_are_the_wedges_and_their_rates():
    d = load_design(FORCE)
    u = np.linspace(0, 1, 9)
    lim = d.limits.pressure_angle
    m = d.program.evaluate_phase(0, u)
    O = np.array([130.0, 10.0])
    h, hs, hd, _ = side_terms(d, lim, m.s, m.ds, O)
    assert np.allclose(h, phase_wedges(d, 0, lim, u).violation(O), atol=1e-12)
    e = 1e-6
    assert np.allclose((side_terms(d, lim, m.s + e, m.ds, O)[0] - side_terms(d, lim, m.s - e, m.ds, O)[0]) / (2 * e),
                       hs, atol=1e-6)
    assert np.allclose((side_terms(d, lim, m.s, m.ds + e, O)[0] - side_terms(d, lim, m.s, m.ds - e, O)[0]) / (2 * e),
                       hd, atol=1e-6)


@pytest.fixture(scope="module")
def designed():
    doc = read_toml(FORCE)
    doc["optimize"] = {"max_Ca": "cycloidal", "max_Cj": "cycloidal", "continuity": 2, "spans": 8}
    return solve(design_from_dict(doc))


def test_rocker_design_is_smaller_checked_and_local(designed):
    o = designed.optimization.to_dict()
    reference = solve(load_design(FORCE))
    assert designed.verified and o["certified"] and o["method"] == "sequential convex programming"
    assert o["lower_bound"] is None and o["gap"] is None
    assert designed.R0 < 0.9 * reference.R0 and o["reference"]["R0"] == pytest.approx(reference.R0, rel=1e-12)
    assert o["value"] == designed.R0 and o["history"][-1] == pytest.approx(designed.R0, rel=1e-12)
    assert all(b < a for a, b in zip(o["history"], o["history"][1:], strict=False))
    assert 0 <= o["local_measure"] < 1e-3


def test_rocker_design_brute_force(designed):
    """The kernel's pressure angle at 100,001 angles of the rise within the limit; the caps at 200,001 points."""
    design = designed.design
    beta = design.program.phases[0].angle
    phi = np.linspace(0, beta, 100_001)
    g = np.abs(pressure_angle(invert_at(design, designed.centre, phi)))
    assert g.max() <= design.limits.pressure_angle * (1 + 1e-9)
    S = design.program.law_of(0).evaluate(np.linspace(0, 1, 200_001))
    assert np.max(np.abs(S[2])) <= 2 * np.pi * (1 + 1e-9)
    assert np.max(np.abs(S[3])) <= 4 * np.pi**2 * (1 + 1e-9)


def test_rocker_law_written_out_solves_to_the_same_cam(designed):
    doc = read_toml(FORCE)
    doc["motion"][0]["law"] = law_to_table(designed.design.program.law_of(0))
    again = solve(design_from_dict(doc))
    assert again.R0 == designed.R0


def test_rocker_least_centre_distance_form_closure():
    """Form closure with K_C = 1.1 and its own return limit, both phases free, L minimized."""
    doc = read_toml(FORM)
    doc["optimize"] = {"free": ["rise", "return"], "objective": "L", "max_Ca": "cycloidal", "max_Cj": "cycloidal",
                       "continuity": 2, "spans": 6}
    doc.pop("solve", None)
    res = solve(design_from_dict(doc))
    o = res.optimization.to_dict()
    assert res.verified and o["certified"] and o["value"] == res.L
    assert res.L < o["reference"]["L"]
    assert [p["phase"] for p in o["phases"]] == [0, 2]


@pytest.mark.parametrize(("optimize", "cam", "field"), [
    ({"objective": "Ca"}, {"centre": [134.0, 9.0]}, "optimize.objective"),
    ({"objective": "pressure_angle"}, {"centre": [134.0, 9.0]}, "optimize.objective"),
])
def test_rocker_refuses_what_it_does_not_design(optimize, cam, field):
    doc = read_toml(FORCE)
    doc["optimize"] = optimize
    doc["cam"].update(cam)
    with pytest.raises(InputError) as e:
        solve(design_from_dict(doc))
    assert e.value.field == field


@pytest.mark.parametrize("objective", ["Cj", "jerk_squared"])
def test_rocker_smoothest_law_at_the_original_size(objective):
    """The size held: the designed law's cam is no larger than the cycloidal law's least R0 (the independent
    check verifies it), and its jerk peak (dense, 200,001 points) or squared jerk (Gauss-Legendre on the
    original law: 16 pi^4 / 2 for the cycloid) is below the original's."""
    doc = read_toml(FORCE)
    doc["optimize"] = {"objective": objective, "max_Ca": "cycloidal", "continuity": 2, "spans": 6}
    res = solve(design_from_dict(doc))
    o = res.optimization.to_dict()
    assert res.verified and o["certified"] and res.R0 <= o["held_R0"] * (1 + 1e-12)
    S = res.design.program.law_of(0).evaluate(np.linspace(0, 1, 200_001))
    if objective == "Cj":
        assert o["value"] == pytest.approx(np.max(np.abs(S[3])), rel=1e-6) and o["value"] < 4 * np.pi**2
    else:
        assert o["value"] == pytest.approx(np.trapezoid(S[3] ** 2, dx=1 / 200_000), rel=1e-4)
        assert o["value"] < 8 * np.pi**4          # the cycloid's: integral of (4 pi^2 cos 2 pi u)^2
    assert np.max(np.abs(S[2])) <= 2 * np.pi * (1 + 1e-9)


def _least_ratio_of(law: str, hold: float) -> float:
    """A library law's least ratio of pressure angle to limit with its cam within ``hold`` (the rise of
    FORCE): bisection on the limit, each cam sized by the exact method (shares nothing with the SCP)."""
    lo, hi = 0.2, 1.0
    for _ in range(30):
        mid = 0.5 * (lo + hi)
        doc = read_toml(FORCE)
        doc["motion"][0]["law"] = law
        doc["limits"]["pressure_angle"] = 45.0 * mid
        if solve(design_from_dict(doc)).R0 <= hold:
            hi = mid
        else:
            lo = mid
    return hi


def test_rocker_least_pressure_angle_at_the_original_size():
    """The size held (the cycloid's least R0): the pressure angle at 100,001 angles of the rise (the kernel's
    inversion) is the value reported, below the limit, and no larger than the least ratio of the library
    laws within the cap (3-4-5 and modified sine: Ca below the cycloid's 2 pi) at that size."""
    doc = read_toml(FORCE)
    doc["optimize"] = {"objective": "pressure_angle", "max_Ca": "cycloidal", "continuity": 2, "spans": 8}
    res = solve(design_from_dict(doc))
    o = res.optimization.to_dict()
    assert res.verified and o["certified"] and o["method"] == "sequential convex programming"
    assert res.R0 <= o["held_R0"] * (1 + 1e-12) and o["lower_bound"] is None
    design = res.design
    phi = np.linspace(0, design.program.phases[0].angle, 100_001)
    g = np.abs(pressure_angle(invert_at(design, res.centre, phi)))
    assert o["value"] == pytest.approx(g.max() / design.limits.pressure_angle, rel=1e-6)
    assert o["value"] == pytest.approx(o["history"][-1], rel=1e-6)
    hold = o["held_R0"]
    assert hold == solve(load_design(FORCE)).R0 == o["reference"]["R0"]   # the cycloid's least R0, sized alone
    library = {law: _least_ratio_of(law, hold) for law in ("poly345", "modified_sine")}
    assert all(r < 1 for r in library.values())
    assert o["value"] <= min(library.values())
    S = design.program.law_of(0).evaluate(np.linspace(0, 1, 200_001))
    assert np.max(np.abs(S[2])) <= 2 * np.pi * (1 + 1e-9)


@pytest.mark.parametrize("centre_distance", [None, 140.0])
def test_rocker_least_pressure_angle_keeps_k_c_and_l(centre_distance):
    """Form closure, K_C = 1.1, both phases free: the ratio is the pressure angle's own (the kernel's inversion
    at 100,001 angles of each phase), below 1, with the centre inside K_C's stricter zone at the limits (wedges
    at 20,001 positions a phase: the model keeps 1e-4 of the arm inside them at its samples, more than they
    bulge between) and a fixed L kept."""
    from optimize.zone import wedges

    doc = read_toml(FORM)
    doc.pop("solve", None)
    if centre_distance is not None:
        doc["limits"]["centre_distance"] = centre_distance
    doc["optimize"] = {"free": ["rise", "return"], "objective": "pressure_angle", "max_Ca": "cycloidal",
                       "max_Cj": "cycloidal", "continuity": 2, "spans": 6}
    res = solve(design_from_dict(doc))
    o = res.optimization.to_dict()
    p = res.pressure
    assert res.verified and o["certified"] and res.R0 <= o["held_R0"] * (1 + 1e-12)
    d = res.design
    ratios = []
    for i, lim in ((0, p.rise_limit), (2, p.return_limit)):
        start, beta = d.program.starts[i], d.program.phases[i].angle
        phi = np.linspace(start, start + beta, 100_001)
        ratios.append(np.abs(pressure_angle(invert_at(d, res.centre, phi))).max() / lim)
    assert o["value"] == pytest.approx(max(ratios), rel=1e-6) and o["value"] < 0.9
    assert o["history"][-1] == pytest.approx(o["value"], rel=1e-6)
    if centre_distance is not None:
        assert res.L == pytest.approx(centre_distance, rel=1e-12)
    kc = replace(res.design, centre=None, limits=replace(load_design(FORM).limits,
                                                         centre_distance=centre_distance))
    assert kc.limits.safety_factor == 1.1
    u = np.linspace(0, 1, 20_001)
    worst = max(float(np.max(wedges(kc, {i: u}).violation(res.centre))) for i in (0, 2))
    assert worst <= 1e-8 * kc.scale
