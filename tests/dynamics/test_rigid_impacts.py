"""Velocity jumps (rigid impacts) at a force-closed cam: unbounded forces, contact lost at any speed, said so."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main
from cams.dynamics.forces import cam_forces
from cams.dynamics.impacts import rigid_impacts
from cams.dynamics.jump import jump_speed
from cams.io.designfile import load_design
from cams.model.dynamics import FollowerDynamics, Spring
from cams.solve import solve
from laws.units import rpm_to_omega

ROOT = Path(__file__).resolve().parents[2]
FEED = ROOT / "examples" / "slotting_feed_cam.toml"
TRANS = ROOT / "examples" / "translating_force.toml"
MACHINE = Path(__file__).resolve().parents[1] / "machine" / "forces" / "data" / "slotting_forces.toml"


def _strict(text: str):
    def refuse(name):
        raise ValueError(f"not strict JSON: {name}")

    return json.loads(text, parse_constant=refuse)


def test_linear_rise_has_unbounded_force_and_loses_contact(linear_feed):
    design = load_design(linear_feed)
    imps = rigid_impacts(design)
    assert [round(float(np.degrees(i.phi)), 9) for i in imps] == [0.0, 60.0]
    assert [i.effect for i in imps] == ["impulse", "separation"]
    dyn = FollowerDynamics(0.003, load=0.5, spring=Spring(3.0, 0.2), friction=0.1, journal_radius=8.0)
    f = cam_forces(design, solve(design).centre, dyn, rpm=60)
    assert f.impacts == imps and f.unbounded and f.separation and f.contact_lost and not f.ok
    d = f.to_dict()
    assert d["max_contact_force"] == np.inf and d["max_contact_at_deg"] == 0.0 and d["min_contact_force"] == -np.inf
    assert d["contact_lost"] is True and d["contact_force_unbounded"] is True
    bi = d["between_impacts"]
    assert np.isfinite(bi["max_contact_force"]) and bi["max_contact_force"] > 0
    # the swing jumps by 15 deg over 60 deg of cam: 0.25 rad/rad, at 60 rpm (2 pi rad/s) 90 deg/s
    assert [i["velocity_jump"] for i in d["impacts"]] == pytest.approx([90.0, -90.0], rel=1e-9)
    assert {i["unit"] for i in d["impacts"]} == {"deg/s"}
    j = jump_speed(design, dyn)
    assert j.rpm == 0.0 and j.at_impact and np.degrees(j.phi) == pytest.approx(60.0)
    assert j.between_impacts_rpm > 0


def test_translating_velocity_jump_in_mm_per_s():
    design = load_design(TRANS)
    from dataclasses import replace

    from laws.program import Phase, Program

    p = design.program
    prog = Program(tuple(Phase(ph.kind, ph.angle, "linear") if ph.kind != "dwell" else ph for ph in p.phases), p.lift)
    d = design.with_(program=prog) if hasattr(design, "with_") else replace(design, program=prog)
    imps = rigid_impacts(d)
    assert imps and all(i.unit == "mm/s" for i in imps)
    w = rpm_to_omega(100.0)
    # each linear phase starts and ends with a jump of lift / angle (mm per radian) times omega
    expected = sorted(2 * [prog.lift / ph.angle * w for ph in prog.phases if ph.kind != "dwell"])
    assert sorted(abs(i.velocity_jump(w)) for i in imps) == pytest.approx(expected, rel=1e-9)


def test_smooth_law_has_no_impacts():
    design = load_design(FEED)
    assert rigid_impacts(design) == ()
    dyn = FollowerDynamics(0.003, load=0.5, spring=Spring(3.0, 0.2))
    f = cam_forces(design, solve(design).centre, dyn, rpm=60)
    d = f.to_dict()
    assert d["impacts"] == [] and "between_impacts" not in d and d["contact_force_unbounded"] is False
    assert jump_speed(design, dyn).at_impact is False


def test_cams_solve_text_and_json(linear_feed, capsys):
    assert main(["solve", str(linear_feed)]) == 1
    out = capsys.readouterr().out
    assert "contact force: max UNBOUNDED at 0.0000 deg" in out  # angles: 4 decimals in every command
    assert "follower leaves the cam at any speed (velocity drop at 60.0000 deg)" in out and "contact lost: YES" in out
    assert "note: rigid impacts" in out and "+90 deg/s" in out and "-90 deg/s" in out
    assert "between the rigid impacts" in out
    assert main(["solve", str(linear_feed), "--json"]) == 1
    rep = _strict(capsys.readouterr().out)
    fo = rep["forces"]
    assert fo["max_contact_force"] is None and fo["contact_force_unbounded"] is True and fo["contact_lost"] is True
    assert fo["jump_rpm"] == 0.0 and fo["jump_at_impact"] is True
    assert [i["effect"] for i in fo["impacts"]] == ["impulse", "separation"]
    assert any("rigid impacts" in n for n in rep["notes"])


def test_cams_machine_forces_with_a_linear_rise(tmp_path, capsys):
    text = MACHINE.read_text(encoding="utf-8")
    assert 'law = "parabolic"' in text
    f = tmp_path / "m.toml"
    f.write_text(text.replace('law = "parabolic"', 'law = "linear"', 1), encoding="utf-8")
    assert main(["machine", str(f), "--forces", "--json"]) == 1
    rep = _strict(capsys.readouterr().out)
    cam, t = rep["forces"]["cam"], rep["timing"]
    assert cam["ok"] is False and cam["contact_lost"] is True and cam["max_contact_force"] is None
    for imp in cam["impacts"]:
        (c,) = imp["cycle_deg"]
        assert c == pytest.approx((t["mount_deg"] + imp["cam_angle_deg"]) % 360, abs=1e-9)
    assert main(["machine", str(f), "--forces"]) == 1
    out = capsys.readouterr().out
    assert "max contact force UNBOUNDED" in out and "contact lost: YES" in out and "rigid impacts" in out


def test_no_deceleration_means_no_jump_speed_in_words(tmp_path, capsys):
    """An all-linear program has no deceleration between its impacts: the jump speed there is 'none', not 'inf rpm'."""
    from pathlib import Path

    from cams.cli import main

    src = Path(__file__).resolve().parents[2] / "examples" / "slotting_feed_cam.toml"
    text = src.read_text(encoding="utf-8").replace('law = "parabolic"', 'law = "linear"').replace('law = "harmonic"', 'law = "linear"')
    path = tmp_path / "alllin.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["solve", str(path)]) == 1
    out = capsys.readouterr().out
    assert "jump speed none (no deceleration" in out and "inf rpm" not in out
