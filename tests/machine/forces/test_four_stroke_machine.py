"""A machine file's gas table of period 720: ``cams machine --forces`` analyses two crank turns and a 720-degree flywheel."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main
from cams.machine.design import design_machine
from cams.machine.kinetostatics import ForceSpec, GasPressure, LinkMass, analyse_forces, machine_forces
from cams.machine.linkage.machines import CrankSlider
from cams.machine.machinefile import machine_from_dict

ROOT = Path(__file__).resolve().parents[3]
SLOTTING = ROOT / "examples" / "machines" / "slotting_machine.toml"
ANGLES = [0, 20, 60, 180, 360, 540, 720]
PRESSURE = [5.0e6, 4.0e6, 1.5e6, 0.2e6, 0.0, 0.1e6, 5.0e6]
START = 30.0


def engine(period: int = 720) -> dict:
    d = tomllib.loads(SLOTTING.read_text(encoding="utf-8"))
    d["linkage"] = {"type": "crank_slider", "stroke": 100.0, "rod": 220.0, "offset": 40.0, "rpm": 600}
    d["cutting"] = {"approach": 0.05, "overrun": 0.05}
    angles = ANGLES if period == 720 else [a / 2 for a in ANGLES]
    d["forces"] = {
        "gravity": 0.0, "delta": 0.02, "samples": 360,
        "links": {"crank": {"mass": 2.0, "inertia": 0.01}, "rod": {"mass": 1.0, "inertia": 0.005}, "slider": {"mass": 0.8}},
        "loads": [{"kind": "gas", "body": "slider", "angles": angles, "pressure": PRESSURE, "bore": 80.0,
                   "period": period, "start": START}],
    }
    return d


def test_two_turns_and_a_720_degree_flywheel():
    spec = machine_from_dict(engine())
    res = design_machine(spec)
    mf = machine_forces(spec, res.solve.centre)
    lk = mf.linkage
    c = np.degrees(lk.rotation)
    assert lk.phi.size == 720 and c[0] == 0.0 and c[-1] == pytest.approx(719.0)  # samples a turn, two turns
    assert mf.flywheel.phi[-1] - mf.flywheel.phi[0] == pytest.approx(4 * np.pi)
    assert mf.flywheel.achieved_delta == pytest.approx(0.02, rel=1e-9)
    assert mf.flywheel.driving_moment == pytest.approx(np.mean(lk.balancing_moment), rel=1e-3)
    assert any("two crank turns" in n for n in mf.notes)
    # the table's angle 0 is where the crank first passes `start` after position 1
    first = np.mod(spec.linkage.crank_sense * (np.radians(START) - lk.phi[0]), 2 * np.pi)
    table = np.mod(np.radians(c) - first, 4 * np.pi)
    expected = -np.interp(np.degrees(table), ANGLES, PRESSURE) * np.pi * 0.08**2 / 4  # toward the crank: -x
    assert np.real(lk.model.loads[0].force) == pytest.approx(expected, rel=1e-12, abs=1e-9)
    # the two turns differ: the table's second half is not the first's
    assert not np.allclose(lk.balancing_moment[:360], lk.balancing_moment[360:])


def test_a_360_degree_table_stays_one_turn():
    spec = machine_from_dict(engine(360))
    mf = machine_forces(spec, design_machine(spec).solve.centre)
    assert mf.linkage.phi.size == 360 and mf.flywheel.phi[-1] - mf.flywheel.phi[0] == pytest.approx(2 * np.pi)
    assert not any("two crank turns" in n for n in mf.notes)


ENGINE = f"""
name = "four-stroke engine with a cam"
[linkage]
type = "crank_slider"
stroke = 100.0
rod = 220.0
offset = 40.0
rpm = 600
[cutting]
approach = 0.05
overrun = 0.05
[follower]
kind = "rocker"
arm = 125.0
swing = 15.0
roller_radius = 15.0
[[motion]]
phase = "rise"
law = "cycloidal"
angle = 60
[[motion]]
phase = "return"
law = "cycloidal"
angle = 60
[[motion]]
phase = "dwell"
[limits]
pressure_angle = 40
[forces]
gravity = 0.0
delta = 0.02
[forces.links.crank]
mass = 2.0
inertia = 0.01
[forces.links.slider]
mass = 0.8
[[forces.loads]]
kind = "gas"
body = "slider"
angles = {ANGLES}
pressure = {PRESSURE}
bore = 80.0
start = {START}
period = 720
"""


def test_cli_reports_cycle_angles_to_720(tmp_path, capsys):
    f = tmp_path / "engine.toml"
    f.write_text(ENGINE, encoding="utf-8")
    assert main(["machine", str(f), "--forces", "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)["forces"]
    assert rep["linkage"]["angle_reference"] == "cycle angle from position 1"
    assert rep["flywheel"]["achieved_delta"] == pytest.approx(0.02, rel=1e-9)
    assert any("two crank turns" in n for n in rep["notes"])
    assert main(["machine", str(f), "--forces", "--plot", str(tmp_path / "plots")]) == 0
    assert (tmp_path / "plots" / "engine_flywheel.png").exists()


def test_api_default_angles_cover_the_cycle():
    """build_model's default crank angles cover two turns with a period-720 table (samples a turn)."""
    m = CrankSlider(crank=48.0, rod=192.0, rod_cg=64.0, rpm=3000)
    spec = ForceSpec(links={"crank": LinkMass(2.0, 0.01), "slider": LinkMass(0.8)},
                     loads=(GasPressure("slider", np.radians(ANGLES), PRESSURE, 80.0, period=4 * np.pi),), gravity=0.0)
    r = analyse_forces(m, spec, samples=36)
    assert r.phi.size == 72 and np.degrees(r.rotation).max() == pytest.approx(710.0)
    assert r.flywheel(delta=0.05, cycle=4 * np.pi).achieved_delta == pytest.approx(0.05, rel=1e-9)
    assert json.dumps(r.to_dict())


def test_gas_load_depends_on_the_crank_position_not_on_the_angles_asked():
    """A 720-degree table's phase is tied to the model's origin: the load at 10 deg is the same whatever other
    angles are asked for, and differs from the load at 370 deg (the other turn)."""
    from cams.machine.kinetostatics import build_model

    m = CrankSlider(crank=48.0, rod=192.0, rod_cg=64.0, rpm=3000)
    gas = GasPressure("slider", tuple(np.radians(ANGLES)), tuple(PRESSURE), bore=80.0, start=np.radians(START),
                      period=4 * np.pi)
    spec = ForceSpec(links={"slider": LinkMass(1.0)}, loads=(gas,))
    at = {}
    for name, phi in (("pair", [0.0, 10.0]), ("alone", [10.0]), ("after", [10.0, 200.0, 500.0]), ("other", [370.0])):
        model = build_model(m, spec, phi=np.radians(phi))
        at[name] = model.loads[0].force[list(phi).index(10.0 if name != "other" else 370.0)]
    assert at["pair"] == at["alone"] == at["after"]
    assert at["other"] != at["pair"]
    # the documented phase: the table's angle 0 at the first pass of `start` at or after the origin (0 here)
    table_deg = (10.0 - START) % 720.0
    assert np.real(at["alone"]) == pytest.approx(-np.interp(table_deg, ANGLES, PRESSURE) * np.pi * 0.08**2 / 4)


def test_flywheel_defaults_to_the_models_cycle():
    """A 720-degree model's flywheel needs no cycle: it takes the loads' cycle (was 'angles must increase')."""
    m = CrankSlider(crank=48.0, rod=192.0, rod_cg=64.0, rpm=3000)
    gas = GasPressure("slider", tuple(np.radians(ANGLES)), tuple(PRESSURE), bore=80.0, start=np.radians(START),
                      period=4 * np.pi)
    r = analyse_forces(m, ForceSpec(links={"crank": LinkMass(2.0, inertia=0.01), "slider": LinkMass(1.0)}, loads=(gas,)),
                       samples=90)
    a, b = r.flywheel(delta=0.05), r.flywheel(delta=0.05, cycle=4 * np.pi)
    assert a.phi[-1] - a.phi[0] == pytest.approx(4 * np.pi)
    assert a.flywheel_inertia == b.flywheel_inertia and a.excess_work == b.excess_work
