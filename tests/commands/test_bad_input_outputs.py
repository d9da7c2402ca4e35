"""An output named as another kind of file than the one written is refused: one line naming the option, exit 2,
nothing written (in process: tests/inprocess.py). ``cams profile --svg cam.png`` wrote SVG into a ``.png`` (an
image viewer then calls it broken), ``cams sweep --out s.png`` a CSV, ``cams new --out d.csv`` and ``cams solve
--save-design d.json`` TOML. A name of no known kind (``cam.points``) stays the user's choice."""

from __future__ import annotations

import os

import pytest

from tests.conftest import EXAMPLES
from tests.inprocess import cams_cli

ROCKER = EXAMPLES / "rocker_force.toml"
DESIGNED = EXAMPLES / "translating_designed_rise.toml"


@pytest.mark.parametrize(
    ("argv", "option", "name", "wanted"),
    [
        (["profile", ROCKER, "--svg"], "--svg", "cam.png", ".svg"),
        (["profile", ROCKER, "--dxf"], "--dxf", "cam.svg", ".dxf"),
        (["profile", ROCKER, "--csv"], "--csv", "cam.dxf", ".csv"),
        (["profile", ROCKER, "--table"], "--table", "lift.json", ".csv"),
        (["sweep", ROCKER, "--vary", "follower.arm=100,120", "--quiet", "--out"], "--out", "s.png", ".csv"),
        (["new", "rocker", "--out"], "--out", "d.csv", ".toml"),
        (["solve", DESIGNED, "--save-design"], "--save-design", "d.json", ".toml"),
    ],
)
def test_an_output_named_as_another_kind_is_refused(tmp_path, argv, option, name, wanted):
    r = cams_cli(*argv, tmp_path / name)
    assert (r.returncode, r.stdout) == (2, ""), r.stderr
    assert r.stderr.count("\n") == 1 and f" {option}: " in r.stderr, r.stderr
    assert f"not a {name[name.rindex('.') :]} file: give it a {wanted} name" in r.stderr
    assert os.listdir(tmp_path) == []


def test_a_name_of_no_known_kind_is_written(tmp_path):
    """``--csv cam.points`` writes the same CSV as ``--csv cam.csv``."""
    out, ref = tmp_path / "cam.points", tmp_path / "cam.csv"
    assert cams_cli("profile", ROCKER, "--csv", out).returncode == 0
    assert cams_cli("profile", ROCKER, "--csv", ref).returncode == 0
    assert out.read_bytes() == ref.read_bytes() and out.read_text(encoding="utf-8").startswith("phi_deg,")
