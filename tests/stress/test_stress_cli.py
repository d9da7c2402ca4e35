"""``cams solve`` on hard-corner design files: exit 2 and one line on stderr when
infeasible; strict JSON (no NaN/Infinity) when feasible."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from cams.cli import main

from .helpers import design_dict, time_limit, to_toml


def _strict_json(text: str) -> dict:
    def no(name):
        raise ValueError(f"JSON holds {name}")

    return json.loads(text, parse_constant=no)


INFEASIBLE = {
    "empty_zone_form": (design_dict("rocker", follower={"swing": 170.0},
                                    limits={"pressure_angle": 10.0, "closure": "form"}), "limits.pressure_angle"),
    "limit_0.1_rocker": (design_dict("rocker", limits={"pressure_angle": 0.1}), "limits.pressure_angle"),
    "swing_179.9": (design_dict("rocker", follower={"swing": 179.9}, limits={"pressure_angle": 89.0}),
                    "limits.pressure_angle"),
    "L_far_below": (design_dict("rocker", limits={"centre_distance": 0.1}), "limits.centre_distance"),
    "limit_89.99_vanishing_R0": (design_dict("rocker", limits={"pressure_angle": 89.99}), "limits.pressure_angle"),
    "limit_90": (design_dict("rocker", limits={"pressure_angle": 90.0}), "limits.pressure_angle"),
    "swing_180": (design_dict("rocker", follower={"swing": 180.0}), "follower.swing"),
}

FEASIBLE = {
    "limit_0.1_translating": design_dict("translating", limits={"pressure_angle": 0.1}),
    "limit_89_rocker_form": design_dict("rocker", limits={"pressure_angle": 89.0, "closure": "form"}),
    "swing_0.01": design_dict("rocker", follower={"swing": 0.01}, limits={"pressure_angle": 80.0}),
    "swing_170_limit_89": design_dict("rocker", follower={"swing": 170.0}, limits={"pressure_angle": 89.0}),
    "stroke_1e-3": design_dict("translating", follower={"stroke": 1e-3, "roller_radius": 0.0}),
    "arm_10m": design_dict("rocker", follower={"arm": 10_000.0, "roller_radius": 800.0}),
    "no_dwell": design_dict("translating", motion=[{"phase": "rise", "law": "cycloidal", "angle": 180},
                                                   {"phase": "return", "law": "poly345", "angle": 180}],
                            limits={"closure": "form"}),
    "phases_1deg": design_dict("rocker", motion=[{"phase": "rise", "law": "cycloidal", "angle": 1},
                                                 {"phase": "dwell", "angle": 1},
                                                 {"phase": "return", "law": "cycloidal", "angle": 1},
                                                 {"phase": "dwell"}]),
    "huge_floor": design_dict("rocker", limits={"min_base_radius": 132.4}),
    "L_1000x": design_dict("rocker", limits={"centre_distance": 110_485.4}),
}



def _run(capsys, tmp_path, d, *extra):
    p = tmp_path / "design.toml"
    p.write_text(to_toml(d), encoding="utf-8")
    with time_limit(what="cams solve"):
        rc = main(["solve", str(p), *extra])
    out = capsys.readouterr()
    return rc, out.out, out.err


@pytest.mark.parametrize("name", list(INFEASIBLE))
def test_infeasible_file_exit_2_one_line(name, capsys, tmp_path):
    d, field = INFEASIBLE[name]
    rc, out, err = _run(capsys, tmp_path, d, "--json")
    assert rc == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith(f"cams solve: error: {field}:"), lines[0]


@pytest.mark.parametrize("name", list(FEASIBLE))
def test_feasible_file_strict_json(name, capsys, tmp_path):
    rc, out, err = _run(capsys, tmp_path, FEASIBLE[name], "--json")
    rep = _strict_json(out)
    # a minimum below the roller radius is the right answer but no cam to make: exit 1 (a failed check);
    # so is an undercut or self-crossing profile (cams.assess)
    assert rc == (0 if rep["buildable"] else 1), err
    no_profile = not rep["R0"] > FEASIBLE[name]["follower"].get("roller_radius", 0.0)
    assert no_profile == any(f.startswith("no working profile") for f in rep["failures"])
    assert rep["buildable"] == (not rep["failures"])
    if no_profile:
        assert rep["buildable"] is False
    assert rep["verified"] is True and rep["R0"] > 0
    assert rep["max_pressure_angle"]["rise"] <= rep["limits"]["rise"] + 1e-6


@pytest.mark.parametrize("method", ["convex", "exhaustive"])
def test_sampled_methods_strict_json(method, capsys, tmp_path):
    d = design_dict("rocker", follower={"swing": 0.5}, limits={"pressure_angle": 80.0}, solve={"samples": 24})
    rc, out, _ = _run(capsys, tmp_path, d, "--json", "--method", method)
    assert rc in (0, 1)  # a sampled answer may exceed the limit slightly between samples
    rep = _strict_json(out)
    assert rep["method"] == method and rep["samples"] == 24


def test_limit_89_9_strict_json(capsys, tmp_path):
    """Regression (fixed in f69e9ce): exit 1 and '"rise": NaN' in the JSON."""
    rc, out, _ = _run(capsys, tmp_path, design_dict("rocker", limits={"pressure_angle": 89.9}), "--json")
    rep = _strict_json(out)
    assert rc == (0 if rep["buildable"] else 1) and rep["verified"] is True


def test_real_command_line(tmp_path):
    """One real process each way (entry point, stderr, exit codes)."""
    bad = tmp_path / "empty.toml"
    bad.write_text(to_toml(INFEASIBLE["empty_zone_form"][0]), encoding="utf-8")
    good = tmp_path / "tiny.toml"
    good.write_text(to_toml(FEASIBLE["stroke_1e-3"]), encoding="utf-8")
    code = "import sys; from cams.cli import main; sys.exit(main(sys.argv[1:]))"
    r = subprocess.run([sys.executable, "-c", code, "solve", str(bad)], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and r.stdout == ""
    assert len(r.stderr.strip().splitlines()) == 1 and "limits.pressure_angle" in r.stderr
    r = subprocess.run([sys.executable, "-c", code, "solve", str(good), "--json"], capture_output=True, text=True,
                       timeout=60)
    assert r.returncode == 0, r.stderr
    assert _strict_json(r.stdout)["verified"] is True
