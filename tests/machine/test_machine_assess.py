"""``cams machine`` judges its feed cam by the rule every command shares (cams.assess), as ``cams check`` does."""

import json
from pathlib import Path

import pytest

from cams.cli import main

SLOTTING = Path(__file__).resolve().parents[2] / "examples" / "machines" / "slotting_machine.toml"


def _files(tmp_path, roller: str, closure: str = "force", constraints: str = "pressure_angle"):
    """The slotting machine with another roller (and closure), and the same feed cam as a design file.

    The machine turns its cam counter-clockwise on the crank's shaft at the crank's 60 rpm: the design file says
    so in its [cam] table and copies the machine file's cam tables ([follower] to the end) unchanged. The cam is
    sized by ``[solve] constraints`` (``"pressure_angle"``: the pressure angle alone, so that a cam that fails its
    profile's checks is kept and judged).
    """
    text = SLOTTING.read_text(encoding="utf-8").replace("roller_radius = 15.0", f"roller_radius = {roller}")
    text = text.replace('closure = "force"', f'closure = "{closure}"')
    assert "[solve]\n" in text
    text = text.replace("[solve]\n", f'[solve]\nconstraints = "{constraints}"\n')
    machine = tmp_path / "machine.toml"
    machine.write_text(text, encoding="utf-8")
    cam_tables = text[text.index("[follower]"):]
    design = tmp_path / "design.toml"
    design.write_text('name = "feed cam"\n[cam]\nrotation = "ccw"\nrpm = 60\n\n' + cam_tables, encoding="utf-8")
    return machine, design


def _json(capsys, argv) -> tuple[int, dict]:
    code = main([*argv, "--json"])
    return code, json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("roller, closure, constraints, usable", [
    ("15.0", "force", "pressure_angle", True),   # the example: R0 = 40.06 mm, no undercut
    ("25.0", "force", "pressure_angle", False),  # R0 = 40.06 mm > 25 mm, but the pitch curve's radius of
                                                 # curvature 19.7 mm < 25 mm: undercut
    ("25.0", "force", "all", True),              # sized to the part: the roller governs, no undercut
    ("0.0", "form", "all", False),               # a knife edge in a groove
])
def test_machine_assesses_its_cam_as_check_does(tmp_path, capsys, roller, closure, constraints, usable):
    machine, design = _files(tmp_path, roller, closure, constraints)
    mcode, mrep = _json(capsys, ["machine", str(machine)])
    ccode, crep = _json(capsys, ["check", str(design)])
    for key in ("verified", "buildable", "failures"):
        assert mrep[key] == crep[key], key
    assert (mcode, ccode) == ((0, 0) if usable else (1, 1))
    assert mrep["buildable"] is usable and (usable or mrep["failures"])
    if "R0" in crep:    # the same cam, sized the same way (a knife edge in a groove has no profile to check)
        assert mrep["cam"]["R0"] == pytest.approx(crep["R0"], rel=1e-12)


def test_undercut_feed_cam_is_reported_in_words_and_fails(tmp_path, capsys):
    machine, _ = _files(tmp_path, "25.0")
    assert main(["machine", str(machine)]) == 1
    out = capsys.readouterr().out
    assert "verified: yes" in out and "buildable: NO" in out
    assert "FAIL: undercut" in out and "roller radius 25" in out


def test_machine_result_ok_is_the_shared_usable(tmp_path):
    from cams.assess import assess_cam
    from cams.cam import Cam
    from cams.io.designfile import load_design
    from cams.machine.design import design_machine
    from cams.machine.machinefile import load_machine

    machine, design = _files(tmp_path, "25.0")
    res = design_machine(load_machine(machine))
    cam = Cam(load_design(design))
    ref = assess_cam(cam)
    assert res.solve.R0 == pytest.approx(cam.solution.R0, rel=1e-12)  # the same cam, sized the same way
    assert not res.overlap  # the timing is fine: only the cam fails
    assert res.assessment.failures == ref.failures and not ref.usable
    assert not res.ok
