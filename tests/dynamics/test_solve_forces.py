"""Forces at the cam through ``cams solve`` and the report: the same numbers as the API."""

import json

import pytest

from cams.cam import Cam
from cams.cli import main
from cams.dynamics.forces import cam_forces, chosen_spring
from cams.dynamics.jump import jump_speed
from cams.present.report import report_sections
from tests.conftest import EXAMPLES

FILE = EXAMPLES / "slotting_feed_cam.toml"


def test_solve_json_reports_the_forces(capsys):
    assert main(["solve", str(FILE), "--json"]) == 0
    fo = json.loads(capsys.readouterr().out)["forces"]
    cam = Cam.from_file(FILE)
    spec = cam.design.dynamics
    dyn = spec.dynamics.with_spring(chosen_spring(spec, cam.design))
    cf = cam_forces(cam.design, cam.solution.centre, dyn)
    assert fo["max_contact_force"] == pytest.approx(float(cf.contact.max()), rel=1e-12)
    assert fo["jump_rpm"] == pytest.approx(jump_speed(cam.design, dyn).rpm, rel=1e-12)
    assert fo["jump_rpm"] > 60 and not fo["contact_lost"] and not fo["jammed"]


def test_no_dynamics_no_forces(capsys):
    assert main(["solve", str(EXAMPLES / "rocker_force.toml"), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["forces"] is None


def test_report_has_a_forces_page():
    titles = [t for t, _ in report_sections(Cam.from_file(FILE))]
    assert titles[-1] == "Forces at the cam"
    assert "Forces at the cam" not in [t for t, _ in report_sections(Cam.from_file(EXAMPLES / "rocker_force.toml"))]


def test_cams_solve_computes_the_forces_once(monkeypatch, capsys):
    """The forces printed and the assessment's [dynamics] check come from one call (Cam.forces, Cam.forces_note)."""
    import cams.dynamics.forces
    from cams.cli import main
    from tests.conftest import EXAMPLES

    calls = []
    real = cams.dynamics.forces.design_forces
    monkeypatch.setattr(cams.dynamics.forces, "design_forces", lambda *a, **k: calls.append(1) or real(*a, **k))
    assert main(["solve", str(EXAMPLES / "slotting_feed_cam.toml")]) == 0
    out = capsys.readouterr().out
    assert len(calls) == 1 and "contact force" in out
