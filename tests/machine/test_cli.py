"""``cams machine``: text, JSON, plot and one-line errors."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from cams.cli import main

ROOT = Path(__file__).resolve().parents[2]
SLOTTING = ROOT / "examples" / "machines" / "slotting_machine.toml"
PUMP = ROOT / "examples" / "machines" / "pump.toml"


def test_json_report(capsys):
    assert main(["machine", str(SLOTTING), "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    assert {"linkage", "windows", "cam", "overlap", "timing", "analysis"} <= set(rep)
    assert rep["linkage"]["l_O2A"] == pytest.approx(75.0)
    assert rep["linkage"]["l_O3B"] == pytest.approx(100.0)
    assert rep["windows"]["cutting"][0] < rep["windows"]["cutting"][1]
    assert rep["overlap"] is False
    assert rep["cam"]["verified"] is True and rep["cam"]["R0"] > 0


def test_text_report(capsys):
    assert main(["machine", str(PUMP)]) == 0
    out = capsys.readouterr().out
    assert "swing theta = 60.0000 deg" in out and "gears 20/40" in out and "feeding overlaps cutting: no" in out


def test_plot(tmp_path, capsys):
    assert main(["machine", str(SLOTTING), "--plot", str(tmp_path)]) == 0
    png = tmp_path / "slotting_machine_cycle.png"
    assert png.exists() and png.stat().st_size > 1000


def test_bad_file_is_one_line(tmp_path, capsys):
    text = SLOTTING.read_text(encoding="utf-8").replace("time_ratio = 2.0", "time_ratio = 1.0")
    f = tmp_path / "bad.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["machine", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "linkage.time_ratio" in err and "K must be > 1" in err


def test_short_window_is_one_line(tmp_path, capsys):
    text = SLOTTING.read_text(encoding="utf-8").replace("angle = 60\n[[motion]]\nphase = \"dwell\"\nangle = 10", "angle = 175\n[[motion]]\nphase = \"dwell\"\nangle = 10", 1)
    assert "angle = 175" in text
    f = tmp_path / "short.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["machine", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "largest feasible rise angle is 168.2 deg" in err


def _pitch_convex_radius(points) -> float:
    """Smallest radius of the circle through three consecutive points turning the curve's way (a closed polygon)."""
    import numpy as np

    p0, p1, p2 = points, np.roll(points, -1, axis=0), np.roll(points, -2, axis=0)
    a, b, c = (np.linalg.norm(p1 - p0, axis=1), np.linalg.norm(p2 - p1, axis=1), np.linalg.norm(p2 - p0, axis=1))
    cross = (p1 - p0)[:, 0] * (p2 - p0)[:, 1] - (p1 - p0)[:, 1] * (p2 - p0)[:, 0]
    turn = np.sign(np.sum(cross))  # the pitch curve's own sense: convex stretches turn with it
    keep = (cross * turn > 0) & (a > 1e-6) & (b > 1e-6)
    return float(np.min(a[keep] * b[keep] * c[keep] / (2.0 * np.abs(cross[keep]))))


def test_an_undercut_feed_cam_fails_the_machine(tmp_path, capsys):
    # issue 12, item 9: one definition of a usable cam. A 39 mm roller on the slotting machine's feed cam
    # (R0 = 40.06 mm) is undercut; `cams check` refused it, `cams machine` exited 0 with it.
    import numpy as np

    from cams.machinefile import load_machine
    from cams.profile import build_profile

    text = SLOTTING.read_text(encoding="utf-8").replace("roller_radius = 15.0", "roller_radius = 39.0")
    path = tmp_path / "undercut.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["machine", str(path), "--json"]) == 1
    cam = json.loads(capsys.readouterr().out)["cam"]
    assert cam["verified"] is True and cam["R0"] > 39.0
    assert cam["buildable"] is False and any(f.startswith("undercut") for f in cam["failures"])
    # independent reference: the pitch curve turns tighter than the roller somewhere (three-point circles)
    spec = load_machine(path)
    prof = build_profile(spec.cam, np.array([cam["centre"]["x"], cam["centre"]["y"]]), tolerance=0.01)
    assert _pitch_convex_radius(np.asarray(prof.pitch)) < 39.0
    assert main(["machine", str(path)]) == 1
    out = capsys.readouterr().out
    assert "buildable: NO" in out and "undercut" in out
    assert main(["machine", str(SLOTTING)]) == 0
    assert "buildable: yes" in capsys.readouterr().out
