"""``cams check`` and ``cams profile`` on the command line: output, JSON, exit codes."""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CHECK_KEYS = {"name", "passed", "worst", "at_deg", "limit", "unit"}


@pytest.mark.parametrize("name", ["rocker_force", "translating_form_centric"])
def test_check_json_passes(capsys, name):
    code = main(["check", str(EXAMPLES / f"{name}.toml"), "--json"])
    rep = json.loads(capsys.readouterr().out)
    assert code == 0 and rep["passed"] is True
    assert all(set(c) == CHECK_KEYS and c["passed"] for c in rep["checks"])
    assert {c["name"] for c in rep["checks"]} >= {"jamming_rise", "undercut", "profile_polygon"}


def test_check_text_output(capsys):
    assert main(["check", str(EXAMPLES / "rocker_form.toml"), "--tolerance", "0.01"]) == 0
    out = capsys.readouterr().out
    assert "tolerance 0.01 mm" in out and "pressure angle, return" in out and "all checks pass" in out


def test_check_fails_with_exit_1_for_undercut(tmp_path, capsys):
    """The pressure angle's cam alone (``constraints = "pressure_angle"``) with a 28 mm roller undercuts."""
    text = (EXAMPLES / "rocker_form.toml").read_text().replace("roller_radius = 10.0", "roller_radius = 28.0")
    text = text.replace("[solve]\n", '[solve]\nconstraints = "pressure_angle"\n')
    f = tmp_path / "big_roller.toml"
    f.write_text(text)
    assert main(["check", str(f), "--json"]) == 1
    rep = json.loads(capsys.readouterr().out)
    bad = {c["name"] for c in rep["checks"] if not c["passed"]}
    assert "undercut" in bad
    u = next(c for c in rep["checks"] if c["name"] == "undercut")
    assert 170 < u["at_deg"] < 180 and u["limit"] == 28.0
    assert rep["largest_roller_radius"] == pytest.approx(u["worst"])


@pytest.mark.parametrize("args,field", [
    (["--tolerance", "0"], "--tolerance"),
    (["--tolerance", "-0.001"], "--tolerance"),
    (["--tolerance", "nan"], "--tolerance"),
])
def test_check_bad_input_exit_2(capsys, args, field):
    assert main(["check", str(EXAMPLES / "rocker_force.toml"), *args]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and field in err


def test_check_bad_profile_table_exit_2(tmp_path, capsys):
    f = tmp_path / "bad.toml"
    f.write_text((EXAMPLES / "rocker_force.toml").read_text() + "\n[profile]\ntolerance = 0.01\ncolour = 'red'\n")
    assert main(["check", str(f)]) == 2
    assert "colour" in capsys.readouterr().err


def test_groove_with_knife_edge_is_not_buildable(tmp_path, capsys):
    """A knife edge cannot run in a groove: not buildable (exit 1, naming the key), as in every command."""
    f = tmp_path / "knife_groove.toml"
    f.write_text((EXAMPLES / "rocker_form.toml").read_text().replace("roller_radius = 10.0", "roller_radius = 0.0"))
    assert main(["check", str(f)]) == 1
    out = capsys.readouterr().out
    assert "buildable: NO" in out and "follower.roller_radius" in out


def test_profile_writes_all_three(tmp_path, capsys):
    csv, dxf, svg = tmp_path / "c.csv", tmp_path / "c.dxf", tmp_path / "c.svg"
    code = main(["profile", str(EXAMPLES / "rocker_form.toml"), "--csv", str(csv), "--dxf", str(dxf),
                 "--svg", str(svg), "--tolerance", "0.002", "--json"])
    rep = json.loads(capsys.readouterr().out)
    assert code == 0 and rep["groove"] is True and rep["tolerance"] == 0.002
    assert sorted(os.listdir(tmp_path)) == ["c.csv", "c.dxf", "c.svg"]
    with open(csv) as fh:
        assert fh.readline().strip() == "phi_deg,pitch_x,pitch_y,work_x,work_y,outer_x,outer_y"
    data = np.loadtxt(csv, delimiter=",", skiprows=1)
    assert len(data) == rep["points"] and data[0, 0] == 0.0


def test_profile_text_summary(tmp_path, capsys):
    out_csv = tmp_path / "t.csv"
    assert main(["profile", str(EXAMPLES / "translating_force.toml"), "--csv", str(out_csv)]) == 0
    out = capsys.readouterr().out
    assert "points at tolerance 0.001 mm" in out and f"wrote {out_csv}" in out


def test_profile_unwritable_output_exit_2_and_nothing_written(tmp_path, capsys):
    good = tmp_path / "ok.csv"
    code = main(["profile", str(EXAMPLES / "rocker_force.toml"), "--csv", str(good),
                 "--dxf", str(tmp_path / "missing" / "c.dxf")])
    err = capsys.readouterr().err
    assert code == 2 and "--dxf" in err and err.count("\n") == 1
    assert os.listdir(tmp_path) == []  # checked before anything is written
