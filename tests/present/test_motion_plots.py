"""The motion design's picture: the laws, pressure angles and cams it draws are the designs' own."""

from __future__ import annotations

import numpy as np
import pytest

from cams.cam import Cam
from cams.io.designfile import design_from_dict, load_design
from cams.io.document import read_toml
from cams.present.motion_plots import plot_motion_design
from tests.conftest import ROOT
from tests.inprocess import cams_cli

EXAMPLE = str(ROOT / "examples" / "translating_force.toml")


@pytest.fixture(scope="module")
def cam():
    doc = read_toml(EXAMPLE)
    doc["optimize"] = {"max_Ca": "poly4567", "max_Cj": "poly4567", "spans": 5}
    return Cam(design_from_dict(doc))


def test_picture_draws_both_laws_pressures_and_cams(cam):
    fig = plot_motion_design(cam)
    assert len(fig.axes) == 6
    s_axis, pressure, cams = fig.axes[0], fig.axes[4], fig.axes[5]
    original = next(ln for ln in s_axis.lines if ln.get_label().startswith("original"))
    u = original.get_xdata()
    assert np.allclose(original.get_ydata(), cam.given.program.law_of(0).evaluate(u)[0])
    designed = next(ln for ln in pressure.lines if ln.get_label() == "designed")
    # the designed cam's pressure angle on the rise, drawn: its peak is the independent check's (the limit)
    assert np.max(designed.get_ydata()) == pytest.approx(np.degrees(cam.solution.pressure.rise), abs=0.05)
    labels = [ln.get_label() for ln in cams.lines]
    reference = cam.solution.optimization.reference["R0"]
    assert f"original: R0 = {reference:.3f} mm" in labels
    assert f"designed: R0 = {cam.solution.R0:.3f} mm" in labels


def test_plot_command_writes_the_picture_of_a_designed_file(tmp_path):
    text = open(EXAMPLE, encoding="utf-8").read() + "\n[optimize]\nmax_Ca = \"poly4567\"\nmax_Cj = \"poly4567\"\n" \
        "spans = 5\n"
    f = tmp_path / "designed.toml"
    f.write_text(text, encoding="utf-8")
    r = cams_cli("plot", f, "--out", tmp_path / "p", "--only", "optimized")
    assert r.returncode == 0, r.stderr
    assert sorted(p.suffix for p in (tmp_path / "p").iterdir()) == [".png", ".svg"]


def test_optimized_picture_of_a_plain_file_is_skipped(tmp_path):
    r = cams_cli("plot", EXAMPLE, "--out", tmp_path / "p", "--only", "motion,optimized")
    assert r.returncode == 0 and "no [optimize] table" in r.stderr
    assert not any("optimized" in p.name for p in (tmp_path / "p").iterdir())
    assert load_design(EXAMPLE).optimize is None


def test_report_has_the_motion_design_table_and_picture(cam):
    from cams.present.report import _figures, report_sections

    sections = dict(report_sections(cam))
    rows = dict(sections["Motion design"])
    o = cam.solution.optimization.to_dict()
    assert rows["minimized"] == f"R0: {o['value']:.6g} mm"
    assert rows["proven lower bound"].startswith(f"{o['lower_bound']:.6g} mm")
    assert rows["certified"] == "yes"
    assert any(name.startswith("Motion design") for name, _ in _figures(cam))


def test_picture_draws_the_first_stage_law_beside_the_smoothed_one(cam):
    """The second stage smoothed the law: the first stage's (from the report's law table) is drawn too."""
    from laws.spline import SplineLaw

    sm = cam.solution.optimization.smoothing
    assert sm["smoothed"]
    fig = plot_motion_design(cam)
    jerk = fig.axes[3]
    first = next(ln for ln in jerk.lines if ln.get_label().startswith("first stage"))
    (table,) = sm["first_stage_laws"]
    law = SplineLaw(tuple(table["breaks"]), tuple(tuple(r) for r in table["coefficients"]))
    u = np.asarray(first.get_xdata())
    assert np.allclose(first.get_ydata(), law.evaluate(u)[3])
    assert "total variation of S'''" in fig.get_suptitle()


def test_picture_states_the_gap_as_cams_solve_prints_it():
    """The optimality gap is a ratio: the picture's title says so, with the digits of ``cams solve``'s line (it
    printed "gap 0.0053" where the text said "gap 0.00527 (relative)")."""
    import re

    designed = ROOT / "examples" / "translating_designed_rise.toml"
    r = cams_cli("solve", designed)
    (printed,) = re.findall(r"gap \S+ \(relative\)", r.stdout)
    assert printed in plot_motion_design(Cam.from_file(designed)).get_suptitle()
