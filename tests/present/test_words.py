"""Words a designer reads: the names of the binding lines, both radii of the cam, units and precision.

The references here are independent of the printed text's code: the signed
pressure angle is recomputed by kinematic inversion (``cams.verify.pressure``), the
cam's smallest radius by a dense sampling of the working profile.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.solve import solve
from cams.verify.pressure import contact_normal
from tests.conftest import rocker_dict


def _translating_dict(rotation: str, closure: str) -> dict:
    return {
        "name": "test translating",
        "follower": {"kind": "translating", "stroke": 20.0, "roller_radius": 5.0},
        "cam": {"rotation": rotation},
        "motion": [
            {"phase": "rise", "law": "cycloidal", "angle": 100},
            {"phase": "dwell", "angle": 40},
            {"phase": "return", "law": "harmonic", "angle": 130},
            {"phase": "dwell"},
        ],
        "limits": {"pressure_angle": 30, "closure": closure},
    }


def _rocker(rotation: str, rise: str, closure: str) -> dict:
    return rocker_dict(cam={"rotation": rotation}, follower={"rise_direction": rise},
                       limits={"pressure_angle": 40, "closure": closure})


#: Every relative sense of cam and follower, both closures.
DESIGNS = {
    **{f"rocker cam {c} rise {r} {cl}": _rocker(c, r, cl)
       for c in ("ccw", "cw") for r in ("cw", "ccw") for cl in ("force", "form")},
    **{f"translating cam {c} {cl}": _translating_dict(c, cl) for c in ("ccw", "cw") for cl in ("force", "form")},
}


def signed_pressure_angle(design, centre, phase: int, phi: float) -> float:
    """Pressure angle (radians) at cam angle ``phi``, signed positive where the cam drives along the rise.

    From the pitch curve's outward normal ``n`` and the rise direction ``e``
    (kinematic inversion): the magnitude is ``arccos(n . e)``, the sign that of
    ``n`` turned from ``e`` in the cam's sense of rotation.
    """
    p = design.program
    u = (phi - p.starts[phase]) / p.phases[phase].angle
    m = p.evaluate_phase(phase, np.array([min(max(u, 0.0), 1.0)]))
    n, e, _ = contact_normal(design, centre, m.s, m.ds)
    n, e = n[0], e[0]
    turn = design.cam_sense * (e[0] * n[1] - e[1] * n[0])
    return float(np.copysign(np.arccos(np.clip(n @ e, -1.0, 1.0)), turn))


@pytest.mark.parametrize("key", sorted(DESIGNS))
def test_binding_line_names_follow_the_sign_of_the_pressure_angle(key):
    """t-t where the signed pressure angle is +[gamma], t1-t1 where it is -[gamma], in every sense."""
    design = design_from_dict(DESIGNS[key])
    res = solve(design)
    rep = res.to_dict()
    assert rep["binding"]
    limits = dict(design.constrained_phases())
    for b, d in zip(res.binding, rep["binding"], strict=True):
        g = signed_pressure_angle(design, res.centre, b.phase, b.phi)
        want = limits[b.phase] if d["line"] == "t-t" else -limits[b.phase]
        assert g == pytest.approx(want, abs=1e-7), (d, np.degrees(g))


def _mirror(d: dict) -> dict:
    flip = {"cw": "ccw", "ccw": "cw"}
    m = {**d, "cam": {**d["cam"], "rotation": flip[d["cam"]["rotation"]]}, "follower": dict(d["follower"])}
    if "rise_direction" in m["follower"]:
        m["follower"]["rise_direction"] = flip[m["follower"]["rise_direction"]]
    return m


@pytest.mark.parametrize("key", sorted(k for k in DESIGNS if "cam ccw" in k))
def test_mirror_images_name_their_binding_lines_alike(key):
    a = solve(design_from_dict(DESIGNS[key])).to_dict()
    b = solve(design_from_dict(_mirror(DESIGNS[key]))).to_dict()
    assert b["R0"] == pytest.approx(a["R0"], rel=1e-9)
    assert [(x["line"], x["phase"], round(x["phi"], 6)) for x in a["binding"]] == \
        [(x["line"], x["phase"], round(x["phi"], 6)) for x in b["binding"]]


def test_force_closure_t1_t1_is_the_start_position():
    """Seed 001: under force closure the t1-t1 line is the one at the start position (cam angle 0)."""
    for key, d in DESIGNS.items():
        if "force" not in key:
            continue
        rep = solve(design_from_dict(d)).to_dict()
        for b in rep["binding"]:
            if b["line"] == "t1-t1":
                assert b["phi"] == pytest.approx(0.0, abs=1e-9), key


# -- item 13: R0 beside the cam's own smallest radius; the automatic bore is a suggestion ------------------

EXAMPLES_ROLLER = ("rocker_force", "rocker_form", "translating_force", "translating_form_centric", "slotting_feed_cam")


def _dense_smallest_radius(design, centre) -> float:
    """The largest circle about the cam centre that no roller disc reaches, from the fixed frame.

    The cam is what the roller discs leave as the follower moves round it:
    its smallest radius is ``min |A(phi) - O| - r`` over a dense, even set of
    cam angles (no inversion, no profile), refined nowhere.
    """
    phi = np.linspace(0.0, 2 * np.pi, 720_001)
    s = design.program.evaluate(phi).s
    A = design.follower.position(s)
    return float(np.min(np.linalg.norm(A - np.asarray(centre), axis=1)) - design.follower.roller_radius)


@pytest.mark.parametrize("name", EXAMPLES_ROLLER)
def test_smallest_cam_radius_against_dense_swept_rollers_examples(name, examples_dir):
    from cams.io.designfile import load_design

    d = load_design(examples_dir / f"{name}.toml")
    res = solve(d)
    rep = res.to_dict()
    ref = _dense_smallest_radius(d, res.centre)
    assert rep["smallest_cam_radius"] == pytest.approx(ref, abs=1e-7 * d.scale)
    assert rep["smallest_cam_radius"] < rep["R0"]


@pytest.mark.parametrize("key", sorted(DESIGNS))
def test_smallest_cam_radius_against_dense_swept_rollers_every_sense(key):
    d = design_from_dict(DESIGNS[key])
    res = solve(d)
    assert res.to_dict()["smallest_cam_radius"] == pytest.approx(_dense_smallest_radius(d, res.centre),
                                                                    abs=1e-7 * d.scale)


def test_smallest_cam_radius_below_R0_less_roller_when_the_rocker_swings_in():
    """A rocker whose rise brings the roller nearer the cam centre: the cam is smallest inside the rise, not at R0 - r."""
    from cams.kinematics.inversion import smallest_cam_radius

    d = design_from_dict(rocker_dict(follower={"swing": 30.0}, limits={"pressure_angle": 40},
                                     cam={"rotation": "cw"}))
    res = solve(d)
    r, at = smallest_cam_radius(d, res.centre)
    ref = _dense_smallest_radius(d, res.centre)
    assert r == pytest.approx(ref, abs=1e-7 * d.scale)
    assert r < res.R0 - d.follower.roller_radius - 1e-3 or r == pytest.approx(res.R0 - d.follower.roller_radius)


def _swept_radius_at(design, centre, phi_deg: float) -> float:
    """``|A(phi) - O| - r`` at one cam angle (degrees), from the fixed frame as in :func:`_dense_smallest_radius`."""
    s = design.program.evaluate(np.radians([phi_deg])).s
    return float(np.linalg.norm(design.follower.position(s)[0] - np.asarray(centre)) - design.follower.roller_radius)


@pytest.mark.parametrize("key", sorted(DESIGNS))
def test_smallest_cam_radius_at_deg_is_where_it_is_reached(key):
    """The JSON's ``smallest_cam_radius_at_deg``: the swept roller reaches the smallest radius at that cam angle."""
    d = design_from_dict(DESIGNS[key])
    res = solve(d)
    rep = res.to_dict()
    at = rep["smallest_cam_radius_at_deg"]
    assert 0.0 <= at <= 360.0
    assert _swept_radius_at(d, res.centre, at) == pytest.approx(rep["smallest_cam_radius"], abs=1e-9 * d.scale)


def test_smallest_cam_radius_and_its_angle_inside_the_rise_against_the_dense_argmin():
    """A centre the rise brings the roller nearest to (not the dwell): radius and angle are the dense argmin's."""
    from cams.kinematics.inversion import smallest_cam_radius

    d = design_from_dict(rocker_dict(follower={"swing": 30.0}, limits={"pressure_angle": 40}))
    A = d.follower.position(d.program.evaluate(np.radians([30.0])).s)[0]  # the roller centre a third into the rise
    centre = A + np.array([0.0, 30.0]) * np.sign(A[1] - d.follower.position(0.0)[1] or 1.0)
    r, at = smallest_cam_radius(d, centre)
    phi = np.linspace(0.0, 360.0, 720_001)
    dist = np.linalg.norm(d.follower.position(d.program.evaluate(np.radians(phi)).s) - centre, axis=1)
    k = int(np.argmin(dist))
    assert 0.0 < phi[k] < np.degrees(d.program.phases[0].angle)  # inside the rise, one point
    assert r == pytest.approx(dist[k] - d.follower.roller_radius, abs=1e-7 * d.scale)
    assert np.degrees(at) == pytest.approx(phi[k], abs=2e-3)


def _main(capsys, *argv):
    from cams.cli import main

    rc = main(list(argv))
    return rc, capsys.readouterr().out


def test_solve_and_check_print_R0_beside_the_cams_smallest_radius(capsys, examples_dir):
    f = str(examples_dir / "rocker_force.toml")
    rc, out = _main(capsys, "solve", f)
    assert rc == 0
    assert "R0      = 13.240793 mm  (pitch curve's base radius" in out
    assert "Rmin    = 3.240793 mm  (the cam's own smallest radius" in out
    rc, out = _main(capsys, "check", f)
    assert rc == 0 and "R0 = 13.240793 mm (pitch curve)" in out and "cam's smallest radius 3.240793 mm" in out
    assert "suggested bore radius" in out


def test_the_suggested_bore_stays_out_of_the_manufacturing_files(capsys, tmp_path, examples_dir):
    import ezdxf

    src = (examples_dir / "rocker_force.toml").read_text(encoding="utf-8")
    dxf, svg = tmp_path / "a.dxf", tmp_path / "a.svg"
    rc, out = _main(capsys, "profile", str(examples_dir / "rocker_force.toml"), "--dxf", str(dxf), "--svg", str(svg))
    assert rc == 0 and "suggested bore radius" in out
    assert "BORE" not in {e.dxf.layer for e in ezdxf.readfile(str(dxf)).modelspace()}
    assert 'id="BORE"' not in svg.read_text()
    given = tmp_path / "bored.toml"
    given.write_text(src.replace("[cam]\n", "[cam]\nbore_radius = 2.0\n", 1), encoding="utf-8")
    rc, out = _main(capsys, "profile", str(given), "--dxf", str(dxf), "--svg", str(svg))
    assert rc == 0 and "bore radius 2.000000 mm" in out and "suggested bore" not in out
    circles = [e for e in ezdxf.readfile(str(dxf)).modelspace() if e.dxf.layer == "BORE"]
    assert len(circles) == 1 and circles[0].dxf.radius == pytest.approx(2.0)
    assert 'id="BORE"' in svg.read_text()


# -- item 15: units beside every number, one precision per quantity ---------------------------------------


def test_spring_units_follow_the_follower(capsys, examples_dir, tmp_path):
    """A rocker's closing spring is torsional (N m/rad, N m), a translating follower's linear (N/m, N)."""
    rc, out = _main(capsys, "solve", str(examples_dir / "slotting_feed_cam.toml"))
    assert rc == 0
    # the given rate's least preload for the margin is 0; the least installed twist, a quarter of the 15 deg swing,
    # makes it 3 N m/rad x 3.75 deg = 0.19635 N m, and the largest force 3 x (3.75 + 15) deg = 0.981748 N m
    assert ("spring: rate 3 N m/rad, preload 0.19635 N m, installed twist 3.75 deg, largest force 0.981748 N m"
            in out)
    assert "contact force: max 14.863 N at 104.0000 deg, min 6.93182 N" in out
    assert "camshaft: largest driving torque 0.589563 N·m at 29.5000 deg; largest braking torque 0.434114 N·m at " \
           "96.0000 deg" in out
    assert "jamming limit 89.6333 deg" in out
    rc, out = _main(capsys, "machine", str(examples_dir / "machines" / "slotting_machine_forces.toml"), "--forces")
    assert "spring rate 3 N m/rad, preload 0.19635 N m, installed twist 3.75 deg" in out
    assert "max contact force 14.863 N at cam angle 104.0000 deg" in out


def test_sweep_csv_headers_carry_units_and_no_round_off_tails(capsys, tmp_path, examples_dir):
    import csv

    out = tmp_path / "s.csv"
    from cams.cli import main

    assert main(["sweep", str(examples_dir / "rocker_force.toml"), "--vary", "limits.pressure_angle=30:45:2",
                 "--out", str(out), "--jobs", "1", "--quiet"]) == 0
    text = out.read_text()
    head = text.splitlines()[0].split(",")
    assert head[:6] == ["index", "file", "limits.pressure_angle", "R0_mm", "L_mm", "offset_mm"]
    assert "max_pressure_angle_rise_deg" in head and "error_bound_mm" in head
    rows = list(csv.DictReader(out.open()))
    # the binding rise angle is the limit: printed as 30 and 45, not 29.999999999999996
    assert [r["max_pressure_angle_rise_deg"] for r in rows] == ["30", "45"]
    assert "9999999" not in text


@pytest.mark.parametrize("name", EXAMPLES_ROLLER)
def test_every_length_in_the_solve_and_check_text_carries_mm(capsys, examples_dir, name):
    """Each number printed is followed by its unit (mm, deg, N, N m, rpm, ms; a peak's mm/s or rad/s...), or is a
    count or a flag."""
    import re

    f = str(examples_dir / f"{name}.toml")
    for cmd in ("solve", "check"):
        _, out = _main(capsys, cmd, f)
        for line in out.splitlines():
            line = re.sub(r"\bphase \d+", "", line)  # a phase's number (its [[motion]] index from 0)
            line = re.sub(r"\(-?[\d.]+, -?[\d.]+\) mm", "mm", line)  # a point: its unit after the pair
            line = re.sub(r"^\s*(error bound: [0-9.e+-]+ mm)", "", line)
            for m in re.finditer(r"(?<![\w.])(-?\d+(?:\.\d+)?(?:e[+-]?\d+)?)(?![\w.])(\s*[^\s,;)]*)", line):
                num, unit = m.group(1), m.group(2).strip()
                if unit.startswith(("mm", "deg", "N", "rpm", "ms", "rad/", "points", "(limit", "self-crossing")) \
                        or unit == "s" or num in ("0", "1"):
                    continue
                raise AssertionError(f"{cmd}: a number without a unit: {num!r} in {line!r}")


def test_notes_give_lengths_in_mm():
    """A floor on R0 above the minimum, and one below it: the notes name the lengths with their unit."""
    import re

    for floor in (40.0, 5.0):
        res = solve(design_from_dict(rocker_dict(limits={"min_base_radius": floor})))
        (note,) = [n for n in res.notes if "constructive floor" in n]
        for num in re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?![\w.])", note):
            assert re.search(rf"{re.escape(num)} mm", note), note
