"""Every key a machine file accepts does something; the rest is refused when the file loads, naming the field.

Without ``--forces``: the [forces] table, the loads' windows and [dynamics] are checked on loading, so a
plain ``cams machine FILE`` refuses what ``--forces`` would.
"""

from __future__ import annotations

import copy
import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main
from cams.io.designfile import dynamics_from_dict
from cams.machine.design import design_machine
from cams.machine.kinetostatics import ForceSpec, LinkMass, Resistance, analyse_forces
from cams.machine.linkage.machines import CrankSlider
from cams.machine.machinefile import force_spec_from_dict, machine_from_dict
from cams.machine.timing import Drive, Timing, place_cam, windows
from laws.errors import InputError
from laws.units import LENGTH_UNITS

ROOT = Path(__file__).resolve().parents[2]
SLOTTING = ROOT / "examples" / "machines" / "slotting_machine.toml"
PUMP = ROOT / "examples" / "machines" / "pump.toml"
FORCES = ROOT / "tests" / "machine" / "forces" / "data" / "slotting_forces.toml"


def raw(path: Path) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


def refused(d: dict) -> InputError:
    with pytest.raises(InputError) as e:
        machine_from_dict(d)
    assert "\n" not in str(e.value)
    return e.value


def cli_error(tmp_path, capsys, text: str) -> str:
    """``cams machine FILE`` (no --forces) on ``text``: exit 2 and the one line on stderr."""
    f = tmp_path / "m.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["machine", str(f)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    return err


# --------------------------------------------------------------------------- [cam] bore_radius
def test_bore_is_checked_against_the_profile(capsys):
    d = raw(SLOTTING)
    d["cam"] = {"bore_radius": 10.0}
    res = design_machine(machine_from_dict(d))
    assert res.bore["bore_radius"] == 10.0 and res.bore["clear"] and res.ok
    assert res.bore["min_work_radius"] > 10.0
    assert any("bore radius 10 mm" in n and "clears it" in n for n in res.notes)
    assert res.to_dict()["bore"] == res.bore
    # a bore larger than the profile's smallest radius: the feed cam is sized to clear it (by the hub wall)...
    bore = float(np.ceil(res.bore["min_work_radius"])) + 1.0
    d["cam"] = {"bore_radius": bore, "hub_wall": 2.0}
    grown = design_machine(machine_from_dict(d))
    assert grown.bore["clear"] and grown.ok and grown.solve.governs == "bore"
    assert grown.bore["min_work_radius"] == pytest.approx(bore + 2.0, rel=1e-9)
    # ... unless the pressure angle alone sizes it: then it fails the run
    d["cam"] = {"bore_radius": bore}
    d["solve"] = {**d.get("solve", {}), "constraints": "pressure_angle"}
    big = design_machine(machine_from_dict(d))
    assert not big.bore["clear"] and not big.ok
    assert any("NOT clear" in n for n in big.notes)


def test_bore_fails_the_command(tmp_path, capsys):
    f = tmp_path / "bore.toml"
    text = SLOTTING.read_text(encoding="utf-8").replace("[solve]\n", '[solve]\nconstraints = "pressure_angle"\n')
    f.write_text(text + "\n[cam]\nbore_radius = 200.0\n", encoding="utf-8")
    assert main(["machine", str(f), "--json"]) == 1
    rep = json.loads(capsys.readouterr().out)
    assert rep["bore"]["clear"] is False and rep["bore"]["bore_radius"] == 200.0


def test_no_bore_no_check():
    res = design_machine(machine_from_dict(raw(SLOTTING)))
    assert res.bore is None and res.to_dict()["bore"] is None


# --------------------------------------------------------------------------- [timing] follower_direction
def test_follower_direction_with_gears_of_another_ratio():
    d = raw(PUMP)  # gears 20/40: the cam turns 0.5 times a crank turn
    d.setdefault("timing", {})["follower_direction"] = 90.0
    e = refused(d)
    assert e.field == "timing.follower_direction" and "0.5 times per crank turn" in str(e) and "remove it" in str(e)


def test_follower_direction_with_equal_gears():
    d = raw(SLOTTING)
    d["timing"]["follower_direction"] = 30.0
    d["drive"] = {"kind": "gears", "z_crank": 30, "z_cam": 30, "mesh": "external"}
    e = refused(d)
    assert e.field == "timing.follower_direction" and "against the crank" in str(e)
    d["drive"]["mesh"] = "internal"  # turns with the crank: the key angle is fixed
    spec = machine_from_dict(d)
    t = place_cam(windows(spec.linkage, spec.cutting), spec.cam.program, spec.drive, spec.timing)
    assert np.degrees(t.key_angle) == pytest.approx(30.0 - np.degrees(t.mount_frame))


def test_place_cam_refuses_follower_direction_with_gears():
    spec = machine_from_dict(raw(PUMP))
    with pytest.raises(InputError) as e:
        place_cam(windows(spec.linkage, spec.cutting), spec.cam.program, spec.drive,
                  Timing(margin=spec.timing.margin, follower_direction=1.0))
    assert e.value.field == "timing.follower_direction"
    assert Drive.gears(20, 20, mesh="internal").ratio == 1  # the one gear drive that keeps the key angle


# --------------------------------------------------------------------------- [dynamics] journal_radius
def test_journal_radius_of_a_translating_follower(tmp_path, capsys):
    d = raw(FORCES)
    d["follower"] = {"kind": "translating", "stroke": 10.0, "roller_radius": 8.0}
    d["dynamics"] = {"mass": 0.5, "spring_rate": 2000.0, "friction": 0.1, "journal_radius": 8.0}
    e = refused(d)
    assert e.field == "dynamics.journal_radius" and "rocker" in str(e) and "guide" in str(e)
    del d["dynamics"]["journal_radius"]
    assert machine_from_dict(d).cam.dynamics.dynamics.journal_radius == 0.0


def test_dynamics_from_dict_follower_kind():
    table = {"mass": 0.5, "friction": 0.1, "journal_radius": 8.0}
    with pytest.raises(InputError, match="dynamics.journal_radius: applies to a rocker"):
        dynamics_from_dict(table, follower="translating")
    assert dynamics_from_dict(table, follower="rocker").dynamics.journal_radius == 8.0


# --------------------------------------------------------------------------- units
def test_only_mm():
    assert LENGTH_UNITS == {"mm": 1e-3}
    with pytest.raises(InputError) as e:
        dynamics_from_dict({"mass": 0.5}, "cm")
    assert e.value.field == "units" and "mm" in str(e.value) and "journal_radius" in str(e.value)
    with pytest.raises(InputError, match="units: 'in' is not supported: machine files are in mm"):
        force_spec_from_dict({}, "slotting", units="in")


# --------------------------------------------------------------------------- [forces.links.NAME] cg
@pytest.mark.parametrize("link", ["tool", "block"])
def test_cg_of_a_sliding_body_is_refused_on_loading(tmp_path, capsys, link):
    text = FORCES.read_text(encoding="utf-8")
    head = f"[forces.links.{link}]"
    assert head in text
    err = cli_error(tmp_path, capsys, text.replace(head, head + "\ncg = 40.0", 1))
    assert f"forces.links.{link}.cg: does not apply to the {link}" in err
    assert "centre of mass is taken at its pin" in err and "'bar'" in err


def test_cg_of_a_turning_link_is_used():
    d = raw(FORCES)
    d["forces"]["links"]["bar"]["cg"] = 30.0
    fs = machine_from_dict(d).forces
    assert fs.links["bar"].cg == 30.0


def test_cg_of_a_slider_refused_by_the_api():
    m = CrankSlider(crank=100.0, rod=400.0, rpm=120)
    with pytest.raises(InputError) as e:
        analyse_forces(m, ForceSpec(links={"slider": LinkMass(10.0, 0.0, 5.0)}), samples=12)
    assert e.value.field == "forces.links.slider.cg"


# --------------------------------------------------------------------------- [forces.friction] radius
@pytest.mark.parametrize(
    "old, new, field",
    [
        ("prismatic = { coefficient = 0.15 }", "prismatic = { coefficient = 0.15, radius = 3.0 }",
         "forces.friction.prismatic.radius"),
        ("prismatic = { coefficient = 0.15 }", "prismatic = { coefficient = 0.15 }\nC_guide = { coefficient = 0.1, radius = 2.0 }",
         "forces.friction.C_guide.radius"),
    ],
)
def test_radius_of_a_prismatic_pair_is_refused(tmp_path, capsys, old, new, field):
    text = FORCES.read_text(encoding="utf-8")
    assert old in text
    err = cli_error(tmp_path, capsys, text.replace(old, new, 1))
    assert f"{field}: applies to a revolute pair's journal" in err


def test_overridden_entry_is_still_checked():
    """A `prismatic` entry every pair overrides is still checked (it is accepted, so it must be valid)."""
    table = {"friction": {"prismatic": {"coefficient": -1.0}, "A_slot": {"coefficient": 0.1}, "C_guide": {"coefficient": 0.1}}}
    with pytest.raises(InputError, match="forces.friction.prismatic.coefficient"):
        force_spec_from_dict(table, "slotting")


def test_revolute_radius_is_used():
    fs, _ = force_spec_from_dict({"friction": {"revolute": {"coefficient": 0.1, "radius": 15.0},
                                               "O2": {"coefficient": 0.2, "radius": 20.0}}}, "slotting")
    assert fs.friction["A"].radius == 15.0 and fs.friction["O2"].radius == 20.0


# --------------------------------------------------------------------------- [[forces.loads]] resistance
LOAD = '[[forces.loads]]          # cutting resistance Q over the cut (window from [cutting])\nkind = "resistance"\nbody = "tool"\nforce = 1000.0\n'


@pytest.mark.parametrize(
    "extra, field, words",
    [
        ("approach = 1.5", "forces.loads[0].approach", "must be a fraction of the stroke in [0, 1), got 1.5"),
        ("overrun = -0.1", "forces.loads[0].overrun", "[0, 1)"),
        ('approach = 0.6\noverrun = 0.5', "forces.loads[0].overrun", "approach + overrun must be < 1"),
        ('working = "sideways"', "forces.loads[0].working", "not a valid option"),
        ('window = "sometimes"', "forces.loads[0].window", "not a valid option"),
        ('window = "working"\napproach = 0.1', "forces.loads[0].approach", "applies to window = 'cut' only"),
        ('window = "always"\noverrun = 0.1', "forces.loads[0].overrun", "applies to window = 'cut' only"),
        ('window = "working"\napproach = 1.5', "forces.loads[0].approach", "applies to window = 'cut' only"),
        ('window = "always"\nworking = "fast"', "forces.loads[0].working", "window = 'always'"),
    ],
)
def test_resistance_checked_on_loading(tmp_path, capsys, extra, field, words):
    text = FORCES.read_text(encoding="utf-8")
    assert LOAD in text
    err = cli_error(tmp_path, capsys, text.replace(LOAD, LOAD + extra + "\n", 1))
    assert f"{field}: " in err and words in err, err


@pytest.mark.parametrize(
    "body, words",
    [("crank", "'crank' does not slide on a guide"), ("wheel", "'wheel' is not a link of a slotting linkage")],
)
def test_load_body_checked_on_loading(tmp_path, capsys, body, words):
    text = FORCES.read_text(encoding="utf-8")
    err = cli_error(tmp_path, capsys, text.replace(LOAD, LOAD.replace('"tool"', f'"{body}"'), 1))
    assert "forces.loads[0].body: " in err and words in err and "'block', 'tool'" in err, err


def test_resistance_windows_that_need_no_approach():
    d = raw(FORCES)
    d["forces"]["loads"] = [{"kind": "resistance", "body": "tool", "force": 10.0, "window": "working"},
                            {"kind": "resistance", "body": "tool", "force": 5.0, "window": "always"}]
    fs = machine_from_dict(d).forces
    assert [(ld.approach, ld.overrun) for ld in fs.loads] == [(0.0, 0.0), (0.0, 0.0)]  # not [cutting]'s 0.05


def test_resistance_api_messages():
    with pytest.raises(InputError) as e:
        Resistance("tool", 5.0, approach=1.5)
    assert e.value.field == "forces.loads.approach"
    with pytest.raises(InputError) as e:
        Resistance("tool", 5.0, window="working", overrun=0.1)
    assert e.value.field == "forces.loads.overrun" and "window = 'cut' only" in str(e.value)
    with pytest.raises(InputError) as e:
        Resistance("tool", 5.0, working="sideways")
    assert e.value.field == "forces.loads.working"


def test_second_load_is_named_by_its_index():
    d = copy.deepcopy(raw(FORCES))
    d["forces"]["loads"].append({"kind": "resistance", "body": "tool", "force": 5.0, "approach": 2.0})
    e = refused(d)
    assert e.field == "forces.loads[1].approach"


def test_bore_figure_against_the_pitch_curve():
    """The profile's smallest radius the bore check prints, against the mechanism: the working profile's nearest
    point to the cam centre lies on the radius through the pitch curve's nearest point, one roller radius in, so
    min |work| = min |pitch| - r, the pitch curve by kinematic inversion from the motion program on a dense grid.
    The check reads the exact smallest radius (the kernel's, refined), not the exported polyline's."""
    d = raw(SLOTTING)
    d["cam"] = {"bore_radius": 10.0}
    res = design_machine(machine_from_dict(d))
    design, O = res.solve.design, res.solve.centre
    f = design.follower
    phi = np.linspace(0.0, 2 * np.pi, 200_001)
    s = design.program.evaluate(phi).s
    th = f.sense * s                                  # the rocker's angle from the near dwell (pivot at the origin)
    A = f.arm * np.stack([np.cos(th), np.sin(th)], axis=-1)
    pitch_radius = np.hypot(A[:, 0] - O[0], A[:, 1] - O[1])   # a rotation about O keeps the distance
    expected = pitch_radius.min() - f.roller_radius
    assert res.bore["min_work_radius"] == pytest.approx(expected, abs=1e-8 * f.arm)
    assert res.bore["min_work_radius"] == res.solve.to_dict()["smallest_cam_radius"]   # one number everywhere
