"""Flat-faced followers on the command line: outputs, JSON keys, exit codes and one-line errors."""

from __future__ import annotations

import csv
import json

import pytest

from cams.cli import main
from cams.io.designfile import design_from_dict, load_design
from cams.model.design import FlatFaceDesign
from cams.model.follower import FlatRocker, FlatTranslating
from laws.errors import InputError
from tests.conftest import EXAMPLES

TRANSLATING = EXAMPLES / "translating_flat.toml"
ROCKER = EXAMPLES / "rocker_flat.toml"

SOLVE_KEYS = {"name", "follower", "face", "R0", "R0_min", "R0_source", "binding_deg", "min_radius", "min_rho",
              "min_rho_at_deg", "L", "face_offset", "offset", "centre", "face_range", "face_width",
              "face_width_centred", "pressure_angle", "verified", "buildable", "failures", "seconds", "notes",
              # the part's keys, every face alike
              "governs", "pressure_angle_R0", "smallest_cam_radius", "smallest_cam_radius_at_deg",
              "largest_cam_radius", "largest_cam_radius_at_deg", "bore_radius", "hub_wall", "hub_wall_required",
              "rpm", "peaks"}
#: the examples have a [dynamics] table: their forces (spring, contact force, torque, jump speed)
EXAMPLE_KEYS = SOLVE_KEYS | {"forces"}


def _flat(kind="translating", **over) -> dict:
    """A flat-face design file as a dict, with overrides per table (``None`` removes a key)."""
    fo = ({"kind": "translating", "face": "flat", "stroke": 20.0} if kind == "translating" else
          {"kind": "rocker", "face": "flat", "swing": 15.0, "centre_distance": 120.0})
    d = {"name": "flat", "follower": fo, "cam": {"rotation": "ccw"},
         "motion": [{"phase": "rise", "law": "cycloidal", "angle": 120}, {"phase": "dwell", "angle": 60},
                    {"phase": "return", "law": "poly345", "angle": 120}, {"phase": "dwell"}],
         "limits": {"min_radius": 5.0}}
    for table, v in over.items():
        if isinstance(v, dict):
            t = {**d.get(table, {}), **v}
            d[table] = {k: x for k, x in t.items() if x is not None}
        else:
            d[table] = v
    return d


def _toml(d: dict) -> str:
    def val(v):
        return json.dumps(v) if isinstance(v, (str, bool)) else repr(v)

    lines = [f"name = {val(d['name'])}"]
    for table in ("follower", "cam", "limits", "solve", "profile", "dynamics"):
        if table in d:
            lines.append(f"[{table}]")
            lines += [f"{k} = {val(v)}" for k, v in d[table].items()]
    for m in d["motion"]:
        lines.append("[[motion]]")
        lines += [f"{k} = {val(v)}" for k, v in m.items()]
    return "\n".join(lines) + "\n"


def _file(tmp_path, d: dict, name="flat.toml") -> str:
    p = tmp_path / name
    p.write_text(_toml(d), encoding="utf-8")
    return str(p)


def _run(capsys, *argv):
    rc = main(list(argv))
    out = capsys.readouterr()
    return rc, out.out, out.err


@pytest.mark.parametrize("file, kind", [(TRANSLATING, "translating"), (ROCKER, "rocker")])
def test_solve_json_keys_and_values(capsys, file, kind):
    rc, out, err = _run(capsys, "solve", str(file), "--json")
    assert rc == 0 and err == ""
    rep = json.loads(out)
    assert set(rep) == EXAMPLE_KEYS
    assert rep["follower"] == kind and rep["face"] == "flat" and rep["verified"] is True
    assert set(rep["face_range"]) == {"from", "to", "from_at_deg", "to_at_deg"}
    assert set(rep["pressure_angle"]) == {"min", "max", "max_at_deg"} and rep["pressure_angle"]["max"] == 0.0
    assert rep["face_width"] == pytest.approx(rep["face_range"]["to"] - rep["face_range"]["from"])
    if kind == "rocker":
        assert rep["L"] == 120.0 and rep["face_offset"] == 0.0 and rep["offset"] is None
        assert rep["centre"] == {"x": 120.0, "y": 0.0} and rep["face_width_centred"] is None
        assert 0 < rep["face_range"]["from"] < rep["face_range"]["to"]  # on the cam's side of the pivot
    else:
        assert rep["L"] is None and rep["offset"] == 0.0
        assert rep["centre"] == {"x": 0.0, "y": pytest.approx(-rep["R0"])}
        assert rep["face_range"]["from"] < 0 < rep["face_range"]["to"]  # both sides of the axis


def test_solve_text(capsys):
    rc, out, _ = _run(capsys, "solve", str(TRANSLATING))
    assert rc == 0
    assert "flat face, sized by convexity" in out and "R0      = 20.66" in out
    assert "pressure angle: 0 deg everywhere (fixed by the geometry" in out
    assert "a face centred on the axis needs 38.197" in out
    rc, out, _ = _run(capsys, "solve", str(ROCKER))
    assert rc == 0 and "along the face from the pivot's foot" in out and "the face passes through the pivot" in out


def test_offset_moves_only_the_contact(tmp_path, capsys):
    base = json.loads(_run(capsys, "solve", _file(tmp_path, _flat()), "--json")[1])
    shifted = json.loads(_run(capsys, "solve", _file(tmp_path, _flat(follower={"offset": 3.0}), "s.toml"),
                              "--json")[1])
    assert shifted["R0"] == base["R0"] and shifted["face_width"] == pytest.approx(base["face_width"])
    assert shifted["face_range"]["from"] == pytest.approx(base["face_range"]["from"] - 3.0)
    assert shifted["centre"]["x"] == -3.0


def test_offset_face_reports_its_pressure_angle(tmp_path, capsys):
    rc, out, _ = _run(capsys, "solve", _file(tmp_path, _flat("rocker", follower={"face_offset": 10.0})), "--json")
    rep = json.loads(out)
    assert rc == 0 and 0 < rep["pressure_angle"]["min"] < rep["pressure_angle"]["max"] < 90
    # atan(|f| / c): largest where the contact is nearest the pivot's foot
    import math

    assert rep["pressure_angle"]["max"] == pytest.approx(math.degrees(math.atan(10.0 / rep["face_range"]["from"])),
                                                         abs=1e-6)


def test_defaults_and_floor(tmp_path, capsys):
    d = design_from_dict(_flat(limits={"min_radius": None}))
    assert isinstance(d, FlatFaceDesign) and isinstance(d.follower, FlatTranslating)
    assert d.min_radius == pytest.approx(2.0)  # a tenth of the stroke
    r = design_from_dict(_flat("rocker", limits={"min_radius": None}))
    assert isinstance(r.follower, FlatRocker) and r.follower.face_offset == 0.0 and r.follower.sense == -1
    assert r.min_radius == pytest.approx(0.1 * 120.0 * 15 * 3.141592653589793 / 180)
    rc, out, _ = _run(capsys, "solve", _file(tmp_path, _flat(limits={"min_base_radius": 40.0})), "--json")
    rep = json.loads(out)
    assert rc == 0 and rep["R0"] == 40.0 and rep["R0_source"] == "limits.min_base_radius"
    assert rep["R0_min"] < 40.0 and rep["min_rho"] > rep["min_radius"] and rep["notes"]


@pytest.mark.parametrize("file", [TRANSLATING, ROCKER])
def test_check_profile_plot_report_run(tmp_path, capsys, file):
    rc, out, _ = _run(capsys, "check", str(file), "--json")
    rep = json.loads(out)
    assert rc == 0 and rep["passed"] and rep["face"] == "flat"
    assert [c["name"] for c in rep["checks"]] == ["convexity", "profile_polygon"]
    rc, out, _ = _run(capsys, "check", str(file))
    assert rc == 0 and "pass  convex profile: smallest radius of curvature" in out and "all checks pass" in out
    csv, dxf, svg = tmp_path / "c.csv", tmp_path / "c.dxf", tmp_path / "c.svg"
    rc, out, _ = _run(capsys, "profile", str(file), "--csv", str(csv), "--dxf", str(dxf), "--svg", str(svg), "--json")
    rep = json.loads(out)
    assert rc == 0 and rep["columns"] == "phi_deg,work_x,work_y" and len(rep["written"]) == 3
    lines = csv.read_text().splitlines()
    assert lines[0] == "phi_deg,work_x,work_y" and len(lines) == rep["points"] + 1
    assert len(lines[1].split(",")) == 3
    import ezdxf

    doc = ezdxf.readfile(str(dxf))
    # no [cam] bore_radius: the suggested bore is not a dimension, so no BORE circle (issue 12, item 13); the
    # centre mark and the timing datum are drawn in every drawing (issue 25)
    assert {e.dxf.layer for e in doc.modelspace()} == {"PROFILE", "BASE", "CENTRE", "DATUM"}
    text = svg.read_text()
    assert 'id="PROFILE"' in text and 'id="PITCH"' not in text
    rc, out, err = _run(capsys, "plot", str(file), "--out", str(tmp_path / "pics"))
    assert rc == 0
    names = sorted(p.name for p in (tmp_path / "pics").iterdir())
    stem = "translating_flat_face_cam" if file == TRANSLATING else "rocker_flat_face_cam"
    # the flat examples carry [dynamics] and a speed: their forces are drawn too (issue 22)
    assert names == sorted(f"{stem}_{k}.{e}" for k in ("motion", "pressure", "curvature", "profile", "forces")
                           for e in ("png", "svg"))
    assert err == ""  # the zone is not drawn and, not asked for, not mentioned
    rc, out, err = _run(capsys, "report", str(file), "--out", str(tmp_path / "rep"))
    assert rc == 0 and (tmp_path / "rep" / "report.pdf").exists()
    html = (tmp_path / "rep" / "report.html").read_text()
    assert "face width needed" in html and "smallest radius of curvature" in html


def test_plot_only_zone_is_a_note(tmp_path, capsys):
    rc, out, err = _run(capsys, "plot", str(TRANSLATING), "--out", str(tmp_path), "--only", "zone")
    assert rc == 0 and out == "" and list(tmp_path.iterdir()) == []
    assert err.startswith("cams plot: note: zone:") and err.count("\n") == 1


def test_check_fails_on_a_bore_too_large_for_a_chosen_cam_and_sizing_clears_it(tmp_path, capsys):
    """A chosen R0 of 25 mm cannot take a bore of 30 mm: the bore check fails and a note gives the least R0 that
    fits; sized (no chosen R0) the cam grows to clear it: its smallest radius R0 is the bore, exactly."""
    f = _file(tmp_path, _flat(cam={"bore_radius": 30.0, "base_radius": 25.0}))
    rc, out, _ = _run(capsys, "check", f, "--json")
    rep = json.loads(out)
    assert rc == 1 and not rep["passed"]
    assert [c["name"] for c in rep["checks"] if not c["passed"]] == ["bore"]
    assert any("the least R0 that fits is 30 mm" in n for n in rep["notes"])
    f = _file(tmp_path, _flat(cam={"bore_radius": 30.0}))
    rc, out, _ = _run(capsys, "solve", f, "--json")
    rep = json.loads(out)
    assert rc == 0 and rep["governs"] == "bore" and rep["R0"] == pytest.approx(30.0, rel=1e-12)
    assert rep["smallest_cam_radius"] == pytest.approx(30.0, rel=1e-12) and rep["hub_wall"] >= 0.0


@pytest.mark.parametrize("over, field, words", [
    ({"follower": {"roller_radius": 5.0}}, "follower.roller_radius", "does not apply to a flat-faced follower"),
    ({"limits": {"pressure_angle": 30}}, "limits.pressure_angle", "does not apply to a flat-faced follower"),
    ({"limits": {"return_pressure_angle": 30}}, "limits.return_pressure_angle", "fixed by the geometry"),
    ({"limits": {"safety_factor": 1.1}}, "limits.safety_factor", "does not apply"),
    ({"limits": {"closure": "form"}}, "limits.closure", "only 'force'"),
    ({"limits": {"closure": "glue"}}, "limits.closure", "must be one of 'force', 'form'"),
    ({"limits": {"min_radius": 0.0}}, "limits.min_radius", "must be a number > 0"),
    ({"limits": {"min_radius": "big"}}, "limits.min_radius", "must be a number"),
    ({"follower": {"face": "curved"}}, "follower.face", "must be one of 'roller', 'flat'"),
    ({"follower": {"stroke": -2.0}}, "follower.stroke", "must be > 0"),
    ({"follower": {"swing": 10.0}}, "follower.swing", "applies to rocker followers"),
    ({"follower": {"colour": "red"}}, "follower", "unknown key(s) colour"),
    ({"cam": {"base_radius": -1.0}}, "cam.base_radius", "must be a number > 0"),
    ({"cam": {"base_radius": 20.0}, "limits": {"min_base_radius": 30.0}}, "cam.base_radius",
     "a floor on R0 (limits.min_base_radius) has nothing to size"),
    ({"cam": {"base_radius": 40.0}, "limits": {"min_base_radius": 30.0}}, "cam.base_radius",
     "a floor on R0 (limits.min_base_radius) has nothing to size"),
    ({"solve": {"method": "exact"}}, "solve.method", "does not apply to a flat-faced follower"),
    ({"profile": {"min_curvature_radius": 2.0}}, "profile.min_curvature_radius", "limits.min_radius"),
    ({"dynamics": {"mass": 1.0, "face_friction": -0.1}}, "dynamics.face_friction", "must be >= 0"),
    ({"dynamics": {"mass": 1.0, "face_friction": "oily"}}, "dynamics.face_friction", "must be a"),
    ({"dynamics": {"mass": 1.0, "face_friction": True}}, "dynamics.face_friction", "must be a"),
    ({"dynamics": {"mass": 1.0, "journal_radius": 5.0}}, "dynamics.journal_radius", "applies to a rocker's pivot"),
    ({"dynamics": {"mass": 1.0, "journal_radius": 0.0}}, "dynamics.journal_radius", "applies to a rocker's pivot"),
    ({"motion": [{"phase": "rise", "law": "linear", "angle": 180}, {"phase": "return", "law": "cycloidal",
                                                                    "angle": 180}]}, "motion[1]", "cusp"),
])
def test_bad_translating_input_is_one_line(tmp_path, capsys, over, field, words):
    rc, out, err = _run(capsys, "solve", _file(tmp_path, _flat(**over)))
    assert rc == 2 and out == ""
    assert err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(f"cams solve: error: {field}") and words in err


@pytest.mark.parametrize("over, field, words", [
    ({"follower": {"centre_distance": None}}, "follower.centre_distance", "is required for a flat-faced rocker"),
    ({"follower": {"centre_distance": 0.0}}, "follower.centre_distance", "must be > 0"),
    ({"follower": {"arm": 125.0}}, "follower.arm", "give follower.centre_distance"),
    ({"follower": {"stroke": 20.0}}, "follower.stroke", "applies to translating followers"),
    ({"follower": {"swing": 180.0}}, "follower.swing", "(0, 180)"),
    ({"follower": {"rise_direction": "up"}}, "follower.rise_direction", "'cw', 'ccw'"),
    ({"limits": {"centre_distance": 120.0}}, "limits.centre_distance", "follower.centre_distance"),
    ({"limits": {"min_radius": 500.0}}, "limits.min_radius", "no base radius below"),
    ({"cam": {"base_radius": 200.0}}, "cam.base_radius", "cannot touch a base circle"),
    ({"cam": {"rpm": 60}, "dynamics": {"mass": 0.01, "face_friction": -1e-9}}, "dynamics.face_friction",
     "must be >= 0"),
    ({"cam": {"rpm": 60}, "dynamics": {"mass": 0.01, "face_friction": float("nan")}}, "dynamics.face_friction",
     "must be"),
])
def test_bad_rocker_input_is_one_line(tmp_path, capsys, over, field, words):
    rc, out, err = _run(capsys, "solve", _file(tmp_path, _flat("rocker", **over)))
    assert rc == 2 and out == ""
    assert err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(f"cams solve: error: {field}") and words in err


@pytest.mark.parametrize("key, table, value", [
    ("centre_distance", "follower", 120.0), ("face_offset", "follower", 0.0), ("min_radius", "limits", 5.0),
    ("face_friction", "dynamics", 0.1),
])
def test_flat_only_keys_on_a_roller_design_say_so(tmp_path, capsys, key, table, value):
    from tests.conftest import rocker_dict

    d = rocker_dict(**{table: {key: value}})
    with pytest.raises(InputError, match=rf"^{table}\.{key}: .*flat-faced"):
        design_from_dict(d)


def test_method_options_and_commands_that_do_not_apply(tmp_path, capsys):
    for cmd in ("solve", "check", "profile"):
        rc, _, err = _run(capsys, cmd, str(ROCKER), "--method", "convex")
        assert rc == 2 and err.startswith(f"cams {cmd}: error: --method: does not apply to a flat-faced follower")
    # a sweep takes flat faces (issue 26), each design by its face's pipeline (the batch solver sends them back)
    rc, _, err = _run(capsys, "sweep", str(ROCKER), "--vary", "follower.swing=10:20:3", "--out",
                      str(tmp_path / "s.csv"), "--quiet", "--jobs", "1")
    rows = list(csv.DictReader((tmp_path / "s.csv").open(encoding="utf-8")))
    assert rc == 0 and [r["follower.swing"] for r in rows] == ["10", "15", "20"], err
    assert all(r["verified"] == "True" and r["buildable"] == "True" and r["R0_mm"] for r in rows)
    rc, _, err = _run(capsys, "profile", str(ROCKER), "--tolerance", "0")
    assert rc == 2 and err.startswith("cams profile: error: --tolerance:")


def test_new_flat_templates_load_and_solve(tmp_path, capsys):
    for kind in ("rocker", "translating"):
        out = tmp_path / f"{kind}.toml"
        assert main(["new", kind, "--flat", "--out", str(out)]) == 0
        d = load_design(out)
        assert d.face == "flat" and d.follower.kind == kind
        assert main(["solve", str(out)]) == 0
    capsys.readouterr()


def test_roller_designs_are_untouched(capsys):
    """The face key is optional and "roller" by default: an explicit one changes nothing."""
    from tests.conftest import rocker_dict

    a = design_from_dict(rocker_dict())
    b = design_from_dict(rocker_dict(follower={"face": "roller"}))
    assert a == b and a.face == "roller"


def test_api_refuses_flat_faces_where_only_rollers_apply(tmp_path):
    """The machine loader refuses a flat face with an InputError (not an AttributeError); sweeps take them."""
    from cams.machine.machinefile import load_machine

    machine = (EXAMPLES / "machines" / "slotting_machine.toml").read_text(encoding="utf-8")
    head = machine[: machine.index("[follower]")]
    tail = machine[machine.index("[[motion]]"):]
    tail = tail[: tail.index("[limits]")]
    path = tmp_path / "m.toml"
    path.write_text(head + '[follower]\nkind = "rocker"\nface = "flat"\nswing = 15.0\ncentre_distance = 120.0\n'
                    'rise_direction = "cw"\n' + tail, encoding="utf-8")
    with pytest.raises(InputError, match="follower.face"):
        load_machine(path)


@pytest.mark.parametrize("swing, offset, words", [(90.0, 0.0, "face_offset above 0"), (120.0, 0.0, "face_offset above 60"),
                                                   (15.0, -150.0, "face_offset above -115.911")])
def test_flat_rocker_swing_past_the_cam_centre_names_the_swing(tmp_path, capsys, swing, offset, words):
    """The face line would pass the cam centre: the error names follower.swing and the face offset that would fit
    (f + L cos(swing) > 0 with L = 120), not a key the file does not have."""
    text = ROCKER.read_text(encoding="utf-8")
    lines = [f"swing = {swing!r}" if ln.startswith("swing =") else f"face_offset = {offset!r}"
             if ln.startswith("face_offset =") else ln for ln in text.splitlines()]
    path = tmp_path / "r.toml"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    rc, _, err = _run(capsys, "solve", str(path))
    assert rc == 2 and err.startswith("cams solve: error: follower.swing: ") and words in err, err


def test_machine_refuses_a_flat_face_first(tmp_path, capsys):
    """A machine file whose follower says face = "flat" (the rest a roller's keys) is told flat faces are not for
    machines, not sent fixing arm or pressure_angle first."""
    machine = (EXAMPLES / "machines" / "slotting_machine.toml").read_text(encoding="utf-8")
    path = tmp_path / "m.toml"
    path.write_text(machine.replace("[follower]\n", '[follower]\nface = "flat"\n', 1), encoding="utf-8")
    rc, _, err = _run(capsys, "machine", str(path))
    assert rc == 2 and err.startswith("cams machine: error: follower.face: a machine's feed cam is sized for roller"), err
