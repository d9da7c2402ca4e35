"""Sizing to the part (issue 21): the smallest cam of the floor family that clears the bore by its hub wall and
passes the profile's checks, certified at three unit scales against references that share no formula with it.

The references: the cam's smallest radius as the largest circle about the cam centre that no roller disc reaches,
``min |A(phi) - O| - r`` over a dense set of cam angles (the fixed frame, no inversion, no profile); the pitch
curve's radius of curvature from central differences of the inverted roller centre ``R(-eps phi) (A(s(phi)) - O)``
(the model's follower position and the program only, not the kernel's derivatives); the pressure angle by the
independent check (:mod:`cams.verify.pressure`). The family's cam just below the answer, at R0 (1 - 1e-6), is
sized by the pressure angle alone with that floor, and fails.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from cams.cli import main
from cams.io.designfile import design_from_dict
from cams.solve import solve
from cams.verify.pressure import check_pressure
from laws.errors import InfeasibleError, InputError
from tests.conftest import rocker_dict

HARMONIC = [{"phase": "rise", "law": "harmonic", "angle": 120}, {"phase": "dwell", "angle": 30},
            {"phase": "return", "law": "harmonic", "angle": 120}, {"phase": "dwell"}]


def _scaled(d: dict, k: float) -> dict:
    """The design file ``d`` with every length times ``k`` (the follower's, the bore's, the limits' lengths)."""
    out = json.loads(json.dumps(d))
    for table, keys in (("follower", ("arm", "stroke", "offset", "roller_radius")),
                        ("cam", ("bore_radius", "hub_wall")), ("limits", ("centre_distance", "min_base_radius")),
                        ("profile", ("min_curvature_radius",))):
        for key in keys:
            if key in out.get(table, {}):
                out[table][key] *= k
    return out


def _swept_smallest(design, centre, n: int = 400_001) -> float:
    """The cam's smallest radius from the fixed frame: ``min |A(phi) - O| - r`` on a dense even grid."""
    phi = np.linspace(0.0, 2 * np.pi, n)
    A = design.follower.position(design.program.evaluate(phi).s)
    return float(np.min(np.linalg.norm(A - np.asarray(centre), axis=1)) - design.follower.roller_radius)


def _pitch_rho_min(design, centre, n: int = 200_000) -> float:
    """The pitch curve's smallest convex radius of curvature, by central differences of the inverted roller centre
    (convex: the curve turns with the cam's sense of rotation reversed, as it runs round the centre); good to
    about 1e-7 of it (the differences' truncation and rounding)."""
    h = 2 * np.pi / n
    phi = np.arange(n) * h + h / 2     # off the phase joints

    def P(x):
        r = design.follower.position(design.program.evaluate(x).s) - np.asarray(centre)
        c, s = np.cos(-design.cam_sense * x), np.sin(-design.cam_sense * x)
        return np.stack([c * r[:, 0] - s * r[:, 1], s * r[:, 0] + c * r[:, 1]], axis=-1)

    d = 1e-4
    p0, pp, pm = P(phi), P(phi + d), P(phi - d)
    d1, d2 = (pp - pm) / (2 * d), (pp - 2 * p0 + pm) / d**2
    k = -design.cam_sense * (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
    return float(1.0 / k.max())


def _below(design, R0: float):
    """The family's cam at R0 (1 - 1e-6): the pressure angle alone, floored there."""
    return solve(design.with_(constraints="pressure_angle").with_floor(R0 * (1 - 1e-6)))


@pytest.mark.parametrize("k", [1e-3, 1.0, 1e3])
def test_the_bore_governs_a_smallest_radius_of_15_mm_tight_and_minimal_at_three_scales(k):
    """Issue 21, done when: rocker_force with bore_radius = 10 and hub_wall = 5: the smallest cam that fits has a
    smallest radius of 15 mm, tight; the bore governs; the pressure angle's own R0 is beside it."""
    d = design_from_dict(_scaled(rocker_dict(cam={"rpm": 60, "bore_radius": 10.0, "hub_wall": 5.0}), k))
    res = solve(d)
    rep = res.to_dict()
    alone = solve(d.with_(constraints="pressure_angle"))
    assert res.governs == rep["governs"] == "bore"
    assert rep["pressure_angle_R0"] == alone.R0 == pytest.approx(13.240793033539 * k, rel=1e-9)
    # it passes: verified independently, and its smallest radius is the bore and the wall, 15 mm, tight
    assert check_pressure(d, res.centre).ok
    swept = _swept_smallest(d, res.centre)
    assert swept == pytest.approx(15.0 * k, rel=1e-9) and swept >= 15.0 * k * (1 - 1e-12)
    assert rep["smallest_cam_radius"] == pytest.approx(15.0 * k, rel=1e-12)
    assert rep["hub_wall"] == pytest.approx(5.0 * k, rel=1e-9) and rep["hub_wall_required"] == 5.0 * k
    assert _pitch_rho_min(d, res.centre) > d.follower.roller_radius
    # minimal: one step below on the same family the bore fails (the swept radius below 15 mm)
    below = _below(d, res.R0)
    assert below.R0 == pytest.approx(res.R0 * (1 - 1e-6), rel=1e-12)
    assert _swept_smallest(d, below.centre) < 15.0 * k * (1 - 1e-7)
    # the scales agree: the answer is exactly proportional
    assert res.R0 / k == pytest.approx(25.0, rel=1e-12)


def test_the_bore_example_passes_every_command(tmp_path, capsys):
    """cams solve says the bore governs and the pressure angle's own R0; cams check passes; exit 0."""
    d = rocker_dict(cam={"rpm": 60, "bore_radius": 10.0, "hub_wall": 5.0})
    f = tmp_path / "bore.toml"
    from cams.io.tomlwrite import dumps

    f.write_text(dumps(d), encoding="utf-8")
    assert main(["solve", str(f)]) == 0
    out = capsys.readouterr().out
    assert "governs: the bore and its hub wall (the pressure angle alone: R0 = 13.240793 mm)" in out
    assert "Rmin    = 15.000000 mm" in out and "bore    = 10.000000 mm, hub wall 5.000000 mm" in out
    assert main(["check", str(f), "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    bore = next(c for c in rep["checks"] if c["name"] == "bore")
    assert bore["passed"] and bore["worst"] == pytest.approx(15.0, rel=1e-12) and bore["limit"] == 15.0


@pytest.mark.parametrize("k", [1e-3, 1.0, 1e3])
def test_a_harmonic_rise_with_the_10_mm_roller_is_governed_by_the_roller(k):
    """Issue 21, done when: the pressure angle alone gives R0 = 9.47 mm, below the roller; sized to the part the
    answer passes the undercut check (the pitch curve's radius of curvature, by central differences, above the
    roller) and says the roller governs; just below it, the undercut fails."""
    d = design_from_dict(_scaled(rocker_dict(motion=HARMONIC), k))
    res = solve(d)
    r = d.follower.roller_radius
    assert res.governs == "undercut" and res.pressure_angle_R0 == pytest.approx(9.467812491 * k, rel=1e-8)
    assert check_pressure(d, res.centre).ok
    from cams.cam import Cam

    cam = Cam(d)
    assert cam.checks["undercut"].passed and cam.assessment.usable, cam.assessment.failures
    assert res.R0 > r                                                  # the base circle, a circle of radius R0
    assert _pitch_rho_min(d, res.centre) > r * (1 - 1e-6)             # and everywhere else
    below = _below(d, res.R0)
    assert _pitch_rho_min(d, below.centre) < r * (1 - 5e-7) and below.R0 < r     # the base circle inside it
    assert any("bore_radius" in n for n in res.notes)                  # no bore: its smallest radius tends to 0


def test_the_pressure_angle_alone_is_the_previous_answer_and_fails_the_bore():
    d = design_from_dict(rocker_dict(cam={"bore_radius": 10.0}, solve={"constraints": "pressure_angle"}))
    res = solve(d)
    assert res.governs == "pressure_angle" and res.R0 == pytest.approx(13.240793033539, rel=1e-11)
    from cams.cam import Cam

    a = Cam(d).assessment
    assert not a.buildable and any(f.startswith("bore") for f in a.failures)


def _family_passes(design, floors):
    """Whether each floor's cam of the family (the pressure angle alone, floored) passes every constraint of the
    part, judged by the pipeline's verdict."""
    from cams.faces import face_of
    from cams.faces.part import judge

    face = face_of(design)
    alone = design.with_(constraints="pressure_angle")
    return [judge(face, design, face.size(alone.with_floor(F))).passed for F in floors]


#: Families of every kind (free, fixed L, fixed offset; roller and flat face; each constraint governing).
FAMILIES = {
    "rocker bore": rocker_dict(cam={"bore_radius": 10.0, "hub_wall": 5.0}),
    "rocker harmonic (undercut)": rocker_dict(motion=HARMONIC),
    "rocker swinging in, bore": rocker_dict(follower={"swing": 30.0}, limits={"pressure_angle": 40},
                                            cam={"rotation": "cw", "bore_radius": 20.0}),
    "rocker curvature": rocker_dict(profile={"min_curvature_radius": 8.0}),
    "rocker fixed L, bore": rocker_dict(limits={"centre_distance": 140.0}, cam={"bore_radius": 40.0}),
    "translating bore": {"follower": {"kind": "translating", "stroke": 20.0, "roller_radius": 10.0},
                         "cam": {"bore_radius": 15.0, "hub_wall": 3.0},
                         "motion": [{"phase": "rise", "law": "cycloidal", "angle": 100}, {"phase": "dwell", "angle": 40},
                                    {"phase": "return", "law": "cycloidal", "angle": 100}, {"phase": "dwell"}],
                         "limits": {"pressure_angle": 30}},
    "translating short rise (undercut)": {
        "follower": {"kind": "translating", "stroke": 20.0, "roller_radius": 15.0},
        "motion": [{"phase": "rise", "law": "cycloidal", "angle": 40}, {"phase": "dwell", "angle": 40},
                   {"phase": "return", "law": "cycloidal", "angle": 40}, {"phase": "dwell"}],
        "limits": {"pressure_angle": 30}},
    "translating fixed offset, bore": {
        "follower": {"kind": "translating", "stroke": 20.0, "roller_radius": 10.0, "offset": 5.0},
        "cam": {"bore_radius": 15.0},
        "motion": [{"phase": "rise", "law": "poly345", "angle": 100}, {"phase": "dwell", "angle": 40},
                   {"phase": "return", "law": "poly345", "angle": 100}, {"phase": "dwell"}],
        "limits": {"pressure_angle": 30}},
    "flat rocker bore": {"follower": {"kind": "rocker", "face": "flat", "swing": 15.0, "centre_distance": 120.0},
                         "cam": {"bore_radius": 50.0, "hub_wall": 2.0},
                         "motion": [{"phase": "rise", "law": "cycloidal", "angle": 120},
                                    {"phase": "dwell", "angle": 40},
                                    {"phase": "return", "law": "poly345", "angle": 120}, {"phase": "dwell"}],
                         "limits": {"min_radius": 5.0}},
}


@pytest.mark.parametrize("name", sorted(FAMILIES))
def test_passing_is_monotone_along_the_floor_family(name):
    """Every floor's cam fails below the answer and passes above it (24 floors from the pressure angle's minimum
    to the answer, 12 from it to twice it), and the constraint said to govern is what fails just below."""
    d = design_from_dict(FAMILIES[name])
    res = solve(d)
    start = res.pressure_angle_R0 or solve(d.with_(constraints="pressure_angle")).R0
    below = np.linspace(start, res.R0, 25)[:-1]
    above = np.linspace(res.R0, 2 * res.R0, 12)
    assert not any(_family_passes(d, below)), name
    assert all(_family_passes(d, above)), name
    from cams.faces import face_of
    from cams.faces.part import judge

    face = face_of(d)
    just = judge(face, d, face.size(d.with_(constraints="pressure_angle").with_floor(res.R0 * (1 - 1e-6))))
    assert res.governs in just.failing


def test_seeded_random_rockers_are_monotone_and_minimal():
    """Random rockers (swing, arm, roller, limit, bore, senses): along each floor family passing is monotone on
    16 floors, and the cam 1e-6 below the answer fails."""
    rng = np.random.default_rng(21)
    for _ in range(4):
        d = design_from_dict(rocker_dict(
            follower={"swing": float(rng.uniform(10, 30)), "arm": float(rng.uniform(80, 160)),
                      "roller_radius": float(rng.uniform(5, 20)),
                      "rise_direction": str(rng.choice(["cw", "ccw"]))},
            cam={"rotation": str(rng.choice(["cw", "ccw"])), "bore_radius": float(rng.uniform(5, 30))},
            limits={"pressure_angle": float(rng.uniform(30, 50))}))
        res = solve(d)
        start = res.pressure_angle_R0
        floors = np.linspace(start, 2 * res.R0, 16)
        got = _family_passes(d, floors)
        assert got == [bool(F >= res.R0) for F in floors]
        if res.governs != "pressure_angle":   # else the floors below it do not bind: the exact method's minimum
            assert not _family_passes(d, [res.R0 * (1 - 1e-6)])[0]


def test_a_chosen_cam_that_fails_the_bore_says_the_least_R0_that_fits():
    """The chosen cam (R0 13.24 at L 134.69) cannot take a 20 mm bore: a note gives the least R0 that fits at that
    L, which is the design sized without the chosen cam."""
    d = design_from_dict(rocker_dict(cam={"bore_radius": 20.0, "base_radius": 13.240793},
                                     limits={"centre_distance": 134.688464}))
    res = solve(d)
    assert res.governs == "chosen"
    (note,) = [n for n in res.notes if n.startswith("bore:")]
    fits = solve(d.unchosen())
    assert fits.governs == "bore" and f"the least R0 that fits is {fits.R0:.6g} mm" in note
    assert fits.L == pytest.approx(134.688464, rel=1e-9)


def test_a_chosen_cam_whose_bore_no_cam_of_its_L_clears_is_refused(tmp_path, capsys):
    """A chosen cam (R0 at L = 140 mm) with a bore beyond every cam of that L: one line naming the bore, exit 2."""
    from cams.io.tomlwrite import dumps

    f = tmp_path / "chosen.toml"
    f.write_text(dumps(rocker_dict(cam={"bore_radius": 200.0, "base_radius": 30.0},
                                   limits={"centre_distance": 140.0})), encoding="utf-8")
    assert main(["check", str(f)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("cams check: error: cam.bore_radius: the chosen cam's smallest radius")


@pytest.mark.parametrize("cam, field", [
    ({"bore_radius": 200.0}, "cam.bore_radius"),                    # beyond every cam at this L
    ({"bore_radius": 100.0, "hub_wall": 60.0}, "cam.hub_wall"),     # the bore alone fits; the wall does not
])
def test_a_bore_no_cam_of_a_fixed_L_can_clear_is_refused(cam, field):
    d = design_from_dict(rocker_dict(limits={"centre_distance": 140.0}, cam=cam))
    with pytest.raises(InfeasibleError) as e:
        solve(d)
    assert e.value.field == field and "no cam of this design meets it" in str(e.value)


@pytest.mark.parametrize("over, field", [
    ({"cam": {"bore_radius": 10.0, "hub_wall": -1.0}}, "cam.hub_wall"),
    ({"cam": {"hub_wall": 2.0}}, "cam.hub_wall"),
    ({"solve": {"constraints": "some"}}, "solve.constraints"),
    ({"limits": {"centre_distance": 140.0}, "cam": {"bore_radius": 200.0}}, "cam.bore_radius"),
])
def test_bad_input_is_one_line_naming_the_field_exit_2(tmp_path, capsys, over, field):
    from cams.io.tomlwrite import dumps

    f = tmp_path / "bad.toml"
    f.write_text(dumps(rocker_dict(**over)), encoding="utf-8")
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"cams solve: error: {field}:"), err


def test_the_api_refuses_a_bad_hub_wall_and_constraints():
    with pytest.raises(InputError) as e:
        design_from_dict(rocker_dict(cam={"bore_radius": 5.0, "hub_wall": float("nan")}))
    assert e.value.field == "cam.hub_wall"
    d = design_from_dict(rocker_dict())
    with pytest.raises(InputError) as e:
        d.with_(constraints="bore")
    assert e.value.field == "solve.constraints"


def test_a_flat_face_is_sized_to_its_bore_exactly():
    """A flat face's smallest radius is R0: with a bore the answer is R0 = bore + wall, the bore governs, and the
    cam 1e-6 below fails it; a bore beyond the flat rocker's largest R0 is refused naming it."""
    d = design_from_dict(FAMILIES["flat rocker bore"])
    res = solve(d)
    assert res.governs == "bore" and res.R0 == pytest.approx(52.0, rel=1e-10)
    assert res.to_dict()["smallest_cam_radius"] == pytest.approx(52.0, rel=1e-10) and res.R0 >= 52.0 * (1 - 1e-15)
    below = solve(d.with_(constraints="pressure_angle").with_floor(res.R0 * (1 - 1e-6)))
    assert below.R0 < 52.0
    bad = json.loads(json.dumps(FAMILIES["flat rocker bore"]))
    bad["cam"]["bore_radius"] = 200.0
    with pytest.raises(InfeasibleError) as e:
        solve(design_from_dict(bad))
    assert e.value.field == "cam.bore_radius"
