"""Motion design ([optimize]): the analytic anchors, a brute-force check of the certified answer, bad input.

References: the 3-4-5 polynomial minimizes the integral of the squared jerk with zero end velocity and
acceleration, the 4-5-6-7 the squared snap with zero end jerk as well (Euler-Lagrange: S^(6) = 0, S^(8) = 0);
the least peak acceleration with zero end velocities is the constant-acceleration law's, Ca = 4 (Norton, Cam
Design and Manufacturing Handbook, ch. 3).
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.io.designfile import design_from_dict, load_design
from cams.io.document import read_toml
from cams.io.lawtable import law_to_table
from cams.model.motiondesign import MotionDesignSpec
from cams.solve import solve
from laws.errors import InputError
from laws.standard import Parabolic, Poly345, Poly4567
from optimize.motion.design import design_laws
from tests.inprocess import cams_cli

EXAMPLE = "examples/translating_force.toml"


def _doc(**optimize):
    d = read_toml(EXAMPLE)
    d["optimize"] = optimize
    return d


def _slack_design():
    """The example with a far cam centre: the pressure limit never binds, the law problem stands alone."""
    d = read_toml(EXAMPLE)
    d["cam"]["centre"] = [0.0, -5000.0]
    return design_from_dict(d)


@pytest.mark.parametrize(("objective", "continuity", "degree", "law"), [
    ("jerk_squared", 2, 5, Poly345()),
    ("snap_squared", 3, 7, Poly4567()),
])
def test_smoothest_laws_are_the_polynomials(objective, continuity, degree, law):
    spec = MotionDesignSpec(objective=objective, continuity=continuity, degree=degree, spans=4)
    ld = design_laws(_slack_design(), spec)
    got = ld.program.law_of(0)
    u = np.linspace(0, 1, 401)
    for k in range(4):
        ref = law.evaluate(u)[k]
        assert np.max(np.abs(got.evaluate(u)[k] - ref)) <= 1e-6 * np.max(np.abs(ref)) + 1e-8
    assert ld.lower_bound <= ld.solver_value * (1 + 1e-9)


def test_least_peak_acceleration_is_constant_acceleration():
    spec = MotionDesignSpec(objective="Ca", continuity=1, degree=3, spans=8)
    ld = design_laws(_slack_design(), spec)
    u = np.linspace(0, 1, 2001)
    S = ld.program.law_of(0).evaluate(u)
    assert np.max(np.abs(S[2])) == pytest.approx(4.0, rel=1e-7)
    assert np.max(np.abs(S[0] - Parabolic().evaluate(u)[0])) < 1e-7
    assert 4.0 * (1 - 1e-7) <= ld.solver_value and ld.lower_bound <= 4.0 * (1 + 1e-9)


@pytest.fixture(scope="module")
def designed():
    return solve(design_from_dict(_doc(max_Ca="poly4567", max_Cj="poly4567", spans=10)))


def test_designed_cam_is_smaller_and_certified(designed):
    o = designed.optimization.to_dict()
    reference = solve(load_design(EXAMPLE))
    assert designed.verified and designed.certified is not False and o["certified"]
    assert designed.R0 < 0.8 * reference.R0
    assert o["reference"]["R0"] == pytest.approx(reference.R0, rel=1e-12)
    assert o["lower_bound"] <= designed.R0 and 0 <= o["gap"] < 0.05


def test_brute_force_pressure_and_caps(designed):
    """Dense evaluation, independent of the programs: tan(gamma) = (s' + eps x) / (d + s) at 200,001 angles."""
    design = designed.design
    x, d = designed.centre[0], -designed.centre[1]
    phi = np.linspace(0, design.program.phases[0].angle, 200_001)
    m = design.program.evaluate(phi)
    gamma = np.arctan2(np.abs(m.ds + design.cam_sense * x), d + m.s)
    assert gamma.max() <= design.limits.pressure_angle * (1 + 1e-9)
    u = np.linspace(0, 1, 200_001)
    S = design.program.law_of(0).evaluate(u)
    assert np.max(np.abs(S[2])) <= Poly4567().evaluate(np.linspace(0, 1, 200_001))[2].__abs__().max() * (1 + 1e-6)
    assert np.max(np.abs(S[3])) <= 52.5 * (1 + 1e-9)
    # minimality within rounding of the law: no admissible centre at R0 (1 - 1e-6) (the exact sizing's claim)
    R0 = np.hypot(x, d)
    ang = np.linspace(-np.pi / 2, np.pi / 2, 721)
    xs, ds = R0 * (1 - 1e-6) * np.sin(ang), R0 * (1 - 1e-6) * np.cos(ang)
    sub = slice(None, None, 200)
    g = np.arctan2(np.abs(m.ds[sub][None, :] + design.cam_sense * xs[:, None]), ds[:, None] + m.s[sub][None, :])
    assert np.all(g.max(axis=1) > design.limits.pressure_angle)


def test_library_law_in_the_space_is_no_better():
    """poly345 lies in the degree-5, C2 space: with caps just above its peaks the joint optimum is no larger."""
    ref = solve(design_from_dict({**read_toml(EXAMPLE), "motion": [
        {"phase": "rise", "law": "poly345", "angle": 150}, {"phase": "dwell", "angle": 30},
        {"phase": "return", "law": "cycloidal", "angle": 120}, {"phase": "dwell"}]}))
    doc = read_toml(EXAMPLE)
    doc["motion"][0]["law"] = "poly345"
    doc["optimize"] = {"max_Ca": 5.7735 * 1.01, "max_Cj": 60 * 1.01, "continuity": 2, "degree": 5, "spans": 8}
    got = solve(design_from_dict(doc))
    assert got.R0 <= ref.R0 * (1 + 1e-9)
    assert got.optimization.lower_bound <= got.R0


def test_round_trip_through_a_spline_table(designed, tmp_path):
    doc = read_toml(EXAMPLE)
    doc["motion"][0]["law"] = law_to_table(designed.design.program.law_of(0))
    again = solve(design_from_dict(doc))
    assert again.R0 == pytest.approx(designed.R0, rel=1e-12)


@pytest.mark.parametrize(("optimize", "field"), [
    ({"max_Ca": 3.5, "continuity": 1, "degree": 3, "spans": 8}, "optimize.max_Ca"),
    ({"continuity": 3, "degree": 3}, "optimize.degree"),
    ({"objective": "L"}, "optimize.objective"),
    ({"objective": "speed"}, "optimize.objective"),
    ({"free": ["dwell"]}, "optimize.free"),
    ({"free": [1]}, "optimize.free"),
    ({"spans": 0}, "optimize.spans"),
    ({"colour": 1}, "optimize"),
    ({"objective": "pressure_angle", "max_Ca": 0.5}, "optimize.max_Ca"),
    ({"max_Cj": "harmonic"}, "optimize.max_Cj"),
])
def test_bad_requests_name_the_field(optimize, field):
    with pytest.raises(InputError) as e:
        solve(design_from_dict(_doc(**optimize)))
    assert e.value.field == field


def test_both_objectives_refused():
    d = _doc()
    d["solve"] = {"objective": "R0"}
    with pytest.raises(InputError) as e:
        design_from_dict(d)
    assert e.value.field == "solve.objective"


def test_command_line_bad_cap_exits_2(tmp_path):
    import tomllib  # noqa: F401  (the file is written by hand below)

    text = open(EXAMPLE, encoding="utf-8").read() + '\n[optimize]\nmax_Ca = 3.5\ncontinuity = 1\ndegree = 3\n'
    p = tmp_path / "bad.toml"
    p.write_text(text, encoding="utf-8")
    r = cams_cli("solve", p)
    assert r.returncode == 2
    assert r.stderr.count("\n") == 1 and "optimize.max_Ca" in r.stderr


# -- the numbers the product prints, each against something independent -------------------------------------------


def test_linear_pressure_form_is_the_kernels_pressure_angle():
    """The programs' rows rest on |tan(gamma)| = |s' + eps x| / (d + s): the kernel's inversion gives the same
    (its sign follows the follower's velocity, which turns on the return; the limits bound the magnitude)."""
    from cams.kinematics.inversion import invert_at, pressure_angle

    base = load_design(EXAMPLE)
    for sense in (1, -1):
        design = base.with_(cam_sense=sense)
        x, d = 3.0, 40.0
        phi = np.linspace(0, 2 * np.pi, 721)
        m = design.program.evaluate(phi)
        kernel = pressure_angle(invert_at(design, np.array([x, -d]), phi))
        assert np.allclose(np.abs(np.tan(kernel)), np.abs(m.ds + sense * x) / (d + m.s), rtol=0, atol=1e-12)


def _slack_doc(**optimize):
    d = read_toml(EXAMPLE)
    d["cam"]["centre"] = [0.0, -5000.0]
    d["optimize"] = optimize
    return d


@pytest.mark.parametrize(("objective", "continuity", "degree", "exact"), [
    # integral of (60 - 360 u + 360 u^2)^2 over [0, 1]: the 3-4-5 polynomial's squared jerk
    ("jerk_squared", 2, 5, 720.0),
    # the 4-5-6-7 polynomial's squared snap, by numpy's polynomial algebra on its coefficients
    ("snap_squared", 3, 7, None),
])
def test_squared_objectives_value_and_bound(objective, continuity, degree, exact):
    P = np.polynomial.Polynomial
    if exact is None:
        snap = P([0, 0, 0, 0, 35, -84, 70, -20]).deriv(4)
        exact = float((snap**2).integ()(1.0))
    o = solve(design_from_dict(_slack_doc(objective=objective, continuity=continuity, degree=degree,
                                          spans=4))).optimization.to_dict()
    assert o["value"] == pytest.approx(exact, rel=1e-7)
    assert o["lower_bound"] <= exact and o["gap"] < 1e-6


def test_printed_peaks_are_the_laws_dense_peaks(designed):
    """Cv, Ca, Cj beside the original law's: the designed law's dense maxima (200,001 points)."""
    law = designed.design.program.law_of(0)
    S = law.evaluate(np.linspace(0, 1, 200_001))
    p = designed.optimization.phases[0]
    for k, key in ((1, "Cv"), (2, "Ca"), (3, "Cj")):
        assert p[key] == pytest.approx(np.max(np.abs(S[k])), rel=1e-6)
    assert p["original"] == {"law": "poly4567", "Cv": pytest.approx(2.1875, rel=1e-6),
                             "Ca": pytest.approx(7.5132, rel=1e-4), "Cj": pytest.approx(52.5, rel=1e-6),
                             "jerk_variation": pytest.approx(273.0, rel=1e-6)}


def test_least_pressure_angle_at_todays_size():
    """objective = "pressure_angle": the value is the largest ratio of pressure angle to limit, by the kernel's
    inversion at 100,001 angles; the original law at its own least R0 has ratio 1, so the design must beat it."""
    from cams.kinematics.inversion import invert_at, pressure_angle

    res = solve(design_from_dict(_doc(objective="pressure_angle", max_Ca="poly4567", max_Cj="poly4567", spans=8)))
    o = res.optimization.to_dict()
    design = res.design
    beta = design.program.phases[0].angle
    phi = np.linspace(0, beta, 100_001)
    g = np.abs(pressure_angle(invert_at(design, res.centre, phi)))
    assert o["value"] == pytest.approx(g.max() / design.limits.pressure_angle, rel=1e-7)
    assert o["lower_bound"] <= o["value"] < 1.0
    assert res.R0 <= o["held_R0"] * (1 + 1e-12)


def test_flat_face_from_a_file():
    """A flat face: R0 + s + s'' >= min_radius at 200,001 angles of the designed rise, and a smaller cam."""
    flat = read_toml("examples/translating_flat.toml")
    reference = solve(design_from_dict(flat))
    flat["optimize"] = {"max_Ca": "cycloidal", "max_Cj": "cycloidal", "continuity": 2, "degree": 6, "spans": 8}
    res = solve(design_from_dict(flat))
    o = res.optimization.to_dict()
    assert o["certified"] and o["lower_bound"] <= res.R0 < reference.R0
    assert o["reference"]["R0"] == pytest.approx(reference.R0, rel=1e-12)
    m = res.design.program.evaluate(np.linspace(0, 2 * np.pi, 200_001))
    assert np.min(res.R0 + m.s + m.d2s) >= res.design.min_radius * (1 - 1e-9)


# -- cams solve --save-design: the designed laws as a design file ----------------------------------------------------


def _designed_file(tmp_path, extra: str = "", roller: float | None = None):
    text = open(EXAMPLE, encoding="utf-8").read()
    if roller is not None:
        text = text.replace("roller_radius = 8.0", f"roller_radius = {roller}")
    f = tmp_path / "designed.toml"
    f.write_text(text + '\n[optimize]\nmax_Ca = "poly4567"\nmax_Cj = "poly4567"\nspans = 6\n' + extra,
                 encoding="utf-8")
    return f


def _cli(*args):
    """``cams ARGS`` in this process (tests/inprocess.py): exit code, stdout, stderr."""
    return cams_cli(*args)


def test_saved_design_solves_to_the_same_cam(tmp_path):
    import json

    f = _designed_file(tmp_path)
    out = tmp_path / "saved.toml"
    r = _cli("solve", f, "--json", "--save-design", out)
    assert r.returncode == 0, r.stderr
    rep = json.loads(r.stdout)
    assert rep["saved_design"] == str(out)
    saved = load_design(out)
    assert saved.optimize is None
    again = solve(saved)
    assert again.R0 == rep["R0"] and again.verified
    assert saved.program.law_of(0).coefficients == solve(load_design(f)).design.program.law_of(0).coefficients


def test_save_design_refused_without_optimize_or_to_stdout(tmp_path):
    r = _cli("solve", EXAMPLE, "--save-design", tmp_path / "x.toml")
    assert r.returncode == 2 and "--save-design" in r.stderr and r.stderr.count("\n") == 1
    assert not (tmp_path / "x.toml").exists()
    r = _cli("solve", _designed_file(tmp_path), "--save-design", "-")
    assert r.returncode == 2 and "name a file" in r.stderr
    f = _designed_file(tmp_path)
    before = f.read_text(encoding="utf-8")
    r = _cli("solve", f, "--save-design", f)        # the request itself would be lost
    assert r.returncode == 2 and "--save-design" in r.stderr and r.stderr.count("\n") == 1
    assert f.read_text(encoding="utf-8") == before


def test_failing_design_is_not_saved(tmp_path):
    """A chosen cam whose bore does not fit (the least Ca designed at that size): it fails, exit 1, no file."""
    out = tmp_path / "saved.toml"
    f = _designed_file(tmp_path, extra='objective = "Ca"\n')
    text = f.read_text(encoding="utf-8").replace('rotation = "ccw"', 'rotation = "ccw"\nbase_radius = 30.0\n'
                                                 'bore_radius = 29.0').replace("roller_radius = 8.0",
                                                                               "roller_radius = 8.0\noffset = 0.0")
    f.write_text(text, encoding="utf-8")
    r = _cli("solve", f, "--save-design", out)
    assert r.returncode == 1
    assert not out.exists() and "not written" in r.stdout


def _twelve_mm_roller_doc(k: float = 1.0) -> dict:
    """The designed rise (10 spans) with a 12 mm roller, its lengths ``k`` times larger."""
    doc = _doc(max_Ca="poly4567", max_Cj="poly4567", spans=10)
    doc["follower"]["roller_radius"] = 12.0 * k
    doc["follower"]["stroke"] *= k
    return doc


@pytest.fixture(scope="module")
def twelve_mm_roller():
    """The designed rise with a 12 mm roller, solved once for the two tests of its fallback."""
    return solve(design_from_dict(_twelve_mm_roller_doc()))


def test_optimum_failing_the_profile_checks_gives_the_smallest_passing_cam(twelve_mm_roller):
    """A 12 mm roller: the optimum (R0 10.97 mm) has no working profile; the designed law's smallest cam that
    passes is returned, judged by the commands' one rule (cams.assess), and slightly below it none passes."""
    from dataclasses import replace

    from cams.cam import Cam
    from cams.solve import profile_passes

    res = twelve_mm_roller
    o = res.optimization.to_dict()
    assert res.R0 > 12.0 and any("fails the profile's checks" in n for n in o["notes"])
    assert o["lower_bound"] <= res.R0 and o["certified"]
    cam = Cam(res.design.with_(limits=replace(res.design.limits, min_base_radius=res.R0)))
    assert cam.assessment.usable
    below = solve(res.design.with_(limits=replace(res.design.limits, min_base_radius=res.R0 * (1 - 1e-6)),
                                   constraints="pressure_angle"))
    assert not profile_passes(below)


def test_the_smallest_passing_cam_is_the_same_at_a_large_scale(twelve_mm_roller):
    """The same fallback a million times larger (the sizing to the part's search, on exact extrema): R0 in
    proportion. The unscaled design (k = 1) is the module's solve of it."""
    got = {}
    for k in (1.0, 1e6):
        res = twelve_mm_roller if k == 1.0 else solve(design_from_dict(_twelve_mm_roller_doc(k)))
        assert any("fails the profile's checks" in n for n in res.optimization.notes)
        got[k] = res.R0 / k
    assert got[1e6] == pytest.approx(got[1.0], rel=1e-9)


@pytest.mark.parametrize("example", [EXAMPLE, "examples/rocker_force.toml", "examples/rocker_flat.toml"])
def test_no_free_phase_gives_todays_exact_answer(example):
    d = read_toml(example)
    today = solve(design_from_dict(d))
    d["optimize"] = {"free": []}
    res = solve(design_from_dict(d))
    assert res.R0 == today.R0 and res.optimization.value == today.R0
    lb = res.optimization.lower_bound
    assert lb is None or lb <= today.R0


@pytest.mark.parametrize(("example", "lengths", "optimize"), [
    (EXAMPLE, (("follower", "stroke"), ("follower", "roller_radius")),
     {"max_Ca": "poly4567", "max_Cj": "poly4567", "spans": 10}),
    ("examples/translating_flat.toml", (("follower", "stroke"), ("limits", "min_radius")),
     {"max_Ca": "cycloidal", "max_Cj": "cycloidal", "spans": 8, "continuity": 2, "degree": 6}),
    ("examples/rocker_force.toml", (("follower", "arm"), ("follower", "roller_radius")),
     {"max_Ca": "cycloidal", "max_Cj": "cycloidal", "spans": 8, "continuity": 2}),
    ("examples/rocker_flat.toml", (("follower", "centre_distance"), ("limits", "min_radius")),
     {"free": ["rise", "return"], "max_Ca": "cycloidal", "max_Cj": "cycloidal", "spans": 6, "continuity": 2}),
])
def test_every_unit_scale_gives_the_same_design(example, lengths, optimize):
    """The same design in units 1000 times smaller and larger: R0 and its bound in proportion."""
    got = {}
    for k in (1e-3, 1.0, 1e3):
        d = read_toml(example)
        for table, key in lengths:
            d[table][key] *= k
        d["optimize"] = optimize
        res = solve(design_from_dict(d))
        o = res.optimization.to_dict()
        assert res.verified and o["certified"]
        got[k] = (res.R0 / k, None if o["lower_bound"] is None else o["lower_bound"] / k)
    for k in (1e-3, 1e3):
        assert got[k][0] == pytest.approx(got[1.0][0], rel=1e-5)
        if got[k][1] is not None:
            assert got[k][1] == pytest.approx(got[1.0][1], rel=1e-4) and got[k][1] <= got[k][0]


def test_the_declared_box_is_not_touched(designed):
    """Ca and Cj capped, continuity 3: the jerk's and acceleration's variables need no box of their own (the
    caps imply one); S and S' at the knots have a declared one, which the answer stays well inside."""
    from optimize.motion.space import Space

    o = designed.optimization.to_dict()
    assert not any("bound on their coefficients" in n for n in o["notes"])
    law = designed.design.program.law_of(0)
    S = law.evaluate(np.array(law.breaks))
    sp = Space(designed.design.program, (0,), o["degree"], o["spans"], o["continuity"])
    box = sp.bounds({(0, 2): 7.513188404399298, (0, 3): 52.5})
    assert np.max(np.abs(S[0])) < 0.2 * box[sp.top + 1] and np.max(np.abs(S[1])) < 0.1 * box[sp.top + 2]
