"""``cams laws --json`` prints the characteristic table of laws.characteristics.law_table()."""

from __future__ import annotations

import json
import math

from cams.cli import main
from laws.registry import LAWS


def test_laws_json(capsys):
    assert main(["laws", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert [r["name"] for r in rows] == list(LAWS)
    assert all(set(r) == {"name", "Cv", "Ca", "Cj"} for r in rows)
    cyc = next(r for r in rows if r["name"] == "cycloidal")
    # Norton, Cam Design and Manufacturing Handbook, ch. 3: cycloidal Cv 2, Ca 2 pi, Cj 4 pi^2
    assert math.isclose(cyc["Cv"], 2.0, rel_tol=1e-9)
    assert math.isclose(cyc["Ca"], 2 * math.pi, rel_tol=1e-9)
    assert math.isclose(cyc["Cj"], 4 * math.pi**2, rel_tol=1e-9)
    harmonic = next(r for r in rows if r["name"] == "harmonic")
    assert harmonic["Cj"] is None  # infinite jerk against a dwell is null in JSON


def test_laws_table_text(capsys):
    assert main(["laws"]) == 0
    out = capsys.readouterr().out
    assert "modified_cycloid" in out and "inf" in out
