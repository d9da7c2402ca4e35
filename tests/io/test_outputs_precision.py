"""Exported numbers keep the digits of the design's scale; a chord tolerance too coarse for the cam is refused.

Reference: geometric similarity. The README's rocker scaled by 1e-6 (every length times 1e-6, the tolerance
too) is the same cam: its exported coordinates times 1e6 must equal the full-size ones to many digits.
"""

import json
import re

import numpy as np
import pytest

from cams.cli import main
from tests.conftest import EXAMPLES

ROCKER = (EXAMPLES / "rocker_force.toml").read_text()


def _scaled(tmp_path, k: float):
    text = (ROCKER.replace("arm = 125.0", f"arm = {125.0 * k!r}")
            .replace("roller_radius = 10.0", f"roller_radius = {10.0 * k!r}"))
    assert k == 1.0 or text != ROCKER
    p = tmp_path / f"rocker_{k:g}.toml"
    p.write_text(text)
    return p


def _csv(path) -> np.ndarray:
    return np.loadtxt(path, delimiter=",", skiprows=1)


@pytest.mark.parametrize("k", [1e-6, 1e4])
def test_csv_keeps_the_digits_of_a_micrometre_or_a_metre_cam(tmp_path, capsys, k):
    full, small = tmp_path / "full.csv", tmp_path / "small.csv"
    assert main(["profile", str(_scaled(tmp_path, 1.0)), "--csv", str(full), "--tolerance", "0.001"]) == 0
    assert main(["profile", str(_scaled(tmp_path, k)), "--csv", str(small), "--tolerance", repr(0.001 * k)]) == 0
    capsys.readouterr()
    a, b = _csv(full), _csv(small)
    assert a.shape == b.shape
    assert np.array_equal(a[:, 0], b[:, 0])  # the same cam angles
    size = np.max(np.abs(a[:, 1:]))
    # ten significant digits of the cam's size at least (fixed 9 decimals kept three at 1e-6 mm)
    assert np.max(np.abs(b[:, 1:] / k - a[:, 1:])) < 1e-10 * size


def test_svg_of_a_micrometre_cam_has_a_view_box(tmp_path, capsys):
    svg, ref = tmp_path / "small.svg", tmp_path / "full.svg"
    assert main(["profile", str(_scaled(tmp_path, 1e-6)), "--svg", str(svg), "--tolerance", "1e-9"]) == 0
    assert main(["profile", str(_scaled(tmp_path, 1.0)), "--svg", str(ref), "--tolerance", "1e-3"]) == 0
    capsys.readouterr()
    text = svg.read_text()
    box = [float(x) for x in re.search(r'viewBox="([^"]+)"', text).group(1).split()]
    full = [float(x) for x in re.search(r'viewBox="([^"]+)"', ref.read_text()).group(1).split()]
    assert np.allclose(np.array(box) * 1e6, full, rtol=1e-9)
    first = re.search(r'<g id="PROFILE"[^>]*><path d="M([^ ]+) ', text).group(1)
    x, y = (float(v) for v in first.split(","))
    assert np.hypot(x, y) > 1e-6  # a point of the profile, not 0.000000


def test_default_tolerance_follows_a_micrometre_cam(tmp_path, capsys):
    """Without a tolerance a cam 20 micrometres across is sampled for its size (0.1 % of R0), not at 1 micrometre."""
    rc, rep = _json(capsys, "profile", _scaled(tmp_path, 1e-6))
    assert rc == 0 and rep["tolerance"] == pytest.approx(1e-3 * rep["R0"], rel=1e-12) and rep["points"] > 100


def _json(capsys, *argv):
    rc = main([*map(str, argv), "--json"])
    return rc, json.loads(capsys.readouterr().out)


def _smallest_radius(tmp_path, capsys, design) -> float:
    """The working profile's least distance from the centre, from a finely sampled export."""
    fine = tmp_path / "fine.csv"
    assert main(["profile", str(design), "--csv", str(fine), "--tolerance", "1e-5"]) == 0
    capsys.readouterr()
    d = _csv(fine)
    work = d[:, 3:5] if d.shape[1] >= 5 else d[:, 1:3]
    return float(np.hypot(work[:, 0], work[:, 1]).min())


def test_tolerance_above_five_percent_of_the_smallest_radius_is_refused(tmp_path, capsys):
    design = EXAMPLES / "rocker_force.toml"
    cap = 0.05 * _smallest_radius(tmp_path, capsys, design)  # 5 % of 3.24 mm
    out = tmp_path / "c.csv"
    rc = main(["profile", str(design), "--csv", str(out), "--tolerance", "1000"])
    err = capsys.readouterr().err
    assert rc == 2 and not out.exists() and err.count("\n") == 1
    assert err.startswith("cams profile: error: --tolerance: chord tolerance 1000 mm")
    largest = float(re.search(r"the largest accepted is ([0-9.e+-]+) mm", err).group(1))
    assert largest == pytest.approx(cap, rel=1e-4)
    assert main(["profile", str(design), "--csv", str(out), "--tolerance", repr(1.01 * cap)]) == 2
    assert main(["profile", str(design), "--csv", str(out), "--tolerance", repr(0.99 * cap)]) == 0
    capsys.readouterr()
    # the file's key, named as such, in every command that samples the profile
    f = tmp_path / "coarse.toml"
    f.write_text(design.read_text().replace("[solve]", "[profile]\ntolerance = 1000.0\n[solve]"))
    for cmd in (["check", str(f)], ["profile", str(f), "--csv", str(out)], ["solve", str(f)]):
        rc = main(cmd)
        err = capsys.readouterr().err
        assert rc == 2 and f"cams {cmd[0]}: error: profile.tolerance: chord tolerance 1000 mm" in err


def test_flat_face_tolerance_is_capped_too(tmp_path, capsys):
    design = EXAMPLES / "translating_flat.toml"
    cap = 0.05 * _smallest_radius(tmp_path, capsys, design)
    rc = main(["profile", str(design), "--csv", str(tmp_path / "f.csv"), "--tolerance", repr(1.01 * cap)])
    err = capsys.readouterr().err
    assert rc == 2 and err.startswith("cams profile: error: --tolerance: ")
    largest = float(re.search(r"the largest accepted is ([0-9.e+-]+) mm", err).group(1))
    assert largest == pytest.approx(cap, rel=1e-4)


def test_profile_summary_prints_the_digits_of_a_micrometre_cam(tmp_path, capsys):
    f = _scaled(tmp_path, 1e-6)
    rc, rep = _json(capsys, "profile", f)
    assert main(["profile", str(f)]) == 0
    out = capsys.readouterr().out
    for key, label in (("R0", "R0 = "), ("smallest_cam_radius", "cam's smallest radius "), ("bore_radius", "bore radius ")):
        printed = float(re.search(re.escape(label) + r"([0-9.e+-]+) mm", out).group(1))
        assert printed == pytest.approx(rep[key], rel=1e-6), key
