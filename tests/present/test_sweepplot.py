"""The sweep's chart read back from its artists: the plotted points are the rows, the front's are pareto()'s."""

from __future__ import annotations

import numpy as np
import pytest

from cams.present.sweepplot import save_chart, sweep_chart
from cams.sweep.pareto import pareto_front, parse_objectives, usable_mask
from laws.errors import InputError

COLS = {
    "R0": [20.0, 15.0, 12.0, 30.0, 11.0, 25.0, None],
    "max_pressure_angle_rise": [30.0, 36.0, 43.0, 31.0, 41.0, 28.0, None],
    "L": [110.0, 108.0, 107.0, 120.0, 106.0, 115.0, None],
    "error": [None, None, None, None, None, None, "no admissible centre"],
    "failures": [None, None, None, None, "curvature", None, None],
}
UNITS = {"R0": "mm", "max_pressure_angle_rise": "deg", "L": "mm"}


def _by_label(ax, start):
    return [c for c in [*ax.collections, *ax.lines] if c.get_label().startswith(start)]


@pytest.fixture(scope="module")
def chart():
    usable = usable_mask(COLS)
    front = pareto_front(COLS, parse_objectives("R0,max_pressure_angle_rise"), usable=usable)
    fig = sweep_chart(
        COLS, UNITS, "R0", "max_pressure_angle_rise", colour="L", usable=usable, front=front.rows, step=True
    )
    return fig, front


def test_designs_are_the_usable_rows_coloured_by_the_third_column(chart):
    fig, _ = chart
    ax = fig.axes[0]
    (designs,) = _by_label(ax, "designs")
    usable_rows = [0, 1, 2, 3, 5]  # row 4 has failures, row 6 an error
    assert designs.get_offsets().tolist() == [[COLS["R0"][i], COLS["max_pressure_angle_rise"][i]] for i in usable_rows]
    assert designs.get_array().tolist() == [COLS["L"][i] for i in usable_rows]
    assert fig.axes[1].get_ylabel() == "L (mm)"  # the colour bar, with its unit
    assert ax.get_xlabel() == "R0 (mm)" and ax.get_ylabel() == "max_pressure_angle_rise (deg)"


def test_unusable_rows_are_grey_crosses_in_the_legend(chart):
    fig, _ = chart
    ax = fig.axes[0]
    (bad,) = _by_label(ax, "unusable")
    assert bad.get_offsets().tolist() == [[11.0, 41.0]]  # row 4; row 6 has no values to draw
    assert "2" in bad.get_label() and "1 without values not drawn" in bad.get_label()
    assert np.allclose(bad.get_edgecolor()[0][:3], 0.6) or np.allclose(bad.get_facecolor()[0][:3], 0.6)
    assert any(t.get_text() == bad.get_label() for t in ax.get_legend().get_texts())


def test_front_points_and_staircase_are_paretos(chart):
    fig, front = chart
    ax = fig.axes[0]
    # by hand: usable (R0, angle) = (20,30) (15,36) (12,43) (30,31) (25,28); (30,31) is beaten by (20,30)
    assert sorted(front.rows.tolist()) == [0, 1, 2, 5]
    (pts,) = _by_label(ax, "Pareto front")
    assert sorted(map(tuple, pts.get_offsets().tolist())) == sorted(
        (COLS["R0"][i], COLS["max_pressure_angle_rise"][i]) for i in front.rows
    )
    (step,) = _by_label(ax, "front (step)")
    assert step.get_xdata().tolist() == [12.0, 15.0, 20.0, 25.0]  # by R0, increasing
    assert step.get_ydata().tolist() == [43.0, 36.0, 30.0, 28.0]
    assert step.get_drawstyle() == "steps-post"


def test_no_front_no_colour():
    fig = sweep_chart(COLS, UNITS, "L", "R0")
    ax = fig.axes[0]
    assert len(fig.axes) == 1 and _by_label(ax, "Pareto") == [] and _by_label(ax, "unusable") == []
    (designs,) = _by_label(ax, "designs")
    assert len(designs.get_offsets()) == 6  # every row with values (no usable mask given)


@pytest.mark.parametrize(("name", "magic"), [("c.png", b"\x89PNG"), ("c.svg", b"<?xml"), ("c.pdf", b"%PDF")])
def test_written_in_the_extensions_format(chart, tmp_path, name, magic):
    out = save_chart(chart[0], tmp_path / name)
    assert out.read_bytes()[: len(magic)] == magic
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]  # no temporary left


def test_bad_extension_and_columns_refused(chart, tmp_path):
    with pytest.raises(InputError, match=r"^--plot: .*\.png, \.svg or \.pdf"):
        save_chart(chart[0], tmp_path / "c.jpg")
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(InputError, match=r"^--x: 'Rb' is not a column; the columns are: R0, "):
        sweep_chart(COLS, UNITS, "Rb", "R0")
    with pytest.raises(InputError, match=r"^--colour: 'error' is not a column of numbers"):
        sweep_chart(COLS, UNITS, "R0", "L", colour="error")
