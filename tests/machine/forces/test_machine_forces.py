"""Machine files with [forces] and [dynamics]; ``cams machine FILE --forces`` (text, JSON, plots, one-line errors)."""

from __future__ import annotations

import json
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main
from cams.machine.kinetostatics import GasPressure, Resistance, machine_forces
from cams.machine.machinefile import force_spec_from_dict, load_machine, machine_from_dict
from laws.errors import InputError

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[2]
DATA = HERE / "data" / "slotting_forces.toml"
PUMP = ROOT / "examples" / "machines" / "pump.toml"
SLOTTING = ROOT / "examples" / "machines" / "slotting_machine.toml"

PUMP_FORCES = """
[forces]
passes = "iterate"
delta = 0.1
[forces.links.crank]
mass = 10.0
inertia = 0.3
[forces.links.lever]
mass = 25.0
inertia = 0.6
[forces.links.piston]
mass = 40.0
[forces.friction]
revolute = { coefficient = 0.195, radius = 24.0 }   # seed 004: 1.3 f, f = 0.15, r = 0.024 m
prismatic = { coefficient = 0.15 }
[[forces.loads]]
kind = "resistance"
body = "piston"
force = 2500.0
window = "working"
"""


def test_machine_file_forces_table():
    spec = load_machine(DATA)
    fs, opt = spec.forces, spec.force_options
    assert fs.links["tool"].mass == pytest.approx(71.4) and fs.length_unit == 1e-3
    assert set(fs.friction) == {"O2", "A", "A_slot", "O3", "B", "C", "C_guide"}
    assert fs.friction["A_slot"].coefficient == 0.15 and fs.friction["O3"].radius == 15.0
    (load,) = fs.loads
    assert isinstance(load, Resistance) and (load.approach, load.overrun) == (0.05, 0.05)  # from [cutting]
    assert opt.delta == 0.05 and opt.passes == 2 and opt.samples == 360
    assert spec.cam.dynamics.rate == 3.0


def test_machine_forces_api():
    spec = load_machine(DATA)
    from cams.machine.design import design_machine

    res = design_machine(spec)
    mf = machine_forces(spec, res.solve.centre)
    assert mf.ok and mf.linkage is not None and mf.flywheel is not None and mf.cam is not None
    assert np.max(np.abs(mf.linkage.balancing_moment - mf.linkage.virtual_moment)) < 1e-9
    assert mf.flywheel.achieved_delta == pytest.approx(0.05, rel=1e-9)
    assert mf.jump.rpm > spec.cam.rpm  # the margin keeps the jump speed above the running speed
    # the flywheel's driving moment is the mean balancing moment (the linkage's work over a cycle)
    assert mf.flywheel.driving_moment == pytest.approx(np.mean(mf.linkage.balancing_moment), rel=1e-3)


def test_pump_with_forces(tmp_path, capsys):
    f = tmp_path / "pump_forces.toml"
    f.write_text(PUMP.read_text(encoding="utf-8") + PUMP_FORCES, encoding="utf-8")
    assert main(["machine", str(f), "--forces", "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)["forces"]
    lk = rep["linkage"]
    assert lk["passes"] > 2 and set(lk["pairs"]) == {"O1", "A", "A_slot", "O2", "C", "C_slot", "E"}
    assert lk["balancing_moment"]["virtual_work_max_difference"] < 1e-9
    # energy: the piston's work per cycle is 2500 N x 0.25 m, at 77/60 cycles per second, plus friction
    useful = 2500 * 0.25 * 77 / 60
    assert lk["drive_power_mean_W"] == pytest.approx(useful + lk["friction_power_total_mean_W"], rel=1e-3)
    assert rep["flywheel"]["delta"] == 0.1 and rep["flywheel"]["flywheel_inertia"] > 0
    assert "cam" not in rep  # no [dynamics]


def test_text_report(capsys):
    assert main(["machine", str(DATA), "--forces"]) == 0
    out = capsys.readouterr().out
    assert "forces at 60 rpm (two-stage friction)" in out
    assert "Zhukovsky's lever agrees" in out and "pair O3" in out and "friction losses" in out
    assert "flywheel for delta = 0.05" in out and "J_F =" in out
    assert "jump speed" in out and "contact lost: no" in out


def test_plots(tmp_path, capsys):
    assert main(["machine", str(DATA), "--forces", "--plot", str(tmp_path)]) == 0
    for name in ("cycle", "forces", "hodographs", "flywheel", "cam_forces"):
        png = tmp_path / f"slotting_forces_{name}.png"
        assert png.exists() and png.stat().st_size > 1000, name


def test_without_forces_table(capsys):
    assert main(["machine", str(SLOTTING), "--forces", "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)["forces"]
    assert "linkage" not in rep and any("no [forces] table" in n for n in rep["notes"])


def test_without_forces_flag_no_forces(capsys):
    assert main(["machine", str(DATA), "--json"]) == 0
    assert "forces" not in json.loads(capsys.readouterr().out)


@pytest.mark.parametrize(
    "old, new, field, words",
    [
        ("mass = 71.4", "mass = -71.4", "forces.links.tool.mass", "negative"),
        ("inertia = 1.1", "inertia = -1.1", "forces.links.bar.inertia", "negative"),
        ("delta = 0.05", "delta = 0.0", "forces.delta", "(0, 1)"),
        ("delta = 0.05", "delta = -0.05", "forces.delta", "(0, 1)"),
        ("[forces.links.tool]", "[forces.links.wheel]", "forces.links", "unknown key"),
        ("body = \"tool\"", "body = \"bar\"", "forces.loads[0].body", "does not slide"),
        ("force = 1000.0", "force = -1000.0", "forces.loads[0].force", ">= 0"),
        ("passes = 2", "passes = 0", "forces.passes", ">= 1"),
        ("spring_rate = 3.0", "spring_rate = -3.0", "dynamics.spring_rate", ">= 0"),
        ("mass = 0.003", "mass = -0.003", "dynamics.mass", "> 0"),
    ],
)
def test_bad_forces_input_is_one_line(tmp_path, capsys, old, new, field, words):
    text = DATA.read_text(encoding="utf-8")
    assert old in text
    f = tmp_path / "bad.toml"
    f.write_text(text.replace(old, new, 1), encoding="utf-8")
    assert main(["machine", str(f), "--forces"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and field in err and words in err, err


def test_gas_table_must_cover_the_cycle():
    table = {"loads": [{"kind": "gas", "body": "slider", "angles": [0, 90, 180], "pressure": [1e6, 2e5, 1e5], "bore": 80}]}
    with pytest.raises(InputError) as e:
        force_spec_from_dict(table, "crank_slider")
    assert e.value.field == "forces.loads[0].angles" and "from 0 to 360 deg" in str(e.value)
    table["loads"][0].update(angles=[0, 90, 180, 360], pressure=[1e6, 2e5, 1e5, 1e6])
    spec, _ = force_spec_from_dict(table, "crank_slider")
    assert isinstance(spec.loads[0], GasPressure)


def test_spring_that_cannot_keep_contact(tmp_path, capsys):
    text = DATA.read_text(encoding="utf-8").replace("margin = 1.5", "margin = 1.5\nmax_spring_force = 0.01", 1)
    f = tmp_path / "weak.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["machine", str(f), "--forces"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "dynamics.spring_rate" in err and "cannot keep contact" in err and "at any preload" in err


def test_machine_from_dict_keeps_the_cam_dynamics():
    d = tomllib.loads(DATA.read_text(encoding="utf-8"))
    spec = machine_from_dict(d)
    assert spec.cam.rpm == pytest.approx(60.0) and spec.cam.dynamics.margin == 1.5


def test_plotting_imports_matplotlib_lazily():
    code = ("import sys, cams.machine.kinetostatics, cams.machine.flywheel, cams.dynamics.forces, cams.commands.machine; "
            "print('matplotlib' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True).stdout
    assert out.strip() == "False"


def test_flywheel_without_inertia_is_one_line(tmp_path, capsys):
    """[forces] delta with no link masses: one line naming forces.links (was a brentq traceback)."""
    text = SLOTTING.read_text(encoding="utf-8")
    path = tmp_path / "no_masses.toml"
    path.write_text(text + "\n[forces]\ndelta = 0.1\n", encoding="utf-8")
    assert main(["machine", str(path), "--forces"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("cams machine: error: forces.links: the machine has no inertia") and err.count("\n") == 1


def test_flywheel_without_link_masses_but_with_loads_is_sized(tmp_path, capsys):
    """Massless links with a cutting load: the flywheel alone carries the inertia, and it can be sized."""
    text = SLOTTING.read_text(encoding="utf-8")
    path = tmp_path / "loads_only.toml"
    path.write_text(text + '\n[forces]\ndelta = 0.05\n[[forces.loads]]\nkind = "resistance"\nbody = "tool"\n'
                    'force = 1000.0\n', encoding="utf-8")
    assert main(["machine", str(path), "--forces", "--json"]) == 0
    fw = json.loads(capsys.readouterr().out)["forces"]["flywheel"]
    assert fw["flywheel_inertia"] > 0


def test_hodographs_draw_the_reactions():
    """Each panel of the hodograph figure traces its pair's reaction vector (R_x, R_y) over the whole cycle."""
    from cams.machine.design import design_machine
    from cams.machine.kinetostatics import machine_forces
    from cams.machine.machinefile import load_machine

    spec = load_machine(DATA)
    mf = machine_forces(spec, design_machine(spec).solve.centre)
    lk = mf.linkage
    from cams.present.machine_plots import hodograph_figure

    fig = hodograph_figure(lk, marks=12)
    axes = [ax for ax in fig.axes if ax.get_visible()]
    assert len(axes) == len(lk.model.joints)
    for ax, j in zip(axes, lk.model.joints, strict=True):
        xy = ax.lines[0].get_xydata()
        R = lk.reactions[j.name]
        assert ax.get_title().startswith(j.name)
        assert len(xy) == R.size
        # the same points (the figure orders them by crank rotation)
        assert np.allclose(np.sort(xy[:, 0]), np.sort(np.real(R))) and np.allclose(np.sort(xy[:, 1]), np.sort(np.imag(R)))
        # mark 1 is the reaction at position 1 (the first crank angle)
        marks = ax.lines[2].get_xydata()   # the marks, one line of points (their numbers placed apart)
        assert len(marks) == 12
        assert np.allclose(marks[0], [np.real(R[0]), np.imag(R[0])])


def test_forces_reuse_what_the_machine_design_found(monkeypatch):
    """Given design_machine's result, machine_forces finds neither the machine's windows nor the cam's timing
    again (a resistance load still finds its own window: its approach and overrun are its own), and gives the
    same forces as when it finds them itself."""
    import cams.machine.timing as machine_mod
    from cams.machine.design import design_machine
    from cams.machine.kinetostatics import machine_forces
    from cams.machine.machinefile import load_machine

    spec = load_machine(DATA)
    res = design_machine(spec)
    calls = {"windows": 0, "place_cam": 0}
    for name in calls:
        real = getattr(machine_mod, name)

        def counted(*a, _real=real, _name=name, **k):
            calls[_name] += 1
            return _real(*a, **k)

        monkeypatch.setattr(machine_mod, name, counted)
    alone = machine_forces(spec, res.solve.centre)
    by_itself = dict(calls)
    reused = machine_forces(spec, found=res)
    again = {k: calls[k] - by_itself[k] for k in calls}
    assert again["place_cam"] == 0 and by_itself["place_cam"] == 1
    assert again["windows"] == by_itself["windows"] - 1
    assert np.array_equal(reused.linkage.balancing_moment, alone.linkage.balancing_moment)
    assert reused.to_dict() == alone.to_dict()
