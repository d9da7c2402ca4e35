"""Synthesis from course data gives the asked stroke and time ratio, or a one-line error with the allowed range."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from cams.cli import main
from cams.machine.linkage import analyse, dead_positions
from cams.machine.linkage.machines import CrankSlider, SlottedLeverPump, SlottingMachine
from cams.machine.linkage.synthesis import (
    MAX_TIME_RATIO,
    slotted_lever_synthesis,
    slotting_rod_ratio_min,
    slotting_time_ratio_limit,
)
from laws.errors import InputError

ROOT = Path(__file__).resolve().parents[3]
SLOTTING = ROOT / "examples" / "machines" / "slotting_machine.toml"
PUMP = ROOT / "examples" / "machines" / "pump.toml"


def _by_lengths(K, H, L, rho, **kw):
    """The slotting machine of the synthesis, built from its lengths (no check of the course data)."""
    s = slotted_lever_synthesis(K, H, L)
    bar = s.bar
    return SlottingMachine(crank=s.crank, centre_distance=L, bar=bar, rod=rho * bar,
                           guide_x=-L - s.guide_distance, **kw)


@pytest.mark.parametrize("rho", [0.3, 0.5, 1.0, 2.0, 10.0])
def test_slotting_limit_is_where_the_tool_gets_four_dead_positions(rho):
    kmax = slotting_time_ratio_limit(rho)
    assert slotting_rod_ratio_min(kmax) == pytest.approx(rho, rel=1e-9)
    for f, n in ((0.999, 2), (1.001, 4)):
        m = _by_lengths(kmax * f, 100.0, 150.0, rho)
        assert len(dead_positions(m, samples=200_000)) == n, (rho, f)


@pytest.mark.parametrize("rho", [0.5, 1.0, 2.0])
def test_slotting_course_data_below_the_limit_are_met(rho):
    K = 0.999 * slotting_time_ratio_limit(rho)
    for kw in ({}, {"tool_side": -1, "crank_sense": -1}):
        rep = analyse(SlottingMachine.from_course(K, 100.0, 150.0, rho, **kw))
        assert rep.time_ratio == pytest.approx(K, rel=1e-9) and rep.stroke == pytest.approx(100.0, rel=1e-9)


@pytest.mark.parametrize("K", [8.25, 10.0, 500.0, 1e6])
def test_slotting_time_ratio_beyond_the_limit(K):
    with pytest.raises(InputError) as e:
        SlottingMachine.from_course(K, 100.0, 150.0, 1.0)
    assert e.value.field == "linkage.time_ratio"
    assert "allows 1 < K < 8.24441" in str(e.value) and "np." not in str(e.value)


@pytest.mark.parametrize("K", [300.0, 500.0, 700.0, 999.0, 1000.0])
def test_pump_with_a_large_time_ratio_keeps_it(K):
    """The return stroke is shorter than the analysis grid's step: its dead positions must not be lost."""
    rep = analyse(SlottedLeverPump.from_course(K, 250.0, 525.0))
    assert rep.time_ratio == pytest.approx(K, rel=1e-9) and rep.stroke == pytest.approx(250.0, rel=1e-9)


def test_pump_time_ratio_too_large():
    with pytest.raises(InputError) as e:
        SlottedLeverPump.from_course(1e6, 250.0, 525.0)
    assert e.value.field == "linkage.time_ratio" and f"1 < K <= {MAX_TIME_RATIO:g}" in str(e.value)


@pytest.mark.parametrize("H, rod, e", [(100.0, 300.0, 0.0), (100.0, 300.0, 250.0), (599.99, 300.0, 0.0), (550.0, 300.0, 40.0)])
def test_crank_slider_stroke_is_met(H, rod, e):
    assert analyse(CrankSlider.from_stroke(H, rod, offset=e)).stroke == pytest.approx(H, rel=1e-9)


def test_crank_slider_stroke_too_small_for_the_rod():
    with pytest.raises(InputError) as e:
        CrankSlider.from_stroke(1e-9, 300.0)
    assert e.value.field == "linkage.stroke" and "1e-6 x rod" in str(e.value)


@pytest.mark.parametrize("path, K", [(SLOTTING, 10), (SLOTTING, 500), (SLOTTING, 1e6), (PUMP, 1e6)])
def test_machine_file_time_ratio_out_of_range(tmp_path, capsys, path, K):
    text = path.read_text(encoding="utf-8")
    d = tomllib.loads(text)
    assert d["linkage"]["time_ratio"] == 2.0
    f = tmp_path / "m.toml"
    f.write_text(text.replace("time_ratio = 2.0", f"time_ratio = {K!r}", 1), encoding="utf-8")
    assert main(["machine", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "linkage.time_ratio" in err and "allows 1 < K" in err, err


def test_machine_file_large_pump_time_ratio():
    from cams.machine.machinefile import machine_from_dict

    d = tomllib.loads(PUMP.read_text(encoding="utf-8"))
    d["linkage"]["time_ratio"] = 600.0
    rep = analyse(machine_from_dict(d).linkage)
    assert rep.time_ratio == pytest.approx(600.0, rel=1e-9) and rep.stroke == pytest.approx(250.0, rel=1e-9)
