"""One entry point: ``cams.solve.solve(load_design(f))`` gives what ``cams solve f --json`` prints.

The API honours everything the file says (``[solve] objective``, method, samples) and takes flat-faced
designs (their convexity sizing), so for every example the command line's JSON and the API's ``to_dict`` agree
number for number (the run time aside; the command line adds the forces of a ``[dynamics]`` table).
"""

import json

import pytest

from cams.cli import main
from cams.io.designfile import design_from_dict, load_design
from cams.io.document import read_toml
from cams.solve import solve
from tests.conftest import EXAMPLES

FILES = sorted(p.name for p in EXAMPLES.glob("*.toml"))


def _same(cli: dict, api: dict) -> None:
    """Every key of the API's report equals the command line's (run time aside; notes as a prefix)."""
    for k, v in api.items():
        if k == "seconds":
            continue
        if k == "notes":
            assert cli[k][:len(v)] == v
            continue
        if k == "optimize":  # the motion design's report: its run time aside too
            _same(cli[k], v)
            continue
        assert cli[k] == v, k


@pytest.mark.parametrize("name", FILES)
def test_cli_json_equals_api(capsys, name):
    assert any(n.endswith("flat.toml") for n in FILES)
    code = main(["solve", str(EXAMPLES / name), "--json"])
    cli = json.loads(capsys.readouterr().out)
    api = json.loads(json.dumps(solve(load_design(EXAMPLES / name)).to_dict()))
    _same(cli, api)
    assert code in (0, 1)


def _rocker_force_with(**solve_table) -> dict:
    d = read_toml(EXAMPLES / "rocker_force.toml")
    d.setdefault("solve", {}).update(solve_table)
    return d


def test_objective_of_the_file_is_honoured():
    d = _rocker_force_with(objective="L")
    res = solve(design_from_dict(d))
    assert res.mode == "min_L"
    # the least L is the exact nearest admissible centre to the pivot, found independently of the objective
    least_L = solve(design_from_dict(read_toml(EXAMPLES / "rocker_force.toml")), objective="L").L
    assert res.L == pytest.approx(least_L, rel=1e-12)
    assert res.L < solve(design_from_dict(read_toml(EXAMPLES / "rocker_force.toml"))).L


def test_method_and_samples_of_the_file_are_honoured():
    res = solve(design_from_dict(_rocker_force_with(method="convex", samples=90)))
    assert res.method == "convex" and res.samples == 90


@pytest.mark.parametrize("name", ["translating_flat.toml", "rocker_flat.toml"])
def test_flat_face_through_the_one_entry_point(name):
    from optimize.flat import size_flat_face

    design = load_design(EXAMPLES / name)
    res = solve(design)
    ref = size_flat_face(design)
    assert res.R0 == ref.R0 and res.verified == ref.verified
    assert res.to_dict()["R0_source"] == "convexity"


def test_flat_face_refuses_a_method():
    from laws.errors import InputError

    with pytest.raises(InputError, match="method"):
        solve(load_design(EXAMPLES / "translating_flat.toml"), method="convex")


@pytest.mark.parametrize("name", FILES)
def test_check_design_api_equals_cams_check_json(capsys, name):
    """``cams.solve.check_design(load_design(f))`` is what ``cams check f --json`` prints, flat faces included.

    The command adds the one assessment every command applies (``verified``, ``buildable``, ``failures``, from
    :class:`cams.cam.Cam`) and its ``passed`` is the checks' and the assessment's together.
    """
    from cams.cam import Cam
    from cams.solve import check_design

    code = main(["check", str(EXAMPLES / name), "--json"])
    cli = json.loads(capsys.readouterr().out)
    report = check_design(load_design(EXAMPLES / name))
    api = json.loads(json.dumps(report.to_dict()))
    a = Cam(load_design(EXAMPLES / name)).assessment
    assert {k: v for k, v in cli.items() if k in api and k != "passed"} == {k: v for k, v in api.items() if k != "passed"}
    assert set(cli) - set(api) == {"verified", "buildable", "failures"}  # "certified" only when false
    assert cli["verified"] == a.verified and cli["buildable"] == a.buildable
    assert cli["passed"] == (report.passed and a.usable)
    assert code == (0 if cli["passed"] else 1)


def test_a_sized_cam_that_fails_the_check_says_by_how_much():
    """The sampled methods can exceed the limit between samples: the note gives the excess an inversion finds."""
    import re

    from tests.facade.test_chosen_cam import _largest_rise_pressure_angle

    d = _rocker_force_with(method="exhaustive", samples=12)
    res = solve(design_from_dict(d))
    assert not res.verified
    note = next(n for n in res.notes if n.startswith("rise pressure angle"))
    m = re.match(r"rise pressure angle ([\d.]+) deg exceeds the limit 45.0000 deg by ([\d.]+) deg", note)
    ref = _largest_rise_pressure_angle(d, res.centre)[0]
    assert float(m.group(1)) == pytest.approx(ref, abs=2e-4) and float(m.group(2)) == pytest.approx(ref - 45, abs=2e-4)
