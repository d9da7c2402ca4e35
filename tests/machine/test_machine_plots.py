"""The machine side's pictures (cams.present.machine_plots): Figures without pyplot or a backend, written whole or not at all."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from cams.cli import main

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "machine" / "forces" / "data" / "slotting_forces.toml"


def test_drawing_leaves_the_backend_and_pyplot_alone():
    """Importing and drawing every machine picture keeps the user's backend and pyplot's figure list."""
    code = f"""
import matplotlib
matplotlib.use("svg")
import matplotlib.pyplot as plt
plt.figure()
before = (matplotlib.get_backend(), plt.get_fignums())
from cams.machine.machinefile import load_machine
from cams.machine.design import design_machine
from cams.machine.kinetostatics import machine_forces
from cams.present.machine_plots import machine_figures
from matplotlib.figure import Figure
spec = load_machine({str(DATA)!r})
res = design_machine(spec)
figs = machine_figures(res.diagram, machine_forces(spec, found=res), title="t")
assert list(figs) == ["cycle", "forces", "hodographs", "flywheel", "cam_forces"], list(figs)
assert all(type(f) is Figure for f in figs.values())
assert (matplotlib.get_backend(), plt.get_fignums()) == before, ((matplotlib.get_backend(), plt.get_fignums()), before)
print("ok")
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0 and out.stdout.strip() == "ok", out.stderr


def test_pictures_are_all_or_nothing(tmp_path, monkeypatch, capsys):
    """A picture that fails leaves none of the machine's pictures behind (and not the folder it created)."""
    import cams.present.machine_plots as mp

    class Broken:  # the last picture fails while it is written, after the others were
        def savefig(self, *a, **k):
            raise RuntimeError("writing failed")

    monkeypatch.setattr(mp, "cam_forces_figure", lambda *a, **k: Broken())
    out = tmp_path / "pictures"
    with pytest.raises(RuntimeError):
        main(["machine", str(DATA), "--forces", "--plot", str(out)])
    assert not out.exists() or list(out.iterdir()) == []


def test_pictures_written(tmp_path, capsys):
    """--plot with --forces writes the five pictures, in order, and names them."""
    assert main(["machine", str(DATA), "--forces", "--plot", str(tmp_path)]) in (0, 1)
    text = capsys.readouterr().out
    names = [Path(line.split("plot: ", 1)[1]).name for line in text.splitlines() if line.strip().startswith("plot: ")]
    stem = DATA.stem
    assert names == [f"{stem}_{n}.png" for n in ("cycle", "forces", "hodographs", "flywheel", "cam_forces")]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(names)
