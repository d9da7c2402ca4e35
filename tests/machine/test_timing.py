"""Coupling of the feed cam to its machine: windows, timing, cycle diagram, the overlap check."""

from __future__ import annotations

import copy
import tomllib
from pathlib import Path

import numpy as np
import pytest

from cams.machine.design import design_machine
from cams.machine.linkage.machines import SlottingMachine
from cams.machine.machinefile import load_machine, machine_from_dict
from cams.machine.timing import CamTiming, CuttingZone, Drive, Timing, cycle_diagram, place_cam, windows
from laws.errors import InfeasibleError, InputError

ROOT = Path(__file__).resolve().parents[2]
SLOTTING = ROOT / "examples" / "machines" / "slotting_machine.toml"
PUMP = ROOT / "examples" / "machines" / "pump.toml"


@pytest.fixture(scope="module")
def slotting():
    spec = load_machine(SLOTTING)
    return spec, design_machine(spec)


def raw(path: Path) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


def tool_state(machine, win, c):
    """Tool travel from the working stroke's start and whether it moves in the working direction, at cycle angles c."""
    out = machine.output(win.frame_angle(np.asarray(c, dtype=float)))
    travel = np.abs(out.s - win.stroke.s_start)
    working = np.sign(out.ds * win.sense) == win.stroke.direction
    return travel, working


def test_windows_of_the_slotting_example(slotting):
    spec, res = slotting
    w = res.windows
    H = w.stroke.stroke
    assert H == pytest.approx(100.0, rel=1e-12)
    assert np.degrees(w.working_start) == pytest.approx(120.0, abs=1e-9)  # K = 2: return 120 deg, work 240 deg
    travel, working = tool_state(spec.linkage, w, [w.cut_start, w.cut_end])
    assert travel == pytest.approx([0.05 * H, 0.95 * H], rel=1e-9)
    assert working.all()
    a, b = w.out_of_work
    assert 0 <= a < 2 * np.pi and b - a == pytest.approx(2 * np.pi - (w.cut_end - w.cut_start))


def test_feed_rise_lies_wholly_in_the_out_of_work_window(slotting):
    """The example's rise: every crank angle of it, checked on the linkage's own motion, is out of the cut."""
    spec, res = slotting
    w, t = res.windows, res.timing
    assert len(t.rises) == 1
    r0, r1 = t.rises[0]
    assert np.degrees(r1 - r0) == pytest.approx(60.0, rel=1e-12)  # 60 deg of cam on the crank's shaft
    # inside the window, with the margin
    a, b = w.out_of_work
    rel0 = np.mod(r0 - a, 2 * np.pi)
    assert rel0 >= spec.timing.margin - 1e-9
    assert rel0 + (r1 - r0) <= (b - a) - spec.timing.margin + 1e-9
    # independent: at every angle of the rise the tool is returning or in its overruns
    c = np.linspace(r0, r1, 2001)
    travel, working = tool_state(spec.linkage, w, c)
    H = w.stroke.stroke
    cutting = working & (travel > 0.05 * H) & (travel < 0.95 * H)
    assert not cutting.any()
    # and the cam's program is in its rise there
    cam = t.ratio * (c[1:-1] - t.mount)
    assert np.all(spec.cam.program.phase_of(cam) == 0)
    assert res.overlap is False and res.ok
    assert res.solve.verified


def test_cam_design_follows_the_machine(slotting):
    spec, res = slotting
    assert spec.cam.cam_sense == spec.linkage.crank_sense  # same shaft
    assert spec.cam.rpm == pytest.approx(60.0)
    assert np.degrees(spec.cam.program.lift) == pytest.approx(15.0)
    d = res.to_dict()
    assert d["cam"]["verified"] and d["cam"]["max_pressure_angle"]["rise"] <= 40 + 1e-6
    assert d["notes"] == []


def test_diagram_data(slotting):
    _, res = slotting
    dg = res.diagram
    assert dg.tool.min() == pytest.approx(0.0, abs=1e-9) and dg.tool.max() == pytest.approx(100.0, rel=1e-6)
    assert np.degrees(dg.follower.max()) == pytest.approx(15.0, rel=1e-9)
    d = dg.to_dict(step_deg=5.0)
    assert len(d["crank_deg"]) == 73 and d["follower_unit"] == "deg"


def test_overlap_is_detected():
    """A cam mounted so that its rise falls in the cut is flagged."""
    spec = load_machine(SLOTTING)
    w = windows(spec.linkage, spec.cutting)
    mid = (w.cut_start + w.cut_end) / 2
    bad = CamTiming(mount=mid, mount_frame=0.0, rises=((mid, mid + np.pi / 3),), margins=(0.0, 0.0), largest_rise=0.0, period=(1, 1), ratio=1.0)
    dg = cycle_diagram(spec.linkage, w, spec.cutting, spec.cam.program, bad)
    assert dg.overlap


@pytest.mark.parametrize("placement", ["early", "late", "centre"])
def test_placements(placement):
    spec = load_machine(SLOTTING)
    w = windows(spec.linkage, spec.cutting)
    m = np.radians(5.0)
    t = place_cam(w, spec.cam.program, Drive.shaft(), Timing(margin=m, placement=placement))
    before, after = t.margins
    if placement == "early":
        assert before == pytest.approx(m, abs=1e-9)
    elif placement == "late":
        assert after == pytest.approx(m, abs=1e-9)
    else:
        assert before == pytest.approx(after, abs=1e-9)


def test_window_too_short_states_largest_rise():
    d = raw(SLOTTING)
    win = windows(load_machine(SLOTTING).linkage, CuttingZone(0.05, 0.05))
    span = np.degrees(win.out_of_work[1] - win.out_of_work[0])  # 178.21 deg
    largest = span - 2 * 5.0
    d["motion"] = [
        {"phase": "rise", "law": "parabolic", "angle": 170},
        {"phase": "dwell", "angle": 10},
        {"phase": "return", "law": "harmonic", "angle": 120},
        {"phase": "dwell"},
    ]
    spec = machine_from_dict(d)
    with pytest.raises(InfeasibleError, match=rf"feed window too short.*largest feasible rise angle is {largest:.4g} deg") as ei:
        design_machine(spec)
    assert ei.value.field == "motion"
    d["motion"][0]["angle"] = largest - 1e-6  # just fits
    t = place_cam(win, machine_from_dict(d).cam.program, Drive.shaft(), Timing(margin=np.radians(5.0)))
    assert t.margins[0] == pytest.approx(np.radians(5.0), abs=1e-6)


def test_gear_drive_of_the_pump():
    """Seed 004: the cam turns through Z5-Z6 (assumed 20/40): its rise takes twice its cam angle in crank angle."""
    spec = load_machine(PUMP)
    res = design_machine(spec)
    t = res.timing
    assert t.period == (1, 2) and t.ratio == pytest.approx(0.5)
    assert spec.cam.cam_sense == -spec.linkage.crank_sense  # external mesh
    assert spec.cam.rpm == pytest.approx(77 / 2)
    (r0, r1), = t.rises
    assert np.degrees(r1 - r0) == pytest.approx(80.0)
    assert not res.overlap and res.ok
    # the piston rises during the working (slow) stroke: seed 004's upward delivery
    assert res.stroke.s_end > res.stroke.s_start
    assert np.degrees(res.stroke.working_span) == pytest.approx(240.0, abs=1e-9)


def test_recurring_rise_that_cannot_fit():
    """A cam turning twice per crank turn repeats its rise 180 deg later, inside the cut."""
    d = raw(SLOTTING)
    d["drive"] = {"kind": "gears", "z_crank": 40, "z_cam": 20}
    with pytest.raises(InfeasibleError, match="recurs") as ei:
        design_machine(machine_from_dict(d))
    assert ei.value.field == "drive"


def test_explicit_lengths_equal_synthesis():
    d = raw(SLOTTING)
    m = load_machine(SLOTTING).linkage
    d["linkage"] = {
        "type": "slotting", "crank": m.crank, "centre_distance": m.centre_distance, "bar": m.bar,
        "rod": m.rod, "guide_x": m.guide_x, "rpm": 60,
    }
    lk = machine_from_dict(d).linkage
    assert isinstance(lk, SlottingMachine) and lk.synthesis is None
    assert lk.lengths()["l_BC"] == pytest.approx(m.rod)


@pytest.mark.parametrize(
    "patch, field, text",
    [
        ({"linkage": {"time_ratio": 1.0}}, "linkage.time_ratio", "K must be > 1"),
        ({"linkage": {"stroke": -100.0}}, "linkage.stroke", "> 0"),
        ({"linkage": {"crank": 50.0}}, "linkage", "either the course data"),
        ({"linkage": {"colour": "red"}}, "linkage", "unknown key"),
        ({"linkage": {"type": "shaper"}}, "linkage.type", "not a valid option"),
        ({"cam": {"rotation": "cw"}}, "cam.rotation", "set by the machine"),
        ({"drive": {"kind": "gears", "z_crank": 20}}, "drive.z_cam", "required"),
        ({"drive": {"kind": "gears", "z_crank": 20, "z_cam": 0}}, "drive.z_cam", "whole number"),
        ({"cutting": {"approach": 0.6, "overrun": 0.5}}, "cutting", "< 1"),
        ({"timing": {"placement": "middle"}}, "timing.placement", "not a valid option"),
        ({"linkage": {"bar_side": "same"}}, "linkage.bar", "inside the block's travel"),
    ],
)
def test_bad_machine_files(patch, field, text):
    d = copy.deepcopy(raw(SLOTTING))
    for k, v in patch.items():
        d[k] = {**d.get(k, {}), **v} if k != "drive" else v
    with pytest.raises(InputError, match=text) as ei:
        machine_from_dict(d)
    assert ei.value.field == field


def test_unassemblable_linkage_from_file():
    d = raw(SLOTTING)
    d["linkage"] = {"type": "slotting", "crank": 75.0, "centre_distance": 150.0, "bar": 100.0, "rod": 5.0, "guide_x": -240.0}
    with pytest.raises(InfeasibleError, match=r"linkage.rod: .*crank angles .*needs l_BC >= 10"):
        machine_from_dict(d)


def test_key_angle_on_the_crank_shaft():
    """With the roller's direction given, the cam's start radius is keyed at (direction - crank angle at mount)."""
    d = raw(SLOTTING)
    d["timing"]["follower_direction"] = 30.0
    spec = machine_from_dict(d)
    w = windows(spec.linkage, spec.cutting)
    t = place_cam(w, spec.cam.program, spec.drive, spec.timing)
    assert np.degrees(t.key_angle) == pytest.approx(30.0 - np.degrees(t.mount_frame))
    assert np.mod(t.mount_frame - w.frame_angle(t.mount), 2 * np.pi) == pytest.approx(0.0, abs=1e-12)


def test_offset_crank_slider_machine_file():
    """An offset crank-slider has a quick return; the cam's rise goes in its return stroke."""
    d = raw(SLOTTING)
    d["linkage"] = {"type": "crank_slider", "stroke": 100.0, "rod": 220.0, "offset": 40.0, "rpm": 60}
    d["cutting"] = {"approach": 0.05, "overrun": 0.05}
    res = design_machine(machine_from_dict(d))
    assert res.stroke.stroke == pytest.approx(100.0, rel=1e-10)
    assert res.stroke.time_ratio > 1.05
    assert not res.overlap and res.ok
