"""``cams solve`` as a user runs it: JSON keys, exit codes, one-line errors."""

import json
import subprocess
import sys

import numpy as np
import pytest

from cams.cli import main
from tests.conftest import EXAMPLES


def test_solve_json_has_the_documented_keys(capsys):
    assert main(["solve", str(EXAMPLES / "rocker_force.toml"), "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    for k in ("R0", "L", "centre", "max_pressure_angle", "binding", "method", "samples", "error_bound", "seconds"):
        assert k in rep
    assert rep["method"] == "exact" and rep["samples"] is None
    assert set(rep["centre"]) == {"x", "y"} and set(rep["max_pressure_angle"]) == {"rise", "return"}
    assert rep["max_pressure_angle"]["rise"] <= 45 + 1e-6
    assert rep["R0"] == pytest.approx(np.hypot(rep["centre"]["x"] - 125.0, rep["centre"]["y"]), rel=1e-12)
    assert rep["L"] == pytest.approx(np.hypot(rep["centre"]["x"], rep["centre"]["y"]), rel=1e-12)


@pytest.mark.parametrize("method", ["convex", "exhaustive"])
def test_method_override(capsys, method):
    assert main(["solve", str(EXAMPLES / "rocker_form.toml"), "--json", "--method", method]) in (0, 1)
    rep = json.loads(capsys.readouterr().out)
    assert rep["method"] == method and rep["samples"] == 360


def test_translating_reports_offset(capsys):
    assert main(["solve", str(EXAMPLES / "translating_force.toml"), "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    assert rep["L"] is None and rep["offset"] == pytest.approx(-rep["centre"]["x"])


def test_summary_is_readable(capsys):
    assert main(["solve", str(EXAMPLES / "rocker_form.toml")]) == 0
    out = capsys.readouterr().out
    assert "R0" in out and "verified: yes" in out


def test_bad_input_is_one_line_exit_2(tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text((EXAMPLES / "rocker_force.toml").read_text().replace("pressure_angle = 45", "pressure_angle = 95"))
    r = subprocess.run([sys.executable, "-m", "cams.cli", "solve", str(p)], capture_output=True, text=True)
    assert r.returncode == 2
    assert r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "limits.pressure_angle" in lines[0] and "(0, 90)" in lines[0]


def test_infeasible_L_is_one_line_exit_2(tmp_path, capsys):
    p = tmp_path / "l.toml"
    p.write_text((EXAMPLES / "rocker_force.toml").read_text().replace("safety_factor = 1.0", "safety_factor = 1.0\ncentre_distance = 10.0"))
    assert main(["solve", str(p)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "admissible L" in err[0]


def test_usage_error_exit_2():
    r = subprocess.run([sys.executable, "-m", "cams.cli", "solve"], capture_output=True, text=True)
    assert r.returncode == 2 and "Traceback" not in r.stderr


def test_tiny_design_prints_its_digits(tmp_path, capsys):
    """A micrometre design keeps about seven significant digits (was R0 = 0.000000 mm)."""
    from cams.cli import main
    from cams.io.designfile import load_design
    from cams.solve import solve
    from tests.conftest import EXAMPLES

    text = (EXAMPLES / "rocker_force.toml").read_text(encoding="utf-8")
    text = text.replace("arm = 125.0", "arm = 1.25e-6").replace("roller_radius = 10.0", "roller_radius = 1e-7")
    path = tmp_path / "tiny.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["solve", str(path)]) == 0
    out = capsys.readouterr().out
    R0 = solve(load_design(path)).R0
    shown = float(out.split("R0      = ")[1].split()[0])
    assert shown == pytest.approx(R0, rel=1e-5) and R0 < 1e-6


def test_unbuildable_minimum_fails_with_exit_1(tmp_path, capsys):
    """The pressure angle's minimum R0 below the roller radius (``constraints = "pressure_angle"``) is reported
    (it is the answer asked for) but the command fails: no cam to make. Sized to the part (the default), the roller
    governs and the cam passes."""
    path = tmp_path / "nodwell.toml"
    text = ('[follower]\nkind = "rocker"\narm = 125.0\nswing = 15.0\nroller_radius = 10.0\n'
            '[[motion]]\nphase = "rise"\nlaw = "cycloidal"\nangle = 180\n'
            '[[motion]]\nphase = "return"\nlaw = "cycloidal"\nangle = 180\n'
            '[limits]\npressure_angle = 45\n')
    path.write_text(text + '[solve]\nconstraints = "pressure_angle"\n', encoding="utf-8")
    assert main(["solve", str(path), "--json"]) == 1
    rep = json.loads(capsys.readouterr().out)
    assert rep["R0"] < 10.0 and rep["verified"] and rep["buildable"] is False and rep["governs"] == "pressure_angle"
    assert any(n.startswith("not buildable") for n in rep["notes"])
    # sized to the part: the roller governs, buildable
    path.write_text(text, encoding="utf-8")
    assert main(["solve", str(path), "--json"]) == 0
    part = json.loads(capsys.readouterr().out)
    assert part["buildable"] is True and part["governs"] == "undercut" and part["R0"] > 10.0
    assert part["pressure_angle_R0"] == rep["R0"]
    # with a floor above the roller it is buildable and passes, the floor governs
    path.write_text(text + "min_base_radius = 20.0\n", encoding="utf-8")
    assert main(["solve", str(path), "--json"]) == 0
    floor = json.loads(capsys.readouterr().out)
    assert floor["buildable"] is True and floor["governs"] == "min_base_radius" and floor["R0"] == 20.0
