"""The contact through the commands: cams solve's words and its JSON contact object (each figure recomputed here
in another notation), cams check failing a cam whose stress, film or life fails (exit 1), the least width that
brings p0 to the allowable exactly, the flat face's zero entrainment flagged, and the bad inputs (exit 2)."""

from __future__ import annotations

import json
import tomllib

import numpy as np
import pytest

from cams.cli import main
from tests.commands.test_bad_input import to_toml
from tests.conftest import EXAMPLES

#: the JSON contact object's keys, exactly the issue's
KEYS = {
    "force_model",
    "max_pressure",
    "max_pressure_at_deg",
    "at_max",
    "max_shear",
    "max_shear_depth",
    "max_von_mises",
    "min_film",
    "min_film_parameter",
    "zero_entrainment_at_deg",
    "min_width",
    "bearing_life_hours",
    "limit",
}
#: the materials' constants as the test reads them off the table's sources (E MPa, nu)
STEEL, BEARING = (206e3, 0.30), (208e3, 0.30)


def _doc(name: str) -> dict:
    return tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8"))


def _run(tmp_path, doc: dict, capsys, *args: str, command: str = "solve") -> tuple[int, str, str]:
    f = tmp_path / "d.toml"
    f.write_text(to_toml(doc), encoding="utf-8")
    capsys.readouterr()
    rc = main([command, str(f), *args])
    out = capsys.readouterr()
    return rc, out.out, out.err


def _json(tmp_path, doc, capsys) -> tuple[int, dict]:
    rc, out, _ = _run(tmp_path, doc, capsys, "--json")
    return rc, json.loads(out)


@pytest.mark.parametrize("name", ["translating_contact.toml", "rocker_contact.toml", "translating_flat_contact.toml"])
def test_solve_says_the_contact(name, capsys):
    capsys.readouterr()
    rc = main(["solve", str(EXAMPLES / name)])
    out = capsys.readouterr().out
    assert rc == 0
    assert "largest Hertz pressure p0" in out and " MPa at " in out
    assert "lubricant film: thinnest" in out and "µm" in out
    assert "least face width for the allowable stress" in out
    assert "contact limit that binds" in out
    assert "unconservative" in out and "edge" in out
    if "flat" not in name:
        assert "L10 life" in out and " h at the cam's speed" in out


def _norton_p0(F, L, R1, R2, m1, m2):
    B = 0.5 * (1.0 / R1 + 1.0 / R2)
    a = np.sqrt(2 * F * ((1 - m1[1] ** 2) / m1[0] + (1 - m2[1] ** 2) / m2[0]) / (np.pi * L * B))
    return 2 * F / (np.pi * a * L), a


def test_the_json_contact_recomputed(tmp_path, capsys):
    """The largest p0 from its own force and radii (Norton's notation, the materials' constants typed here); the
    subsurface stresses as their known fractions; the least width brings p0 to the allowable (770 MPa, through-
    hardened steel) exactly when solved at that width (the rigid force does not depend on the width)."""
    doc = _doc("translating_contact.toml")
    rc, rep = _json(tmp_path, doc, capsys)
    co = rep["contact"]
    assert rc == 0 and set(co) == KEYS
    assert set(co["at_max"]) == {"force", "cam_curvature_radius", "follower_radius", "half_width"}
    am = co["at_max"]
    p0, b = _norton_p0(am["force"], 12.0, am["cam_curvature_radius"], am["follower_radius"], STEEL, BEARING)
    assert co["max_pressure"] == pytest.approx(p0, rel=1e-12)
    assert am["half_width"] == pytest.approx(b, rel=1e-12)
    assert am["follower_radius"] == 12.0 and co["force_model"] == "rigid"
    assert co["max_shear"] == pytest.approx(0.300283 * p0, rel=2e-6)
    assert co["max_shear_depth"] == pytest.approx(0.786151 * b, rel=1e-5)
    assert co["max_von_mises"] == pytest.approx(0.5575 * p0, rel=1e-4)
    assert co["min_width"] == pytest.approx(12.0 * (p0 / 770.0) ** 2, rel=1e-12)
    doc["cam"]["width"] = co["min_width"]
    doc["solve"] = {"constraints": "pressure_angle"}  # the same cam: at p0 = allowable the sizing may not lift it
    _, narrow = _json(tmp_path, doc, capsys)
    assert narrow["contact"]["max_pressure"] == pytest.approx(770.0, rel=1e-9)
    assert narrow["forces"]["max_contact_force"] == rep["forces"]["max_contact_force"]


def test_the_largest_pressure_is_the_largest_over_the_turn(tmp_path, capsys):
    """The largest p0 is at least that of the largest force and of the sharpest convex curvature (each of them
    computed here with that sample's radius)."""
    from cams.cam import Cam
    from cams.io.designfile import load_design

    cam = Cam(load_design(EXAMPLES / "rocker_contact.toml"))
    co = cam.contact
    p0 = [_norton_p0(F, 10.0, rc, 10.0, STEEL, BEARING)[0] for F, rc in zip(co.force, co.cam_radius, strict=True)]
    assert co.max_pressure == pytest.approx(max(p0), rel=1e-12)
    assert co.to_dict()["max_pressure_at_deg"] == pytest.approx(np.degrees(co.phi[int(np.argmax(p0))]) % 360)


@pytest.mark.parametrize(
    "change, words",
    [
        ({"allowable_stress": 200.0}, "contact stress: p0 ="),
        ({"min_film_parameter": 5.0}, "lubricant film: film parameter"),
        ({"life_hours": 1e7}, "bearing life: L10 ="),
    ],
)
@pytest.mark.parametrize("command", ["check", "solve"])
def test_a_failing_contact_fails_the_cam(change, words, command, tmp_path, capsys):
    """The cam sized by its pressure angle and floor alone (else the sizing raises R0 to meet the allowable)."""
    doc = _doc("translating_contact.toml")
    doc["contact"].update(change)
    doc["solve"] = {"constraints": "pressure_angle"}
    rc, out, err = _run(tmp_path, doc, capsys, command=command)
    assert rc == 1, (out, err)
    assert words in out
    rc, rep = _json(tmp_path, doc, capsys) if command == "solve" else (1, None)
    if rep is not None:
        assert rc == 1 and any(f.startswith(words.split(":")[0]) for f in rep["failures"])
        ratio = {
            "contact stress": "contact_stress",
            "lubricant film": "film_parameter",
            "bearing life": "bearing_life",
        }[words.split(":")[0]]
        assert rep["contact"]["limit"] == ratio


def test_an_allowable_no_cam_meets_is_refused(tmp_path, capsys):
    """200 MPa on the translating example: the largest pressure levels off near 297 MPa as R0 grows (the roller's
    own radius bounds it), so no cam meets it: refused in one line naming the allowable, without scanning on."""
    import time

    doc = _doc("translating_contact.toml")
    doc["contact"]["allowable_stress"] = 200.0
    t0 = time.perf_counter()
    rc, _, err = _run(tmp_path, doc, capsys)
    assert rc == 2 and err.count("\n") == 1 and " contact.allowable_stress: no cam of this design meets it" in err
    assert "levels off" in err and time.perf_counter() - t0 < 60


def test_a_flat_face_s_zero_entrainment_is_flagged(tmp_path, capsys):
    """The flat example without its floor on R0: R0 + s + 2 s'' changes sign, the entrainment falls to zero where
    it does (checked against the program's own values) and the film with it: said, and the cam fails its film."""
    from cams.io.designfile import design_from_dict

    doc = _doc("translating_flat_contact.toml")
    del doc["limits"]["min_base_radius"]
    rc, rep = _json(tmp_path, doc, capsys)
    co = rep["contact"]
    assert rc == 1 and co["zero_entrainment_at_deg"]
    d = design_from_dict(doc)
    phi = np.radians(co["zero_entrainment_at_deg"])
    m = d.program.evaluate(phi)
    assert np.all(np.abs(rep["R0"] + m.s + 2 * m.d2s) < 0.05 * rep["R0"])
    assert any("entrainment velocity falls to zero" in n for n in rep["notes"])
    assert co["min_film_parameter"] < 0.05
    assert co["at_max"]["follower_radius"] is None  # a plane


@pytest.mark.parametrize(
    "change, field, words",
    [
        ({"contact": {"viscosity": 0.1}}, "contact.cam_material", "material"),
        ({"cam": {"rpm": 300, "width": 0.0}}, "cam.width", "> 0"),
        ({"cam": {"rpm": 300, "width": -2.0}}, "cam.width", "> 0"),
        (
            {"contact": {"cam_modulus": 0.0, "cam_poisson": 0.3, "follower_material": "steel"}},
            "contact.cam_modulus",
            "> 0",
        ),
        (
            {
                "contact": {
                    "cam_material": "steel",
                    "follower_material": "steel",
                    "cam_roughness": 0.0,
                    "follower_roughness": 0.2,
                }
            },
            "contact.cam_roughness",
            "> 0",
        ),
        (
            {"contact": {"cam_material": "steel", "follower_material": "steel", "follower_poisson": 0.5}},
            "contact.follower_poisson",
            "(-1, 0.5)",
        ),
        (
            {"contact": {"cam_material": "steel", "follower_material": "steel", "cam_poisson": -1.0}},
            "contact.cam_poisson",
            "(-1, 0.5)",
        ),
        (
            {"contact": {"cam_material": "unobtainium", "follower_material": "steel"}},
            "contact.cam_material",
            "known: steel, through_hardened_steel",
        ),
        (
            {"contact": {"cam_material": "steel", "follower_material": "steel", "life_hours": 1000.0}},
            "contact.life_hours",
            "bearing_rating",
        ),
        (
            {"contact": {"cam_material": "steel", "follower_material": "steel", "bearing_rating_type": "big"}},
            "contact.bearing_rating_type",
            "track_roller",
        ),
        (
            {"contact": {"cam_material": "steel", "follower_material": "steel", "force_model": "elastic"}},
            "contact.force_model",
            "rigid",
        ),
    ],
)
def test_bad_input_is_one_line(change, field, words, tmp_path, capsys):
    doc = _doc("translating_contact.toml")
    for table, values in change.items():
        doc[table] = values if table == "contact" else {**doc[table], **values}
    rc, out, err = _run(tmp_path, doc, capsys)
    assert rc == 2, (out, err)
    assert err.count("\n") == 1 and "Traceback" not in err
    assert f" {field}: " in err and words in err, err


def test_contact_needs_its_width_and_forces(tmp_path, capsys):
    doc = _doc("translating_contact.toml")
    del doc["cam"]["width"]
    rc, _, err = _run(tmp_path, doc, capsys)
    assert rc == 2 and " cam.width: " in err and err.count("\n") == 1
    doc = _doc("translating_contact.toml")
    del doc["dynamics"]
    rc, _, err = _run(tmp_path, doc, capsys)
    assert rc == 2 and " contact: " in err and "[dynamics]" in err
    doc = _doc("translating_flat_contact.toml")
    doc["contact"]["bearing_rating"] = 1000.0
    rc, _, err = _run(tmp_path, doc, capsys)
    assert rc == 2 and " contact.bearing_rating: " in err and "flat face" in err
