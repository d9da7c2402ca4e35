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
