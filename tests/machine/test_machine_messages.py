"""``cams machine``'s one-line errors: design files, plain numbers, the --plot option."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main
from cams.machine.timing import CuttingZone, Drive, Timing
from laws.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
SLOTTING = ROOT / "examples" / "machines" / "slotting_machine.toml"


def _err(capsys) -> str:
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0, err
    return err


def test_design_file_is_named_as_such(capsys):
    assert main(["machine", str(ROOT / "examples" / "rocker_force.toml")]) == 2
    err = _err(capsys)
    assert "no [linkage] table" in err and "cams solve" in err and "None" not in err, err


def test_linkage_without_type(tmp_path, capsys):
    f = tmp_path / "m.toml"
    f.write_text(SLOTTING.read_text(encoding="utf-8").replace('type = "slotting"', "", 1), encoding="utf-8")
    assert main(["machine", str(f)]) == 2
    err = _err(capsys)
    assert "linkage.type: is required" in err and "None" not in err, err


@pytest.mark.parametrize(
    "old, new, field, shown",
    [
        ("margin = 5.0", "margin = -5.0", "timing.margin", "got -5"),
        ("approach = 0.05", "approach = 1.5", "cutting.approach", "got 1.5"),
        ("stroke = 100.0", "stroke = -100.0", "linkage.stroke", "got -100"),
        ("rod_ratio = 1.0", "rod_ratio = 0.0", "linkage.rod_ratio", "got 0"),
    ],
)
def test_numbers_are_plain(tmp_path, capsys, old, new, field, shown):
    text = SLOTTING.read_text(encoding="utf-8")
    assert old in text
    f = tmp_path / "m.toml"
    f.write_text(text.replace(old, new, 1), encoding="utf-8")
    assert main(["machine", str(f)]) == 2
    err = _err(capsys)
    assert field in err and shown in err and "np." not in err and "float64" not in err, err


@pytest.mark.parametrize(
    "make, shown",
    [
        (lambda: Timing(margin=np.float64(-0.1)), "-5.729577951"),
        (lambda: Drive(ratio=np.float64(-2.0)), "got -2"),
        (lambda: CuttingZone(overrun=np.float64(1.0)), "got 1"),
    ],
)
def test_api_messages_show_plain_numbers(make, shown):
    with pytest.raises(InputError) as e:
        make()
    assert shown in str(e.value) and not re.search(r"np\.|float64", str(e.value)), str(e.value)


def test_plot_into_an_existing_file_names_the_option(tmp_path, capsys):
    afile = tmp_path / "afile"
    afile.write_text("x", encoding="utf-8")
    assert main(["machine", str(SLOTTING), "--plot", str(afile)]) == 2
    err = _err(capsys)
    assert "--plot" in err and "is a file" in err, err
    assert main(["machine", str(SLOTTING), "--plot", str(afile / "sub")]) == 2
    err = _err(capsys)
    assert "--plot" in err, err
    assert afile.read_text(encoding="utf-8") == "x"


def test_machine_with_an_unbuildable_cam_fails(tmp_path, capsys):
    """The same rule as cams solve: a minimum R0 not larger than the roller radius is a failed check (exit 1)
    (the pressure angle alone sizing it: sized to the part it would grow past the roller)."""
    from pathlib import Path

    from cams.cli import main

    src = Path(__file__).resolve().parents[2] / "examples" / "machines" / "slotting_machine.toml"
    path = tmp_path / "big_roller.toml"
    path.write_text(src.read_text(encoding="utf-8").replace("roller_radius = 15.0", "roller_radius = 45.0")
                    .replace("[solve]\n", '[solve]\nconstraints = "pressure_angle"\n'), encoding="utf-8")
    assert main(["machine", str(path), "--json"]) == 1
    import json

    cam = json.loads(capsys.readouterr().out)["cam"]
    assert cam["buildable"] is False and cam["verified"] is True and cam["R0"] < 45.0
