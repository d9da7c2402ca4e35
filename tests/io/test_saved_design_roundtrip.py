"""``cams solve --save-design``: the saved design solves back to the same cam, for every objective a follower allows.

Issue 28, item 3: with ``objective = "L"`` the saved file dropped the objective and sized another cam (the
designed laws' least R0: L 0.11964 mm instead of 0.11495 mm). Each case designs laws (a small space: degree 5,
3 spans) through the command line in-process, saves them, solves the saved file with the same command and
compares the two reports: the cam (R0, L or offset, centre) and the verdicts are the same numbers, bit for bit
(the saved file holds the laws' coefficients and the centre exactly, ``repr`` of each float), the laws the same.
"""

from __future__ import annotations

import json

import pytest

from cams.cli import main
from cams.io.designfile import load_design
from cams.io.document import read_toml
from tests.conftest import EXAMPLES
from tests.stress.helpers import to_toml

SPACE = {"degree": 5, "spans": 3, "continuity": 2, "max_Ca": "poly4567", "max_Cj": "modified_trapezoid"}

#: example, [optimize] objectives the follower allows (docs/files.md, [optimize] objective), extra [optimize] keys
CASES = [
    ("rocker_force.toml", ["R0", "L", "pressure_angle", "Ca", "Cj", "jerk_squared", "snap_squared"], {}),
    ("rocker_form.toml", ["R0", "L", "pressure_angle", "Ca"], {}),
    ("translating_force.toml", ["R0", "pressure_angle", "Ca", "Cj", "jerk_squared", "snap_squared"], {}),
    ("translating_flat.toml", ["R0", "Ca", "Cj", "jerk_squared", "snap_squared"], {}),
    ("rocker_flat.toml", ["R0", "Ca", "Cj", "jerk_squared", "snap_squared"], {}),
]


def _solve(capsys, path, *more) -> tuple[int, dict]:
    code = main(["solve", str(path), "--json", *map(str, more)])
    out, err = capsys.readouterr()
    assert "Traceback" not in err, err
    return code, json.loads(out)


def _design_file(tmp_path, example: str, objective: str) -> object:
    d = read_toml(EXAMPLES / example)
    d.get("solve", {}).pop("objective", None)
    snap = {"degree": 7, "continuity": 3} if objective == "snap_squared" else {}  # its peak needs C3
    d["optimize"] = {**SPACE, **snap, "objective": objective}
    p = tmp_path / "design.toml"
    p.write_text(to_toml(d), encoding="utf-8")
    return p


def _same_cam(a: dict, b: dict) -> None:
    for k in ("R0", "L", "offset", "centre", "verified", "buildable", "failures", "max_pressure_angle"):
        assert a.get(k) == b.get(k), (k, a.get(k), b.get(k))


@pytest.mark.parametrize(("example", "objective"), [(e, o) for e, objs, _ in CASES for o in objs])
def test_the_saved_design_solves_back_to_the_same_cam(tmp_path, capsys, example, objective):
    path = _design_file(tmp_path, example, objective)
    saved = tmp_path / "saved.toml"
    code, first = _solve(capsys, path, "--save-design", saved)
    assert code == 0, first.get("failures")
    assert first["optimize"]["objective"] == objective and saved.exists()
    code, again = _solve(capsys, saved)
    assert code == 0, again.get("failures")
    assert "optimize" not in again
    _same_cam(first, again)
    designed = load_design(saved)
    for i in first["optimize"]["free"]:
        law = designed.program.law_of(i)
        assert law.name.startswith("designed spline") or law.name == load_design(path).program.law_of(i).name


def test_the_issues_least_L_solves_back(tmp_path, capsys):
    """The reproducer (a rocker of arm 0.13 mm, form closure, objective L): L 0.1149545 mm both times (was 0.11964
    mm, the designed laws' least R0's cam, which fails its profile checks)."""
    d = read_toml(EXAMPLES.parent / "tests" / "data" / "savedesign_objective_L.toml")
    p = tmp_path / "design.toml"
    p.write_text(to_toml(d), encoding="utf-8")
    saved = tmp_path / "saved.toml"
    code, first = _solve(capsys, p, "--save-design", saved)
    assert code == 0 and first["L"] == pytest.approx(0.1149545, abs=1e-7) and first["mode"] == "min_L"
    code, again = _solve(capsys, saved)
    assert code == 0 and again["mode"] == "min_L"
    _same_cam(first, again)
