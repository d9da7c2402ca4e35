"""``cams explore`` on the command line: the page written whole, its exit codes and one-line errors."""

from __future__ import annotations

import json
import re

import pytest

from cams.cli import main
from cams.io.tomlwrite import dumps
from tests.conftest import EXAMPLES, rocker_dict


def _data(path) -> dict:
    m = re.search(r"const CAMS_DATA = (.*);\n</script>", path.read_text(encoding="utf-8"))
    assert m is not None
    return json.loads(m.group(1))


def _file(tmp_path, name="design.toml", **over):
    d = rocker_dict(**over)
    p = tmp_path / name
    p.write_text(dumps(d), encoding="utf-8")
    return p


def test_a_usable_cam_writes_the_page_and_exits_0(tmp_path, capsys):
    out = tmp_path / "page.html"
    assert main(["explore", str(EXAMPLES / "rocker_force.toml"), "--out", str(out)]) == 0
    said = capsys.readouterr()
    assert said.out.startswith(f"wrote {out}") and said.err == ""
    data = _data(out)
    assert data["diagnosis"] is None and data["face"]["mode"] == "centre"
    assert [f.name for f in tmp_path.iterdir()] == ["page.html"]  # no temporary left behind


@pytest.mark.parametrize("where", ["missing_folder", "a_folder"])
def test_an_unwritable_page_is_one_line_and_exit_2(tmp_path, capsys, where):
    out = tmp_path / "no" / "page.html" if where == "missing_folder" else tmp_path
    assert main(["explore", str(EXAMPLES / "rocker_force.toml"), "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("cams explore: error: --out: cannot write")
    assert "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


def test_bad_design_file_and_missing_out_exit_2(tmp_path, capsys):
    assert main(["explore", str(tmp_path / "nothing.toml"), "--out", str(tmp_path / "p.html")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "nothing.toml" in err
    with pytest.raises(SystemExit) as e:
        main(["explore", str(EXAMPLES / "rocker_force.toml")])
    assert e.value.code == 2
    assert "--out" in capsys.readouterr().err
    bad = _file(tmp_path, limits={"pressure_angle": 95})
    assert main(["explore", str(bad), "--out", str(tmp_path / "p.html")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "limits.pressure_angle" in err
    assert not (tmp_path / "p.html").exists()


def test_no_feasible_zone_still_writes_the_page_saying_why(tmp_path, capsys):
    """The page opens with the diagnosis cams solve gives; the command exits 1 (no usable cam)."""
    f = _file(tmp_path, limits={"pressure_angle": 7})
    assert main(["solve", str(f)]) == 2
    solve_err = capsys.readouterr().err.strip()
    out = tmp_path / "page.html"
    assert main(["explore", str(f), "--out", str(out)]) == 1
    said = capsys.readouterr().out
    data = _data(out)
    assert solve_err == f"cams solve: error: {data['diagnosis']}"
    assert "no cam centre satisfies 7 deg on the rise" in data["diagnosis"] and data["diagnosis"] in said
    assert data["face"]["start"] is None and data["phases"][0]["kind"] == "rise"


def test_a_chosen_cam_that_fails_exits_1_and_starts_there(tmp_path, capsys):
    """[cam] centre outside the zone: the page starts at that centre; the exit code is cams.assess's."""
    f = _file(tmp_path, cam={"rotation": "ccw", "centre": [60.0, 80.0]})
    out = tmp_path / "page.html"
    assert main(["explore", str(f), "--out", str(out)]) == 1
    assert "FAIL" in capsys.readouterr().out
    assert _data(out)["face"]["start"]["centre"] == [60.0, 80.0]


def test_the_page_to_standard_output_says_so_on_stderr():
    """``--out -``: the page is the standard output, whole; the line that says so goes to standard error."""
    import subprocess
    import sys

    run = subprocess.run(
        [sys.executable, "-m", "cams.cli", "explore", str(EXAMPLES / "translating_force.toml"), "--out", "-"],
        capture_output=True,
        text=True,
        timeout=300,
        cwd=EXAMPLES.parent,
    )
    assert run.returncode == 0, run.stderr
    assert run.stdout.startswith("<!doctype html>") and run.stdout.rstrip().endswith("</html>")
    assert run.stderr.startswith("wrote -")


@pytest.mark.parametrize("name, said", [("design.toml", "it is the input file FILE"), ("page.png", "give a .html")])
def test_out_is_neither_the_design_file_nor_another_kind(tmp_path, capsys, name, said):
    """``--out`` equal to the design file replaced the design with the page; another extension hid HTML."""
    f = tmp_path / "design.toml"
    f.write_text((EXAMPLES / "rocker_force.toml").read_text(encoding="utf-8"), encoding="utf-8")
    before = f.read_text(encoding="utf-8")
    assert main(["explore", str(f), "--out", str(tmp_path / name)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("cams explore: error: --out: ") and said in err
    assert f.read_text(encoding="utf-8") == before and sorted(p.name for p in tmp_path.iterdir()) == ["design.toml"]
