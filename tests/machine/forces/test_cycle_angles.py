"""``cams machine --forces`` reports every crank angle as the cycle angle from position 1, like its windows."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main
from cams.machine.design import design_machine
from cams.machine.kinetostatics import machine_forces
from cams.machine.machinefile import load_machine

ROOT = Path(__file__).resolve().parents[3]
SLOTTING = ROOT / "examples" / "machines" / "slotting_machine.toml"
FORCES_DATA = Path(__file__).resolve().parent / "data" / "slotting_forces.toml"

# massless links, no friction: the only load is the cutting resistance, so the balancing
# moment, the reactions and the reduced resisting moment are non-zero only during the cut
RESISTANCE = """
[forces]
samples = 720
delta = 0.05
[forces.links.crank]
inertia = 0.05
[[forces.loads]]
kind = "resistance"
body = "tool"
force = 1000.0
"""


def _inside(a_deg: float, window, tol: float = 0.6) -> bool:
    a, b = window
    return a - tol <= a_deg <= b + tol or a - tol <= a_deg + 360 <= b + tol


@pytest.fixture(params=["ccw", "cw"])
def machine_file(tmp_path, request):
    text = SLOTTING.read_text(encoding="utf-8").replace('crank_rotation = "ccw"', f'crank_rotation = "{request.param}"', 1)
    if request.param == "cw":  # the cam turns the other way: the follower mirrored keeps the example's cam (no undercut)
        text = text.replace('rise_direction = "cw"', 'rise_direction = "ccw"', 1)
    f = tmp_path / f"slotting_{request.param}.toml"
    f.write_text(text + RESISTANCE, encoding="utf-8")
    return f


def test_json_peaks_lie_in_the_cutting_window(machine_file, capsys):
    assert main(["machine", str(machine_file), "--forces", "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    cut = rep["windows"]["cutting"]
    lk = rep["forces"]["linkage"]
    assert _inside(lk["balancing_moment"]["at_deg"], cut), (lk["balancing_moment"], cut)
    for name, p in lk["pairs"].items():
        assert _inside(p["at_deg"], cut), (name, p, cut)
    assert lk["angle_reference"] == "cycle angle from position 1"
    assert rep["forces"]["flywheel"]["angle_reference"] == "cycle angle from position 1"


def test_text_peak_lies_in_the_cutting_window(machine_file, capsys):
    assert main(["machine", str(machine_file), "--forces"]) == 0
    out = capsys.readouterr().out
    cut = [float(x) for x in re.search(r"cutting ([\d.]+) \.\. ([\d.]+) deg", out).groups()]
    at = float(re.search(r"max \|M_b\| = [\d.]+ N m at ([\d.]+) deg", out).group(1))
    assert _inside(at, cut), (at, cut)
    assert "angles: cycle angle from position 1" in out


def test_flywheel_resisting_moment_only_in_the_cut(machine_file):
    spec = load_machine(machine_file)
    res = design_machine(spec)
    mf = machine_forces(spec, res.solve.centre)
    fw = mf.flywheel
    loaded = np.abs(fw.resisting) > 1e-6 * np.max(np.abs(fw.resisting))
    deg = np.degrees(fw.phi[loaded])
    a, b = np.degrees(res.windows.cutting)
    assert deg.min() >= a - 0.6 and deg.max() <= b + 0.6, (deg.min(), deg.max(), a, b)
    assert fw.reference == "cycle angle from position 1"
    # the linkage's own angles: its first sample is position 1
    assert mf.linkage.rotation[0] == 0.0
    assert np.mod(mf.linkage.phi[0] - res.windows.origin, 2 * np.pi) == pytest.approx(0.0, abs=1e-12)


def test_cam_angles_are_mapped_to_cycle_angles(capsys):
    assert main(["machine", str(FORCES_DATA), "--forces", "--json"]) == 0
    rep = json.loads(capsys.readouterr().out)
    cam, t = rep["forces"]["cam"], rep["timing"]
    assert "cam angle" in cam["angle_reference"] and "cycle angle from position 1" in cam["angle_reference"]
    for key in ("max_contact_at", "max_torque_at", "jump_at"):
        (c,) = cam[key + "_cycle_deg"]
        assert c == pytest.approx((t["mount_deg"] + cam[key + "_deg"] / t["ratio"]) % 360, abs=1e-9)


def test_plot_labels_name_the_angle(tmp_path, monkeypatch, capsys):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    labels = []
    real = plt.Figure.savefig

    def grab(fig, *a, **k):
        labels.extend(ax.get_xlabel() for ax in fig.axes if ax.get_xlabel())
        labels.append(fig._suptitle.get_text() if fig._suptitle is not None else "")
        return real(fig, *a, **k)

    monkeypatch.setattr(plt.Figure, "savefig", grab)
    assert main(["machine", str(FORCES_DATA), "--forces", "--plot", str(tmp_path)]) == 0
    text = "\n".join(labels)
    assert "crank angle from the cycle's start" not in text and "(frame)" not in text
    assert text.count("cycle angle from position 1") >= 5, text  # cycle, forces, hodographs, flywheel, cam forces
