"""Pictures are checked for content, not only for existence."""

import numpy as np
import pytest
from shapely.geometry import Point, Polygon

from cams.cam import Cam
from cams.present.plots import plot_motion, plot_pressure, plot_profile, plot_zone, save
from tests.conftest import EXAMPLES


@pytest.fixture(scope="module")
def cams_by_name():
    return {p.stem: Cam.from_file(p) for p in sorted(EXAMPLES.glob("*.toml"))}


@pytest.mark.parametrize("name", ["rocker_force", "rocker_form", "translating_force", "translating_form_centric"])
def test_zone_picture_shades_a_zone_that_holds_the_centre(cams_by_name, name):
    cam = cams_by_name[name]
    fig = plot_zone(cam.solution, tradeoff=cam.tradeoff)
    ax = fig.axes[0]
    zones = [p for p in ax.patches if p.get_label().startswith("allowable zone")]
    assert len(zones) == 1
    poly = Polygon(zones[0].get_xy())
    assert poly.is_valid and poly.area > 0
    # the chosen centre lies on the zone (at its edge for a minimum): within round-off of the sampling
    assert poly.buffer(1e-3 * cam.design.scale).contains(Point(*cam.solution.centre))
    # binding lines are drawn highlighted
    red = [ln for ln in ax.lines if ln.get_color() == "#c53030" and len(ln.get_xdata()) == 2]
    assert len(red) >= len(cam.solution.binding)
    assert ax.get_aspect() == 1.0
    assert "mm" in ax.get_xlabel() and "mm" in ax.get_ylabel()


def test_profile_picture_draws_the_exported_profile(cams_by_name):
    cam = cams_by_name["rocker_form"]
    fig = plot_profile(cam, phi=0.0)
    ax = fig.axes[0]
    filled = [p for p in ax.patches if p.get_label() == "working profile"]
    assert len(filled) == 1
    xy = filled[0].get_xy()[:-1]  # closed polygon repeats the first vertex
    # at phi = 0 the cam frame is the fixed frame shifted to the cam centre
    expected = cam.profile.work + cam.solution.centre
    assert xy.shape == expected.shape
    assert np.allclose(xy, expected, atol=1e-9)


def test_motion_picture_marks_impacts():
    from cams.io.designfile import design_from_dict
    from tests.conftest import rocker_dict

    d = design_from_dict(rocker_dict(motion=[{"phase": "rise", "law": "harmonic", "angle": 100},
                                             {"phase": "dwell", "angle": 40},
                                             {"phase": "return", "law": "linear", "angle": 100},
                                             {"phase": "dwell"}]))
    fig = plot_motion(d)
    marks = [ln.get_label() for ax in fig.axes for ln in ax.lines]  # marked lines, named once in a legend
    assert marks.count("hard impact (velocity jump)") == 2 and marks.count("soft impact (acceleration jump)") == 2
    assert "jerk" in fig.axes[-1].get_ylabel() or "d³s" in fig.axes[-1].get_ylabel()


def test_pressure_picture_peak_matches_the_check(cams_by_name):
    cam = cams_by_name["rocker_form"]
    fig = plot_pressure(cam.solution)
    ax = fig.axes[0]
    rise = next(ln for ln in ax.lines if ln.get_label() == "rise")
    assert np.max(rise.get_ydata()) == pytest.approx(np.degrees(cam.solution.pressure.rise), abs=0.05)


def test_save_writes_png_and_svg(tmp_path, cams_by_name):
    paths = save(plot_motion(cams_by_name["rocker_force"].design), tmp_path / "m")
    assert [p.suffix for p in paths] == [".png", ".svg"]
    assert paths[0].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert b"<svg" in paths[1].read_bytes()[:2000]
    assert sorted(f.name for f in tmp_path.iterdir()) == ["m.png", "m.svg"]


def test_translating_zone_shows_the_offset(cams_by_name):
    cam = cams_by_name["translating_force"]
    fig = plot_zone(cam.solution)
    labels = [h.get_label() for h in fig.axes[0].get_lines()]
    assert f"offset e = {cam.solution.offset:.3f} mm" in labels


def test_names_the_font_lacks_print_no_warnings(tmp_path):
    """A design named in a script the default font lacks (the seeds' Chinese) plots without stderr noise
    (a process of its own: pytest would capture the warnings)."""
    import subprocess
    import sys

    from tests.conftest import EXAMPLES

    text = (EXAMPLES / "rocker_form.toml").read_text(encoding="utf-8")
    lines = [ln for ln in text.splitlines() if not ln.startswith("name =")]
    path = tmp_path / "zh.toml"
    path.write_text('name = "插床进给凸轮"\n' + "\n".join(lines) + "\n", encoding="utf-8")
    r = subprocess.run([sys.executable, "-m", "cams.cli", "plot", str(path), "--out", str(tmp_path / "out"),
                        "--only", "motion"], capture_output=True, text=True)
    assert r.returncode == 0 and r.stderr == "", r.stderr
    assert (tmp_path / "out" / "插床进给凸轮_motion.png").stat().st_size > 1000


def test_motion_picture_names_its_axes_no_smaller_than_their_numbers(cams_by_name):
    """Each pane's quantity and unit (its y label) is printed at least as large as the numbers on its axis (it
    was 8 pt beside 10 pt numbers: about 6 pt on the report's page)."""
    fig = plot_motion(cams_by_name["rocker_force"].design)
    for ax in fig.axes:
        numbers = [t.get_fontsize() for t in ax.get_yticklabels()]
        assert numbers and ax.yaxis.label.get_fontsize() >= max(numbers), ax.get_ylabel()
