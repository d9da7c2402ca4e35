"""The pictures of issue 22, item 7, measured on their artists.

Each test reads what a picture draws (its lines, patches, legends, texts, as laid out by matplotlib's own
renderer) and compares it with what the design or the machine says, computed here another way: the phases'
spans from the motion program, the binding lines' sides from their names, the excess work by integrating the
moments' difference numerically.
"""

from __future__ import annotations

import re
import tomllib

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.lines import Line2D
from matplotlib.patches import Circle

from cams.cam import Cam
from cams.present import plots
from cams.present.faces import presenter
from tests.conftest import EXAMPLES, ROOT

ALL = sorted(p.stem for p in EXAMPLES.glob("*.toml"))
MACHINE = ROOT / "examples" / "machines" / "slotting_machine_forces.toml"


@pytest.fixture(scope="module")
def cams_by_name():
    return {name: Cam.from_file(EXAMPLES / f"{name}.toml") for name in ALL}


def _figures(cam):
    # the forces are drawn only for a design that has them (cams plot skips them otherwise)
    return {name: plots.picture(kind, cam) for name, kind in presenter(cam).pictures.items()
            if plots.missing(kind, cam) is None}


def _rollers(cams_by_name):
    return {n: c for n, c in cams_by_name.items() if "zone" in presenter(c).pictures}


def _legends(fig):
    return [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None] + list(fig.legends)


def _style(h) -> tuple:
    """What a legend sample looks like: colour, line style and width, marker; a patch's fill and edge."""
    from matplotlib.colors import to_rgba

    if isinstance(h, Line2D):
        return ("line", to_rgba(h.get_color()), h.get_linestyle(), round(h.get_linewidth(), 2), h.get_marker())
    return (
        "patch",
        tuple(np.round(h.get_facecolor(), 3)),
        tuple(np.round(h.get_edgecolor(), 3)),
        h.get_linestyle(),
        h.get_fill(),
    )


def _data_x(ax, line) -> np.ndarray:
    """The line's x in data units, whatever coordinates it was drawn in (an axhline's are the axes')."""
    xy = np.column_stack([line.get_xdata(), line.get_ydata()]).astype(float)
    return ax.transData.inverted().transform(line.get_transform().transform(xy))[:, 0]


# ---- a limit line only over the phases it limits -------------------------------------------------------------


def _spans(path, kind) -> list[tuple[float, float]]:
    """The cam-angle spans (deg) of the ``kind`` phases, from the file's [[motion]] table (the last dwell fills)."""
    motion = tomllib.loads(path.read_text(encoding="utf-8"))["motion"]
    start, out = 0.0, []
    for m in motion:
        angle = m.get("angle", 360.0 - sum(n.get("angle", 0.0) for n in motion))
        if m["phase"] == kind:
            out.append((start, start + angle))
        start += angle
    return out


def _check_limits(ax, path, closure):
    limits = tomllib.loads(path.read_text(encoding="utf-8"))["limits"]
    for kind, label in (("rise", "limit, rise"), ("return", "limit, return")):
        lines = [ln for ln in ax.get_lines() if ln.get_label() == label]
        spans = _spans(path, kind)
        if kind == "return" and closure == "force":  # force closure does not limit the return
            assert lines == []
            continue
        value = (
            limits["pressure_angle"]
            if kind == "rise"
            else limits.get("return_pressure_angle", limits["pressure_angle"])
        )
        assert lines, label
        covered = []
        for ln in lines:
            x = _data_x(ax, ln)
            assert np.allclose(ln.get_ydata(), value)
            # within one phase of its kind, and nowhere else
            assert any(a - 1e-6 <= x.min() and x.max() <= b + 1e-6 for a, b in spans), (label, x, spans)
            covered.append((x.min(), x.max()))
        for a, b in spans:  # and over the whole of each
            assert any(abs(lo - a) < 1e-6 and abs(hi - b) < 1e-6 for lo, hi in covered), (label, a, b, covered)


@pytest.mark.parametrize(
    "name", ["rocker_force", "rocker_form", "slotting_feed_cam", "translating_force", "translating_form_centric"]
)
def test_the_limit_line_runs_only_over_the_phases_it_limits(cams_by_name, name):
    cam = cams_by_name[name]
    ax = plots.plot_pressure(cam.solution).axes[0]
    _check_limits(ax, EXAMPLES / f"{name}.toml", cam.design.limits.closure)


def test_the_motion_designs_limit_line_runs_only_over_the_rise(cams_by_name):
    from cams.present.motion_plots import plot_motion_design

    cam = cams_by_name["translating_designed_rise"]
    fig = plot_motion_design(cam)
    panel = next(ax for ax in fig.axes if "pressure" in ax.get_ylabel())
    _check_limits(panel, EXAMPLES / "translating_designed_rise.toml", cam.design.limits.closure)


# ---- one legend sample per line style ------------------------------------------------------------------------


@pytest.mark.parametrize("name", ALL)
def test_each_legend_shows_each_style_once(cams_by_name, name):
    for which, fig in _figures(cams_by_name[name]).items():
        for lg in _legends(fig):
            styles = [_style(h) for h in lg.legend_handles]
            labels = [t.get_text() for t in lg.get_texts()]
            dups = [lab for lab, s in zip(labels, styles, strict=True) if styles.count(s) > 1]
            assert dups == [], (which, dups)


@pytest.mark.parametrize("name", ["rocker_force", "rocker_form", "translating_force", "slotting_feed_cam"])
def test_binding_lines_are_named_beside_a_sample_of_their_own_style(cams_by_name, name):
    """A t-t line is drawn solid and a t1-t1 line dashed: each is named beside a sample of that style."""
    cam = cams_by_name[name]
    fig = plots.plot_zone(cam.solution, tradeoff=cam.tradeoff)
    (lg,) = _legends(fig)
    drawn = {
        ln.get_linestyle() for ln in fig.axes[0].get_lines() if ln.get_color() == "#c53030" and len(ln.get_xdata()) == 2
    }
    for b in cam.solution.binding:
        want = "-" if b.line == "t-t" else "--"
        assert want in drawn
        entries = [
            (h, t.get_text())
            for h, t in zip(lg.legend_handles, lg.get_texts(), strict=True)
            if re.search(rf"(^|\s){re.escape(b.line)} at {np.degrees(b.phi):.4f}", t.get_text())
        ]
        assert len(entries) == 1, [t.get_text() for t in lg.get_texts()]
        assert entries[0][0].get_linestyle() == want, entries[0][1]


# ---- legends inside the figure -------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ALL)
def test_every_legend_lies_inside_its_figure(cams_by_name, name):
    for which, fig in _figures(cams_by_name[name]).items():
        fig.set_dpi(150)  # as saved
        fig.draw_without_rendering()
        for lg in _legends(fig):
            b, page = lg.get_window_extent(), fig.bbox
            assert b.x0 >= page.x0 - 1 and b.y0 >= page.y0 - 1 and b.x1 <= page.x1 + 1 and b.y1 <= page.y1 + 1, (
                which,
                b,
                page,
            )


# ---- zone pictures without empty space -----------------------------------------------------------------------


def _drawn_extent(ax) -> np.ndarray:
    """Corners of what the zone picture draws to scale: its curves and points and the base circle (the
    lines t-t and t1-t1, two points each, are unbounded and cut at the view's edge)."""
    pts = [
        np.column_stack([ln.get_xdata(), ln.get_ydata()]).astype(float)
        for ln in ax.get_lines()
        if len(ln.get_xdata()) not in (0, 2) and ln.get_transform() == ax.transData
    ]
    circles = [p for p in ax.patches if isinstance(p, Circle) and p.get_label().startswith("base circle")]
    for c in circles:
        pts.append(np.array(c.center) + c.radius * np.array([[-1.0, -1.0], [1.0, 1.0]]))
    P = np.concatenate(pts)
    P = P[np.all(np.isfinite(P), axis=1)]
    return np.array([P.min(axis=0), P.max(axis=0)])


#: The largest share of a zone picture (of its view, of its figure) left empty.
EMPTY = 0.25


@pytest.mark.parametrize(
    "name",
    [
        "rocker_force",
        "rocker_form",
        "slotting_feed_cam",
        "translating_force",
        "translating_form_centric",
        "translating_designed_rise",
    ],
)
def test_zone_view_fits_what_it_draws(cams_by_name, name):
    cam = cams_by_name[name]
    fig = plots.plot_zone(cam.solution, tradeoff=cam.tradeoff)
    ax = fig.axes[0]
    (x0, y0), (x1, y1) = _drawn_extent(ax)
    (a0, a1), (b0, b1) = ax.get_xlim(), ax.get_ylim()
    # everything drawn to scale is in view (the base circle whole) ...
    assert a0 <= x0 and x1 <= a1 and b0 <= y0 and y1 <= b1, ((x0, x1, y0, y1), (a0, a1, b0, b1))
    # ... and fills it, but for a margin
    assert (x1 - x0) * (y1 - y0) >= (1 - EMPTY) * (a1 - a0) * (b1 - b0)
    # the figure holds its drawing without a band of empty space (titles, axes and legend fill it)
    fig.set_dpi(150)
    fig.draw_without_rendering()
    drawn = fig.get_tightbbox()
    w, h = fig.get_size_inches()
    assert drawn.width * drawn.height >= (1 - EMPTY) * w * h, (drawn.bounds, (w, h))
    assert drawn.height >= 0.9 * h, (drawn.height, h)


# ---- a flat face names no pitch curve ------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["translating_flat", "rocker_flat"])
def test_flat_face_profile_legend_names_no_pitch_curve(cams_by_name, name):
    cam = cams_by_name[name]
    fig = plots.plot_profile(cam)
    texts = [t.get_text() for lg in _legends(fig) for t in lg.get_texts()]
    assert texts and not any("pitch" in t for t in texts), texts
    assert f"base circle R0 = {cam.solution.R0:.3f} mm" in texts


@pytest.mark.parametrize("name", ["translating_flat", "rocker_flat", "translating_flat_contact"])
def test_the_profile_picture_holds_the_whole_flat_face(cams_by_name, name):
    """The face's two ends (the solution's contact range on it, placed on the face's line at the picture's cam
    angle) and a rocker's pivot lie in the view: the face is drawn beside its data (its stroke off the cam's
    outline), which matplotlib's own limits pass over."""
    cam = cams_by_name[name]
    d, sol = cam.design, cam.solution
    rise = next(k for k, p in enumerate(d.program.phases) if p.kind == "rise")
    phi = d.program.starts[rise] + 0.5 * d.program.phases[rise].angle  # the picture's angle: mid first rise
    origin, direction = (v[0] for v in sol.face_line(np.array([phi])))
    points = [origin + c * direction for c in sol.face_range]
    if d.follower.kind == "rocker":
        points.append(np.zeros(2))
    ax = plots.plot_profile(cam).axes[0]
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    # and the stem or arm as drawn (the follower's lines, the legend's label)
    body = [ln for ln in ax.get_lines() if ln.get_label().startswith(("follower", "rocker"))]
    assert len(body) == 2
    points += [xy for ln in body for xy in np.column_stack([ln.get_xdata(), ln.get_ydata()])]
    for x, y in points:
        assert x0 <= x <= x1 and y0 <= y <= y1, ((x, y), (x0, x1, y0, y1))


def test_a_failing_title_keeps_the_pictures_own():
    cam = Cam.from_file(EXAMPLES / "rocker_force.toml")
    fig = plots.mark_failing(plots.plot_zone(cam.solution), "FAILS: test")
    text = fig.get_suptitle()
    assert text.startswith("FAILS: test\n") and "allowable-centre zone" in text


# ---- the machine's pictures ----------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def machine():
    from cams.machine.design import design_machine
    from cams.machine.kinetostatics import machine_forces
    from cams.machine.machinefile import load_machine

    spec = load_machine(MACHINE)
    res = design_machine(spec)
    return res, machine_forces(spec, found=res)


def test_cam_forces_put_newtons_and_newton_metres_on_axes_of_their_own(machine):
    from cams.present.machine_plots import cam_forces_figure

    res, forces = machine
    assert res.to_dict()["cam"]["follower"] == "rocker"
    fig = cam_forces_figure(forces.cam, follower="rocker")
    top = [
        ax
        for ax in fig.axes
        if any(ln.get_label().startswith("contact") for ln in ax.get_lines())
        or any("spring" in ln.get_label() for ln in ax.get_lines())
    ]
    assert len(top) == 2  # a twin: the same box, two scales
    assert np.allclose(top[0].get_position().bounds, top[1].get_position().bounds)
    newtons = next(ax for ax in top if any(ln.get_label().startswith("contact") for ln in ax.get_lines()))
    moments = next(ax for ax in top if ax is not newtons)
    assert re.search(r"\bN$", newtons.get_ylabel()) and "N m" not in newtons.get_ylabel()
    assert moments.get_ylabel().endswith("N m")
    (spring,) = [ln for ln in moments.get_lines() if "spring" in ln.get_label()]
    assert not any("spring" in ln.get_label() for ln in newtons.get_lines())
    # the spring moment drawn is the rocker's torsional spring F0 + k psi (N m), psi the swing (rad)
    sp = forces.spring
    assert np.allclose(np.sort(spring.get_ydata()), np.sort(sp.preload + sp.rate * forces.cam.q))
    torque = next(ax for ax in fig.axes if ax not in top)
    assert torque.get_ylabel().endswith("N m")


def test_hodograph_numbers_stand_apart(machine):
    from matplotlib.text import Annotation, Text

    from cams.present.machine_plots import hodograph_figure

    _, forces = machine
    fig = hodograph_figure(forces.linkage, marks=12)
    fig.draw_without_rendering()
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        notes = [t for t in ax.texts if isinstance(t, Annotation)]
        boxes = [Text.get_window_extent(t) for t in notes]  # the numbers' own boxes (not their leader lines)
        frame = ax.get_window_extent()
        for b in boxes:
            assert frame.x0 <= b.x0 and b.x1 <= frame.x1 and frame.y0 <= b.y0 and b.y1 <= frame.y1
        for i, b1 in enumerate(boxes):
            for b2 in boxes[i + 1 :]:
                assert min(b1.x1, b2.x1) <= max(b1.x0, b2.x0) or min(b1.y1, b2.y1) <= max(b1.y0, b2.y0), (
                    ax.get_title(),
                    notes[i].get_text(),
                )
        # every position is numbered, once ("6-12" stands for 6, 7, ..., 12)
        numbers = []
        for t in notes:
            for part in t.get_text().split(", "):
                lo, _, hi = part.partition("-")
                numbers += list(range(int(lo), int(hi or lo) + 1))
        assert sorted(numbers) == list(range(1, 13)), ax.get_title()


def _excess_work(phi, Md, Mr, J, omega_m, delta) -> float:
    """The excess work (J) of the moments and the inertia sampled at ``phi``: the energy by the trapezoidal
    rule, then the Wittenbauer segment max(dE - J w_max^2 / 2) - min(dE - J w_min^2 / 2)."""
    dE = np.concatenate([[0.0], np.cumsum(0.5 * np.diff(phi) * ((Md - Mr)[1:] + (Md - Mr)[:-1]))])
    hi, lo = omega_m * (1 + delta / 2), omega_m * (1 - delta / 2)
    return float(np.max(dE - 0.5 * J * hi**2) - np.min(dE - 0.5 * J * lo**2))


def _marked_excess_work(fig) -> float:
    texts = [t.get_text() for ax in fig.axes for t in ax.texts] + [lg.get_title().get_text() for lg in _legends(fig)]
    (hit,) = [m for t in texts for m in re.findall(r"ΔE = ([0-9.eE+-]+) J", t)]
    return float(hit)


def test_flywheel_marks_the_excess_work_of_its_moments(machine):
    from cams.present.machine_plots import flywheel_figure

    _, forces = machine
    fw = forces.flywheel
    fig = flywheel_figure(fw)
    want = _excess_work(fw.phi, fw.driving, fw.resisting, fw.inertia, fw.omega_mean, fw.delta)
    assert _marked_excess_work(fig) == pytest.approx(want, rel=6e-4)
    # the double arrow spans it
    (arrow,) = [t for ax in fig.axes for t in ax.texts if t.arrow_patch is not None]
    assert abs(arrow.xy[1] - arrow.xyann[1]) == pytest.approx(want, rel=1e-6)


def test_flywheel_of_given_moments_marks_their_excess_work():
    """Mr = 100 sin(phi) + 40 sin(2 phi) N m, J = 2 + 0.5 cos(phi) kg m^2: the energy integrated here from the
    closed-form moments on a grid of its own."""
    from cams.machine.flywheel import flywheel
    from cams.present.machine_plots import flywheel_figure

    def Mr(p):
        return 100 * np.sin(p) + 40 * np.sin(2 * p)

    def J(p):
        return 2 + 0.5 * np.cos(p)

    phi = np.linspace(0, 2 * np.pi, 720, endpoint=False)
    fw = flywheel(phi, Mr(phi), J(phi), rpm=300, delta=0.05, interpolation="spline")
    fig = flywheel_figure(fw)
    x = np.linspace(0, 2 * np.pi, 200001)
    want = _excess_work(x, np.zeros_like(x), Mr(x), J(x), np.pi * 300 / 30, 0.05)
    assert _marked_excess_work(fig) == pytest.approx(want, rel=6e-4)


def test_no_legend_of_a_machine_picture_covers_a_curve(machine):
    """The flywheel's work and speed panes end high at the right, where their legends were (no drawn point of a
    curve lies under a legend's box, in any picture of the machine)."""
    from cams.present.machine_plots import machine_figures
    from tests.present.test_pictures import legends_over_curves

    res, forces = machine
    for name, fig in machine_figures(None, forces, title="machine").items():
        fig.draw_without_rendering()
        assert legends_over_curves(fig) == [], name
