"""The blank, the peaks and the lift table (issue 21), against independent computations.

The blank: the cam's largest radius against the roller discs swept in the fixed frame (``max |A(phi) - O| -/+ r``)
and against the exported profile; a flat face's against its closed form. The peaks: the follower's velocity,
acceleration and jerk against finite differences of its displacement alone, times the speed's powers, and the
characteristic values' closed forms. The lift table: every row against the inverted roller centre computed from
the model's follower position (not the kernel), its normal from the numerical tangent, the independent pressure
check's angle, and the exported profile's points at the phase starts.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from cams.cli import main
from cams.io.designfile import design_from_dict, load_design
from cams.solve import solve
from tests.conftest import EXAMPLES, rocker_dict

TRANSLATING = {"name": "t", "follower": {"kind": "translating", "stroke": 20.0, "roller_radius": 8.0, "offset": 4.0},
               "cam": {"rotation": "cw", "rpm": 300.0},
               "motion": [{"phase": "rise", "law": "poly345", "angle": 100}, {"phase": "dwell", "angle": 50},
                          {"phase": "return", "law": "modified_sine", "angle": 110}, {"phase": "dwell"}],
               "limits": {"pressure_angle": 30}}


def _pitch(design, centre, phi):
    """The inverted roller centre ``R(-eps phi) (A(s(phi)) - O)`` from the model's follower position alone."""
    r = design.follower.position(design.program.evaluate(phi).s) - np.asarray(centre)
    c, s = np.cos(-design.cam_sense * phi), np.sin(-design.cam_sense * phi)
    return np.stack([c * r[:, 0] - s * r[:, 1], s * r[:, 0] + c * r[:, 1]], axis=-1)


def _normal_and_rho(design, centre, phi, d=1e-4):
    """The pitch curve's outward normal (the tangent turned towards the outside: the curve runs round the centre in
    the sense ``-eps``) and its signed radius of curvature (positive convex), by central differences."""
    p0, pp, pm = (_pitch(design, centre, phi + x) for x in (0.0, d, -d))
    d1, d2 = (pp - pm) / (2 * d), (pp - 2 * p0 + pm) / d**2
    t = d1 / np.linalg.norm(d1, axis=1)[:, None]
    eps = design.cam_sense
    n = np.stack([-eps * t[:, 1], eps * t[:, 0]], axis=-1)
    k = -eps * (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
    return n, 1.0 / k


def _csv(path):
    with open(path, encoding="utf-8") as fh:
        header = fh.readline().strip().split(",")
    return header, np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


# -- the blank ------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["rocker_force", "rocker_form", "translating_force", "slotting_feed_cam"])
def test_the_largest_radius_against_the_swept_roller_and_the_export(name, tmp_path, capsys):
    d = load_design(EXAMPLES / f"{name}.toml")
    res = solve(d)
    rep = res.to_dict()
    phi = np.linspace(0.0, 2 * np.pi, 400_001)
    far = np.max(np.linalg.norm(d.follower.position(d.program.evaluate(phi).s) - res.centre, axis=1))
    groove = d.limits.closure == "form"
    r = d.follower.roller_radius
    assert rep["largest_cam_radius"] == pytest.approx(far + (r if groove else -r), abs=1e-8 * d.scale)
    assert rep["largest_cam_radius"] >= far + (r if groove else -r) - 1e-12 * d.scale   # the dense grid's is below
    # the exported curve (the outer wall of a groove) reaches it within the chord tolerance, never beyond
    out = tmp_path / "p.csv"
    assert main(["profile", str(EXAMPLES / f"{name}.toml"), "--csv", str(out), "--tolerance", "1e-5"]) == 0
    capsys.readouterr()
    header, data = _csv(out)
    cols = [header.index("outer_x"), header.index("outer_y")] if groove else [3, 4]
    exported = np.max(np.hypot(data[:, cols[0]], data[:, cols[1]]))
    assert rep["largest_cam_radius"] - 1e-5 <= exported <= rep["largest_cam_radius"] + 1e-9 * d.scale
    # the angle where it is reached
    at = np.radians(rep["largest_cam_radius_at_deg"])
    A = d.follower.position(d.program.evaluate(np.array([at])).s)[0]
    assert np.linalg.norm(A - res.centre) == pytest.approx(far, abs=1e-8 * d.scale)


@pytest.mark.parametrize("name", ["translating_flat", "rocker_flat"])
def test_a_flat_faces_radii_against_their_closed_forms(name):
    """The face's distance grows with the lift: smallest R0 (at the near dwell), largest R0 + stroke, or
    ``f - L cos(|a0| + swing)`` with ``cos a0 = (f - R0) / L`` for a rocker."""
    d = load_design(EXAMPLES / f"{name}.toml")
    rep = solve(d).to_dict()
    R0, f = rep["R0"], d.follower
    if f.kind == "translating":
        largest = R0 + d.program.lift
    else:
        a0 = np.arccos((f.face_offset - R0) / f.centre_distance)
        largest = f.face_offset - f.centre_distance * np.cos(a0 + d.program.lift)
    assert rep["smallest_cam_radius"] == pytest.approx(R0, rel=1e-13)
    assert rep["largest_cam_radius"] == pytest.approx(largest, rel=1e-12)


def test_the_smallest_radius_is_one_number_everywhere(tmp_path, capsys):
    """solve's JSON and text, check's report and its bore check, profile's summary, the machine's bore: one number,
    the swept roller's."""
    f = tmp_path / "b.toml"
    f.write_text((EXAMPLES / "rocker_force.toml").read_text(encoding="utf-8")
                 .replace("rpm = 60", "rpm = 60\nbore_radius = 2.0"), encoding="utf-8")
    assert main(["solve", str(f), "--json"]) == 0
    sol = json.loads(capsys.readouterr().out)
    assert main(["check", str(f), "--json"]) == 0
    chk = json.loads(capsys.readouterr().out)
    assert main(["profile", str(f), "--json"]) == 0
    prof = json.loads(capsys.readouterr().out)
    bore = next(c for c in chk["checks"] if c["name"] == "bore")
    values = {sol["smallest_cam_radius"], chk["smallest_cam_radius"], bore["worst"], prof["smallest_cam_radius"],
              prof["min_work_radius"]}
    assert len(values) == 1 and values.pop() == pytest.approx(3.240793033539, rel=1e-12)
    assert sol["hub_wall"] == pytest.approx(1.240793033539, rel=1e-11) and sol["bore_radius"] == 2.0


# -- the peaks ------------------------------------------------------------------------------------------------


def test_the_cycloids_peaks_are_the_characteristic_values_times_the_speed():
    """rocker_force (cycloidal rise of 15 deg over 120 deg at 60 rpm): Cv h w / b, Ca h w^2 / b^2, Cj h w^3 / b^3
    with Cv = 2, Ca = 2 pi, Cj = 4 pi^2, at the rise's middle, first quarter and start."""
    d = load_design(EXAMPLES / "rocker_force.toml")
    pk = solve(d).to_dict()["peaks"]
    h, b, w = np.radians(15.0), np.radians(120.0), 2 * np.pi
    for key, c, power, at in (("velocity", 2.0, 1, 60.0), ("acceleration", 2 * np.pi, 2, 30.0),
                              ("jerk", 4 * np.pi**2, 3, 0.0)):
        assert pk[key]["value"] == pytest.approx(c * h * w**power / b**power, rel=1e-10)
        assert pk[key]["at_deg"] == pytest.approx(at, abs=1e-6)
    assert [pk[k]["unit"] for k in ("velocity", "acceleration", "jerk")] == ["rad/s", "rad/s²", "rad/s³"]


def test_the_peaks_against_finite_differences_of_the_displacement():
    """A translating follower at 300 rpm (poly345 rise, modified sine return): the velocity and the acceleration
    against central differences of s(phi) alone, the jerk (largest at a rise's one-sided end, which no difference
    across the joint sees) against the laws' own third derivatives times h / b^3; each times w^k. Without rpm,
    per radian of cam angle."""
    d = design_from_dict(TRANSLATING)
    pk = solve(d).to_dict()["peaks"]
    w = 300.0 * 2 * np.pi / 60.0
    phi = np.linspace(0.0, 2 * np.pi, 720_001)

    def s(x):
        return d.program.evaluate(x).s

    h1, h2 = 1e-5, 1e-4      # each difference's step: its truncation and rounding below the tolerance
    v = (s(phi + h1) - s(phi - h1)) / (2 * h1)
    a = (s(phi + h2) - 2 * s(phi) + s(phi - h2)) / h2**2
    u = np.linspace(0.0, 1.0, 200_001)
    j, j_at = [], []
    for i, p in enumerate(d.program.phases):
        if p.kind != "dwell":
            j.append(np.abs(p.law.evaluate(u)[3]) * d.program.height_of(i) / p.angle**3)
            j_at.append(d.program.starts[i] + u * p.angle)
    j_ref, j_phi = np.concatenate(j), np.concatenate(j_at)
    k = int(np.argmax(j_ref))
    assert pk["jerk"]["value"] == pytest.approx(j_ref[k] * w**3, rel=1e-12)
    assert pk["jerk"]["at_deg"] == pytest.approx(np.degrees(j_phi[k]), abs=1e-6)
    for key, fd, power, rel in (("velocity", v, 1, 1e-7), ("acceleration", a, 2, 1e-6)):
        m = np.abs(fd)
        tops = np.nonzero((m[1:-1] >= m[:-2]) & (m[1:-1] >= m[2:]) & (m[1:-1] >= m.max() * (1 - 10 * rel)))[0]
        k = int(tops[0]) + 1        # the first of equal peaks (a symmetric law's two)
        assert pk[key]["value"] == pytest.approx(abs(fd[k]) * w**power, rel=rel), key
        assert pk[key]["at_deg"] == pytest.approx(np.degrees(phi[k]), abs=0.05), key
    assert [pk[k]["unit"] for k in ("velocity", "acceleration", "jerk")] == ["mm/s", "mm/s²", "mm/s³"]
    still = solve(d.with_(rpm=None)).to_dict()["peaks"]
    assert still["velocity"]["value"] == pytest.approx(pk["velocity"]["value"] / w, rel=1e-12)
    assert [still[k]["unit"] for k in ("velocity", "acceleration", "jerk")] == ["mm/rad", "mm/rad²", "mm/rad³"]


def test_a_jump_makes_a_peak_unbounded():
    """A harmonic rise meets its dwells with an acceleration jump: the jerk is unbounded (null), at the first jump;
    a linear rise has velocity jumps: the acceleration too."""
    harm = rocker_dict(motion=[{"phase": "rise", "law": "harmonic", "angle": 120}, {"phase": "dwell", "angle": 30},
                               {"phase": "return", "law": "cycloidal", "angle": 120}, {"phase": "dwell"}])
    pk = solve(design_from_dict(harm)).to_dict()["peaks"]
    assert pk["jerk"]["value"] is None and pk["jerk"]["at_deg"] == 0.0
    assert pk["acceleration"]["value"] is not None
    lin = json.loads(json.dumps(TRANSLATING))
    lin["motion"][0]["law"] = "linear"
    lin["limits"]["pressure_angle"] = 60
    pk = solve(design_from_dict(lin)).to_dict()["peaks"]
    assert pk["acceleration"]["value"] is None and pk["jerk"]["value"] is None
    v_rise = 20.0 / np.radians(100.0)                          # the linear rise's s' (mm/rad)
    v_return = 1.76 * 20.0 / np.radians(110.0)                  # the modified sine's Cv h / b
    assert pk["velocity"]["value"] == pytest.approx(max(v_rise, v_return) * 10 * np.pi, rel=1e-3)


def test_the_peaks_are_printed_with_the_speed_only(capsys):
    assert main(["solve", str(EXAMPLES / "rocker_force.toml")]) == 0
    out = capsys.readouterr().out
    assert "peaks at 60 rpm: velocity     1.5708 rad/s at 60.0000 deg" in out
    assert main(["solve", str(EXAMPLES / "rocker_form.toml")]) == 0     # no rpm: the JSON has them, the text not
    assert "peaks" not in capsys.readouterr().out


# -- the lift table -------------------------------------------------------------------------------------------


def _table(tmp_path, capsys, f, *args) -> tuple[list[str], np.ndarray]:
    out = tmp_path / "lift.csv"
    assert main(["profile", str(f), "--table", str(out), *args]) == 0
    capsys.readouterr()
    return _csv(out)


@pytest.mark.parametrize("name", ["rocker_force", "rocker_form", "translating_force"])
def test_the_lift_table_against_the_inverted_roller_centre(name, tmp_path, capsys):
    f = EXAMPLES / f"{name}.toml"
    d = load_design(f)
    res = solve(d)
    header, t = _table(tmp_path, capsys, f, "--step", "1")
    col = {k: t[:, i] for i, k in enumerate(header)}
    assert len(t) == 360 and np.array_equal(col["phi_deg"], np.arange(360.0))
    phi = np.radians(col["phi_deg"])
    rocker = d.follower.kind == "rocker"
    s = d.program.evaluate(phi).s
    assert np.allclose(col["lift_deg" if rocker else "lift_mm"], np.degrees(s) if rocker else s, atol=1e-9)
    P = _pitch(d, res.centre, phi)
    n, rho = _normal_and_rho(d, res.centre, phi)
    r = d.follower.roller_radius
    curves = {"pitch": P, "work": P - r * n}
    if d.limits.closure == "form":
        curves["outer"] = P + r * n
    for c, pts in curves.items():
        tol = 1e-9 * d.scale if c == "pitch" else 1e-6 * d.scale      # the normal by differences
        assert np.allclose(col[f"{c}_x_mm"], pts[:, 0], atol=tol) and np.allclose(col[f"{c}_y_mm"], pts[:, 1], atol=tol)
        assert np.allclose(col[f"{c}_r_mm"], np.hypot(pts[:, 0], pts[:, 1]), atol=tol)
        theta = np.degrees(np.arctan2(pts[:, 1], pts[:, 0])) % 360.0
        dth = (col[f"{c}_theta_deg"] - theta + 180.0) % 360.0 - 180.0
        assert np.all(np.abs(dth) < 1e-5)
    joints = np.isin(col["phi_deg"], np.round(np.degrees(d.program.starts[:-1]), 6))   # one-sided there
    assert np.allclose(col["rho_work_mm"][~joints], (rho - r)[~joints], rtol=1e-4, atol=1e-5 * d.scale)
    # the pressure angle: the independent check's, inside the rises and returns
    from cams.verify.pressure import pressure_angle

    ph = d.program.phase_of(phi)
    for i, p in enumerate(d.program.phases):
        m = (ph == i) & ~joints
        if p.kind == "dwell" or not m.any():
            continue
        u = (phi[m] - d.program.starts[i]) / p.angle
        ref = np.degrees(pressure_angle(d, res.centre, i, u))
        assert np.allclose(col["pressure_angle_deg"][m], ref, atol=1e-7)


def test_the_lift_tables_points_are_the_profiles_at_the_phase_starts(tmp_path, capsys):
    """At the phase starts (samples of every export) the table's points are the exported profile's."""
    f = EXAMPLES / "rocker_force.toml"
    header, t = _table(tmp_path, capsys, f, "--step", "30")
    out = tmp_path / "p.csv"
    assert main(["profile", str(f), "--csv", str(out)]) == 0
    capsys.readouterr()
    ph, prof = _csv(out)
    for deg in (0.0, 120.0, 150.0, 270.0):
        row = t[np.nonzero(t[:, 0] == deg)[0][0]]
        k = np.nonzero(np.abs(prof[:, 0] - deg) < 1e-9)[0][-1]       # the later phase's row at a joint
        for c in ("pitch_x", "pitch_y", "work_x", "work_y"):
            assert row[header.index(f"{c}_mm")] == pytest.approx(prof[k, ph.index(c)], abs=1e-9), (deg, c)


def test_a_flat_faces_lift_table_is_the_envelope_of_its_face_lines(tmp_path, capsys):
    """A translating flat face: each row's point is where the face lines at phi -/+ 1e-5 rad cross (the envelope,
    no support function), its radius of curvature R0 + s + s'' by differences of s, its pressure angle 0."""
    f = EXAMPLES / "translating_flat.toml"
    d = load_design(f)
    R0 = solve(d).R0
    header, t = _table(tmp_path, capsys, f, "--step", "5")
    assert "pitch_x_mm" not in header and len(t) == 72
    col = {k: t[:, i] for i, k in enumerate(header)}
    phi = np.radians(col["phi_deg"])
    eps, h = d.cam_sense, 1e-5

    def line(x):      # the face in the cam frame: normal n(theta), distance R0 + s
        th = np.pi / 2 - eps * x
        return np.stack([np.cos(th), np.sin(th)], axis=-1), R0 + d.program.evaluate(x).s

    (n1, p1), (n2, p2) = line(phi - h), line(phi + h)
    det = n1[:, 0] * n2[:, 1] - n1[:, 1] * n2[:, 0]
    X = np.stack([(p1 * n2[:, 1] - p2 * n1[:, 1]) / det, (n1[:, 0] * p2 - n2[:, 0] * p1) / det], axis=-1)
    assert np.allclose(col["work_x_mm"], X[:, 0], atol=1e-6) and np.allclose(col["work_y_mm"], X[:, 1], atol=1e-6)
    s = d.program.evaluate
    d2 = (s(phi + 1e-4).s - 2 * s(phi).s + s(phi - 1e-4).s) / 1e-8
    joints = np.isin(col["phi_deg"], np.round(np.degrees(d.program.starts[:-1]), 6))
    assert np.allclose(col["rho_work_mm"][~joints], (R0 + s(phi).s + d2)[~joints], atol=1e-4)
    assert np.all(col["pressure_angle_deg"] == 0.0) and np.allclose(col["lift_mm"], s(phi).s, atol=1e-12)


@pytest.mark.parametrize("args, field", [
    (["--table", "-", "--step", "0"], "--step"),
    (["--table", "-", "--step", "-1"], "--step"),
    (["--table", "-", "--step", "7"], "--step"),
    (["--table", "-", "--step", "0.0001"], "--step"),
    (["--step", "2"], "--step"),
])
def test_a_bad_step_is_one_line_naming_it_exit_2(capsys, args, field):
    assert main(["profile", str(EXAMPLES / "rocker_force.toml"), *args]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"cams profile: error: {field}:"), err


def test_a_failing_cams_table_is_written_only_when_allowed(tmp_path, capsys):
    f = tmp_path / "fail.toml"
    f.write_text((EXAMPLES / "rocker_force.toml").read_text(encoding="utf-8")
                 .replace("rpm = 60", "rpm = 60\nbore_radius = 20.0")
                 .replace("[solve]\n", '[solve]\nconstraints = "pressure_angle"\n'), encoding="utf-8")
    out = tmp_path / "lift.csv"
    assert main(["profile", str(f), "--table", str(out)]) == 1
    assert not out.exists() and "no file written" in capsys.readouterr().err
    assert main(["profile", str(f), "--table", str(out), "--allow-failed", "--step", "90"]) == 1
    assert len(_csv(out)[1]) == 4
