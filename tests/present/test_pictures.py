"""Pictures and the report, measured: no text over text, nothing cut off, each legend label once, no blank
pages, the animation's view holding the whole mechanism at every cam angle (issue 12, item 16).

The measures use matplotlib's own renderer (the extents of the drawn text
boxes) and the pixels of the rendered pages, not the code that places them.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg

from cams.cam import Cam
from cams.io.designfile import design_from_dict
from cams.present import plots
from tests.conftest import EXAMPLES, rocker_dict

ALL_EXAMPLES = sorted(p.stem for p in EXAMPLES.glob("*.toml"))


def _drawn_texts(fig):
    """The texts ``fig`` draws (titles, labels, tick labels in view, annotations, legends), with their extents
    in pixels, after a draw: laid out once and kept, at the dots per inch of the PNG, as the pictures are
    written (a draw with the layout engine still on would lay the figure out again, hiding a stale layout)."""
    plots.lay_out(fig, plots.DPI)
    fig.set_dpi(plots.DPI)
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    r = canvas.get_renderer()
    texts = list(fig.texts)
    for lg in fig.legends:
        texts += lg.get_texts()
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        texts += [ax.title, ax._left_title, ax._right_title, ax.xaxis.label, ax.yaxis.label, *ax.texts]
        for axis in (ax.xaxis, ax.yaxis):
            if not axis.get_visible():  # a twin's shared axis: hidden, its labels not drawn
                continue
            texts += [t.label1 for t in axis._update_ticks()] + [axis.get_offset_text()]
        if ax.get_legend() is not None:
            texts += ax.get_legend().get_texts()
    out = [(t, t.get_window_extent(r)) for t in texts if t.get_visible() and t.get_text().strip()]
    return out, fig.bbox


def text_faults(fig) -> list[str]:
    """Pairs of text boxes that overlap (more than a pixel each way), and texts reaching outside the figure."""
    texts, page = _drawn_texts(fig)
    faults = []
    for t, b in texts:
        if b.x0 < page.x0 - 1 or b.y0 < page.y0 - 1 or b.x1 > page.x1 + 1 or b.y1 > page.y1 + 1:
            faults.append(f"cut off: {t.get_text()!r}")
    for i, (t1, b1) in enumerate(texts):
        for t2, b2 in texts[i + 1:]:
            w = min(b1.x1, b2.x1) - max(b1.x0, b2.x0)
            h = min(b1.y1, b2.y1) - max(b1.y0, b2.y0)
            if w > 1 and h > 1:
                faults.append(f"overlap: {t1.get_text()!r} and {t2.get_text()!r}")
    return faults


def legends_over_curves(fig) -> list[str]:
    """The curves (lines of three or more points, of any axes over the legend's own) with a drawn point under a
    legend's box, measured on ``fig`` as drawn last (:func:`text_faults` draws it)."""
    faults = []
    for owner in fig.axes:
        legend = owner.get_legend()
        if legend is None:
            continue
        box = legend.get_window_extent()
        for ax in fig.axes:
            if not ax.get_window_extent().overlaps(owner.get_window_extent()):
                continue
            for line in ax.get_lines():
                xy = line.get_xydata()
                if not line.get_visible() or len(xy) < 3:
                    continue
                P = line.get_transform().transform(xy)
                under = (P[:, 0] > box.x0) & (P[:, 0] < box.x1) & (P[:, 1] > box.y0) & (P[:, 1] < box.y1)
                if under.any():
                    faults.append(f"legend over {line.get_label()!r} ({under.sum()} points)")
    return faults


def legend_duplicates(fig) -> list[str]:
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None] + list(fig.legends)
    dups = []
    for lg in legends:
        labels = [t.get_text() for t in lg.get_texts()]
        dups += sorted({lab for lab in labels if labels.count(lab) > 1})
    return dups


def _figures(cam):
    """Every picture of the cam's face (its pipeline's names), drawn as cams plot draws them."""
    from cams.present.faces import presenter

    figures = {name: plots.picture(kind, cam) for name, kind in presenter(cam).pictures.items()
               if plots.missing(kind, cam) is None}  # the forces: only a cam with [dynamics]
    if cam.given.optimize is not None:
        from cams.present.motion_plots import plot_motion_design

        figures["optimized"] = plot_motion_design(cam)
    return figures


@pytest.mark.parametrize("name", ALL_EXAMPLES)
def test_every_picture_of_every_example_reads(name):
    cam = Cam.from_file(EXAMPLES / f"{name}.toml")
    for which, fig in _figures(cam).items():
        assert text_faults(fig) == [], which
        assert legends_over_curves(fig) == [], which
        assert legend_duplicates(fig) == [], which


def _close_impacts():
    """Harmonic laws with a 1-degree dwell between rise and return: four soft impacts, two pairs 1 degree apart."""
    return design_from_dict(rocker_dict(motion=[
        {"phase": "rise", "law": "harmonic", "angle": 120}, {"phase": "dwell", "angle": 1},
        {"phase": "return", "law": "harmonic", "angle": 120}, {"phase": "dwell"}]))


def test_soft_impact_marks_do_not_write_over_each_other():
    fig = plots.plot_motion(_close_impacts())
    assert text_faults(fig) == []
    assert legend_duplicates(fig) == []
    # the impacts are still marked: one legend entry names them
    labels = [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]
    assert "soft impact (acceleration jump)" in labels


def test_a_long_name_wraps_its_titles_inside_the_figure():
    d = design_from_dict(rocker_dict(name="a rocker cam with a rather long descriptive name for its drawing office"))
    cam = Cam(d)
    for which, fig in _figures(cam).items():
        assert text_faults(fig) == [], which


@pytest.mark.parametrize("name", ALL_EXAMPLES)
def test_the_animation_view_holds_the_mechanism_at_every_angle(name):
    """Every artist of every frame (cam, groove's outer wall, roller, follower) lies inside the fixed view."""
    from matplotlib.figure import Figure

    cam = Cam.from_file(EXAMPLES / f"{name}.toml")
    profile = cam.profile
    lo, hi = plots._animation_box(cam, profile)
    for phi in np.linspace(0.0, 2 * np.pi, 37):
        ax = Figure().add_subplot()
        plots._draw(ax, cam, profile, phi)
        ax.relim()
        dl = ax.dataLim
        assert dl.x0 >= lo[0] and dl.y0 >= lo[1] and dl.x1 <= hi[0] and dl.y1 <= hi[1], (np.degrees(phi), dl, lo, hi)


@pytest.mark.parametrize("name", ["slotting_feed_cam", "rocker_form", "rocker_flat"])
def test_report_checks_are_named_in_words(name):
    """The checks are named in words, not by their internal names (profile_polygon, undercut_outer); the PDF's
    pages are measured in tests/present/test_report_pages.py."""
    import re

    from cams.present.report import report_sections

    sections = report_sections(Cam.from_file(EXAMPLES / f"{name}.toml"))
    names = [label for title, r in sections if title == "Checks" for label, _ in r]
    assert names and not any(re.fullmatch(r"[a-z]+(_[a-z]+)+", n) for n in names), names
