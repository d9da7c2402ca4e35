"""Pictures: the allowable-centre zone, motion diagrams, pressure angle, the forces at the cam.

A flat-faced follower's cam has no zone; its pictures are the
motion diagrams, the pressure angle (:func:`plot_flat_pressure`, fixed by the
geometry), the radius of curvature with the contact's travel on the face
(:func:`plot_curvature`) and the profile (:func:`plot_profile`, face drawn).

matplotlib is imported inside the functions only, and figures are built with
``matplotlib.figure.Figure`` (no pyplot state). Every function returns the
Figure; :func:`save` writes it as PNG and SVG. Pictures take results and data
objects and only draw them.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from pathlib import Path

import numpy as np

from cams.kinematics.inversion import (
    invert_phase,
    pressure_angle,
    smallest_cam_radius,
)
from cams.present.mechanism import radii_label
from cams.words import binding_text, phase_words
from laws.units import TWO_PI, rpm_to_omega, turn_degrees

__all__ = ["plot_zone", "plot_motion", "plot_pressure", "plot_flat_pressure", "plot_curvature", "plot_profile",
           "plot_forces", "picture", "PICTURES", "NEEDS", "missing", "no_forces", "plot_contact", "no_contact",
           "no_vibration", "plot_vibration", "lay_out",
           "animate_profile", "save", "prepare", "rendered", "write_rendered",
           "FORMATS", "DPI", "EFFORT", "fix_layout", "mark_failing", "draw_limits", "legend_once", "legend_above",
           "A4_WIDTH_IN"]

#: Figure width that reads well on an A4 page (inches).
A4_WIDTH_IN = 7.5


def _figure(w=A4_WIDTH_IN, h=5.5):
    from matplotlib.figure import Figure

    return Figure(figsize=(w, h), layout="constrained")


def _wrapped(text: str, width_in: float, fontsize: float) -> str:
    """``text`` broken into lines that fit ``width_in`` inches at ``fontsize`` points (a glyph ~0.55 em wide)."""
    import textwrap

    return "\n".join(textwrap.wrap(text, max(20, int(width_in * 72 / (0.55 * fontsize)) - 4)))


def _title(ax, text: str, width_in: float = A4_WIDTH_IN, fontsize: float = 11.0) -> None:
    """Set ``ax``'s title, wrapped onto lines that fit the figure's width (a long name is not cut off)."""
    ax.set_title(_wrapped(text, width_in, fontsize), fontsize=fontsize)


def _suptitle(fig, text: str, fontsize: float = 11.0) -> None:
    """The figure's title, centred over the whole figure and wrapped to its width (for axes squeezed by a
    legend beside them, whose own title would be wider than they are)."""
    fig.suptitle(_wrapped(text, fig.get_figwidth(), fontsize), fontsize=fontsize)


def _unique_handles(ax) -> tuple[list, list[str]]:
    """Legend handles and labels of ``ax``, each label once (its first artist stands for all of them)."""
    handles, labels = ax.get_legend_handles_labels()
    first: dict[str, object] = {}
    for h, lab in zip(handles, labels, strict=True):
        first.setdefault(lab, h)
    return list(first.values()), list(first)


def _mark_phases(ax, starts) -> None:
    """Draw a dotted line at each phase's start (``starts``, radians from the timing datum) on ``ax``, whose
    abscissa (the cam angle, degrees) is set to one turn, 0 to 360."""
    for s in starts:
        ax.axvline(np.degrees(s), color="0.6", lw=0.6, ls=":")
    ax.set_xlim(0, 360)


def _by_angle(phi):
    """The cam angles ``phi`` (rad, one turn) in degrees, ascending, and ``finite(v)``: a quantity sampled at
    ``phi`` put in that order, its non-finite values NaN (a break in the curve, where a force is unbounded)."""
    x = np.degrees(phi)
    o = np.argsort(x)

    def finite(v):
        v = np.asarray(v, dtype=float)[o]
        return np.where(np.isfinite(v), v, np.nan)

    return x[o], finite


def legend_once(ax, **kw):
    """A legend with each label once."""
    return ax.legend(*_unique_handles(ax), **kw)


def legend_above(ax, *also, ncol: int = 3):
    """The legend of ``ax`` (and of the axes ``also`` drawn over it, a twin's other scale) above it, each label
    once, in one frameless band: it covers none of the curves, wherever they run (the figure's title then goes
    over the whole figure, :func:`_suptitle`; constrained layout makes room between them)."""
    handles: list = []
    labels: list[str] = []
    for a in (ax, *also):
        h, lab = _unique_handles(a)
        handles += h
        labels += lab
    return ax.legend(handles, labels, fontsize=7, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=ncol,
                     frameon=False)


def _legend_below(fig, ax, ncol: int = 2):
    """The legend of ``ax`` under the figure's axes, each label once: it neither covers the drawing nor
    squeezes it sideways (constrained layout makes room for it)."""
    return fig.legend(*_unique_handles(ax), loc="outside lower center", ncol=ncol, fontsize=7)


def _fit_height(fig, ax, *, beside=None, max_h: float = 9.0, min_h: float = 3.0, rounds: int = 6,
                guess: float | None = None):
    """Set the height of ``fig`` (its width kept) so that what it draws fills it: no band of empty figure
    above and below a wide drawing of a fixed aspect (``ax``), nor beside a tall one.

    The height stays within ``[min_h, max_h]`` inches and above what the legend ``beside`` the axes needs.
    Each round lays the figure out (as at :data:`DPI`, :func:`_execute_layout`) and takes up the difference
    between the figure and the box around everything drawn. The last round's layout is the figure's
    (:func:`lay_out` keeps it). ``guess`` (inches) is where the first round starts, when the caller can tell
    about where the rounds end (each round costs a layout; the rounds still decide). Returns
    ``fig``, which keeps the fitting as ``fig.refit`` for a caller that adds a title afterwards
    (:func:`mark_failing`).
    """
    if guess is not None:
        fig.set_size_inches(fig.get_size_inches()[0], float(np.clip(guess, min_h, max_h)))

    def refit():
        drawn = None  # the box around what is drawn, as laid out at the figure's present size
        for _ in range(rounds):
            drawn = _execute_layout(fig, DPI)
            w, h = fig.get_size_inches()
            spare_h, spare_w = h - drawn.height - 0.1, w - drawn.width - 0.1
            if spare_h > 0.05:  # the axes span the width: the spare height goes
                new = h - spare_h
            elif spare_h < -0.02:  # what is drawn reaches past the figure (a start below the fit): that much taller
                new = h - spare_h
            elif spare_w > 0.05:  # the axes span the height: taller until they span the width
                box = ax.get_position()
                new = h + spare_w * (box.height * h) / (box.width * w)
            else:
                break
            floor = min_h if beside is None else max(min_h, beside.get_window_extent().height / fig.dpi + 1.0)
            new = float(np.clip(new, floor, max_h))
            if abs(new - h) < 0.02:
                break
            fig.set_size_inches(w, new)
            drawn = None
        # one layout after a new size starts from the decorations where the old size left them: beside a view of
        # fixed aspect the axis label can end past the figure's edge (cut off). Laid out again until it is inside.
        for _ in range(3):
            if drawn is not None and _inside(drawn, fig):
                break
            drawn = _execute_layout(fig, DPI)
        return fig

    fig.refit = refit
    return refit()


def _inside(box, fig) -> bool:
    """Whether ``box`` (inches, :func:`_execute_layout`) lies within ``fig``'s edges (to a hundredth of an inch)."""
    w, h = fig.get_size_inches()
    return box.x0 >= -0.01 and box.y0 >= -0.01 and box.x1 <= w + 0.01 and box.y1 <= h + 0.01


def _execute_layout(fig, dpi: float):
    """Compute ``fig``'s constrained layout as at ``dpi`` (dots per inch) and return the box around everything it
    draws (inches); the figure remembers its size and ``dpi`` for :func:`lay_out`. A figure without a layout
    engine is only measured."""
    before = fig.dpi
    fig.dpi = dpi
    try:
        engine = fig.get_layout_engine()
        if engine is not None:
            engine.execute(fig)
            fig._cams_laid_out = (*fig.get_size_inches(), dpi)
        return fig.get_tightbbox()
    finally:
        fig.dpi = before


def fix_layout(fig):
    """Keep the positions ``fig``'s constrained layout computed when it was last drawn: its later draws (another
    format, the frames of an animation) skip the layout, which costs a third of a draw. Returns ``fig``; call it
    once the figure's content and size are final and it was drawn."""
    if fig.get_layout_engine() is not None:
        fig.set_layout_engine("none")
    return fig


def lay_out(fig, dpi: float):
    """Compute ``fig``'s constrained layout once, as at ``dpi`` (dots per inch), and keep it (:func:`fix_layout`).

    ``savefig`` of a figure with a layout engine draws it twice, once to lay it out and once to render it, each
    time computing the layout; a figure laid out here is rendered by one drawing. A figure whose last fitting
    round (:func:`_fit_height`) laid it out at its present size and ``dpi`` keeps that layout. Returns ``fig``."""
    if fig.get_layout_engine() is None:
        return fig
    if getattr(fig, "_cams_laid_out", None) != (*fig.get_size_inches(), dpi):
        _execute_layout(fig, dpi)
    return fix_layout(fig)


#: The formats every picture is written in (:func:`save`), at :data:`DPI` for PNG.
FORMATS = ("png", "svg")
#: Dots per inch of a PNG picture.
DPI = 150


def prepare() -> None:
    """Import what drawing a picture needs and load the default font: done once before the pictures are drawn in
    processes forked from this one (:mod:`cams.present.forked`), each child inherits them instead of loading its
    own."""
    import matplotlib.backends.backend_agg  # PNG
    import matplotlib.backends.backend_svg  # SVG
    import matplotlib.figure  # noqa: F401  (the figures)
    from matplotlib.font_manager import FontProperties, findfont, get_font

    get_font(findfont(FontProperties()))


def rendered(fig, formats: tuple[str, ...] = FORMATS) -> dict[str, bytes]:
    """``fig`` drawn as each of ``formats`` (PNG at :data:`DPI`): the files' bytes by format.

    The layout is computed once, as at :data:`DPI` (:func:`lay_out`), and kept for every format: the figure is
    final when it is rendered."""
    import io

    lay_out(fig, DPI)
    files = {}
    for ext in formats:
        buf = io.BytesIO()
        fig.savefig(buf, format=ext, dpi=DPI)
        files[ext] = buf.getvalue()
    return files


def write_rendered(files: dict[str, bytes], stem: str | Path) -> list[Path]:
    """Write the files of :func:`rendered` as ``stem.<format>``, each whole or not at all; returns their paths."""
    from cams.io.files import atomic_write

    stem = Path(stem)
    return [atomic_write(stem.with_suffix(f".{ext}"), "--out", partial(_write_bytes, data=data))
            for ext, data in files.items()]


def _write_bytes(path, *, data: bytes) -> None:
    Path(path).write_bytes(data)


def save(fig, stem: str | Path, formats: tuple[str, ...] = FORMATS) -> list[Path]:
    """Write ``fig`` as ``stem.png`` and ``stem.svg`` (:func:`rendered`), each whole or not at all."""
    return write_rendered(rendered(fig, formats), stem)


def mark_failing(fig, title: str):
    """Title ``fig`` as a failing cam's picture (``title`` from :meth:`cams.assess.Assessment.title`); "" leaves it.

    The title goes above the figure's own titles, in red (a figure title already there follows it on the next
    line); returns ``fig``, refitted to its drawing when it was fitted (:func:`_fit_height`).
    """
    if title:
        below = fig._suptitle.get_text() if fig._suptitle is not None else ""
        fig.suptitle(title + (f"\n{below}" if below else ""), color="#c00000", fontsize="medium", weight="bold")
        refit = getattr(fig, "refit", None)
        if refit is not None:
            refit()
    return fig


def plot_zone(result, *, tradeoff=None, n_lines: int = 6, samples: int = 180):
    """The allowable-centre zone of a solved design (seed 001, figure 3.13).

    Draws the follower's path with the analogue-velocity diagram (psi' l on the
    rocker's arc, or ds/dphi across a translating follower's axis), a subset of
    the t-t and t1-t1 lines with the binding ones highlighted, the admissible
    zone shaded (and the zone without K_C when K_C > 1), the chosen centre, the
    R0 circle, the fixed-L circle when given, and the R0-L trade-off curve.

    Parameters
    ----------
    result : cams.solve.SolveResult
    tradeoff : optimize.tradeoff.TradeOff, optional
    n_lines : int
        Positions per constrained phase whose lines are drawn.
    """
    from matplotlib.patches import Circle, Polygon

    from optimize.drawing import zone_drawing

    d = result.design
    f = d.follower
    # the view holds what is drawn to scale: the centre with its base circle, the analogue diagram, the pivot
    # and the trade-off curve (the lines and the zone are unbounded: they are cut at the view's edge)
    circle = np.asarray(result.centre, float) + result.R0 * np.array([[-1.0, -1.0], [1.0, 1.0]])
    extra = (circle,) if tradeoff is None else (circle, tradeoff.centres)
    zd = zone_drawing(d, result.centre, binding=tuple((b.phi, b.side) for b in result.binding),
                      samples=samples, n_lines=n_lines, extra_points=extra)
    fig = _figure()
    ax = fig.add_subplot()
    if zd.polygon_k1 is not None and len(zd.polygon_k1):
        ax.add_patch(Polygon(zd.polygon_k1, closed=True, fc="#cfe3f7", ec="none", label="zone, K_C = 1"))
    if len(zd.polygon):
        lab = f"allowable zone (K_C = {d.limits.safety_factor:g})" if d.limits.safety_factor != 1 else "allowable zone"
        ax.add_patch(Polygon(zd.polygon, closed=True, fc="#8fc1ee", ec="#2b6cb0", lw=0.8, alpha=0.8, label=lab))
    for _phi, side, p0, p1, binding in zd.lines:
        style = dict(color="#c53030", lw=1.4) if binding else dict(color="0.55", lw=0.5)
        ax.plot([p0[0], p1[0]], [p0[1], p1[1]], ls="-" if side == 0 else "--", **style)
    ax.plot([], [], color="0.55", lw=0.5, label="t-t lines")
    ax.plot([], [], color="0.55", lw=0.5, ls="--", label="t1-t1 lines")
    # one legend sample per style: the binding t-t lines solid, the t1-t1 dashed, each named
    for side, ls in ((0, "-"), (1, "--")):
        named = [binding_text({"line": b.line, "phi": float(np.degrees(b.phi)), "phase": b.phase,
                               "phase_kind": d.program.phases[b.phase].kind})
                 for b in result.binding if b.side == side]
        if named:
            ax.plot([], [], color="#c53030", lw=1.4, ls=ls, label="\n".join(f"binding {n}" for n in named))
    for kind in dict.fromkeys(c.kind for c in zd.curves):
        col = "#2f855a" if kind == "rise" else "#b7791f"
        mine = [c for c in zd.curves if c.kind == kind]
        for c in mine:
            ax.plot(c.A[:, 0], c.A[:, 1], color="k", lw=1.0)
            ax.plot(c.D[:, 0], c.D[:, 1], color=col, lw=1.2)
        ax.plot([], [], color=col, lw=1.2,
                label="analogue diagram, " + "; ".join(phase_words(c.kind, c.phase) for c in mine))
    A0 = f.position(0.0)
    if f.kind == "rocker":
        ax.plot([0, A0[0]], [0, A0[1]], color="k", lw=2)
        ax.plot(0, 0, "ko", ms=4)
        ax.annotate("O1", (0, 0), textcoords="offset points", xytext=(4, 4))
    else:
        ax.axvline(0.0, color="k", lw=0.8, ls="-.", label="follower axis")
        if result.offset is not None:
            # the offset e: from the cam centre across to the follower's axis
            ax.annotate("", xy=(0.0, result.centre[1]), xytext=tuple(result.centre),
                        arrowprops=dict(arrowstyle="<->", color="#6b46c1", lw=1.2))
            ax.plot([], [], color="#6b46c1", lw=1.2, label=f"offset e = {result.offset:.3f} mm")
    ax.plot(*A0, "ko", ms=4)
    ax.annotate("A0", A0, textcoords="offset points", xytext=(4, -10))
    ax.plot(*result.centre, "o", color="#c53030", ms=6, label="cam centre O")
    ax.add_patch(Circle(result.centre, result.R0, fill=False, ls=":", color="#c53030",
                        label=radii_label(result.R0, smallest_cam_radius(d, result.centre)[0])))
    if d.limits.centre_distance is not None and f.kind == "rocker":
        ax.add_patch(Circle((0, 0), d.limits.centre_distance, fill=False, ls="-.", color="0.3",
                            label=f"L = {d.limits.centre_distance:g} mm"))
    if tradeoff is not None:
        ax.plot(tradeoff.centres[:, 0], tradeoff.centres[:, 1], color="#6b46c1", lw=2, label="R0-L trade-off")
    x0, y0, x1, y1 = zd.box
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")
    ax.grid(True, lw=0.3)
    _suptitle(fig, f"{d.name}: allowable-centre zone")
    # outside the drawing (the zone and the centre can lie anywhere in the view), inside the figure: beside a
    # tall view, below a wide one; the figure's height then fits the view
    if (y1 - y0) >= 0.9 * (x1 - x0):
        legend = fig.legend(*_unique_handles(ax), loc="outside right center", fontsize=7)
        return _fit_height(fig, ax, beside=legend)
    fig.legend(*_unique_handles(ax), loc="outside lower center", ncol=2, fontsize=7)
    return _fit_height(fig, ax)


def plot_motion(design, *, n: int = 721):
    """Displacement, velocity, acceleration and jerk against the cam angle.

    Analogues (per radian of cam angle) without a cam speed; time derivatives
    when ``design.rpm`` is set. Phase boundaries are drawn; velocity jumps
    (hard impacts) and acceleration jumps (soft impacts) are marked when
    :mod:`laws.diagnostics` reports them.
    """
    prog = design.program
    # evaluate inside each phase, both ends included, so joints show their jumps
    xs, ys = [], []
    for i, p in enumerate(prog.phases):
        u = np.linspace(0.0, 1.0, max(int(n * p.angle / TWO_PI), 8))
        m = prog.evaluate_phase(i, u)
        xs.append(prog.starts[i] + u * p.angle)
        ys.append(np.stack([m.s, m.ds, m.d2s, m.d3s]))
        xs.append([np.nan])
        ys.append(np.full((4, 1), np.nan))
    x = np.degrees(np.concatenate(xs))
    Y = np.concatenate(ys, axis=1)
    rocker = design.follower.kind == "rocker"
    unit = "rad" if rocker else "mm"
    if design.rpm:
        w = rpm_to_omega(design.rpm)
        Y = Y * np.array([1, w, w**2, w**3])[:, None]
        labels = [f"{'swing' if rocker else 'stroke'}, {unit}", f"velocity, {unit}/s",
                  f"acceleration, {unit}/s²", f"jerk, {unit}/s³"]
    else:
        labels = [f"{'swing' if rocker else 'stroke'}, {unit}", f"ds/dφ, {unit}/rad",
                  f"d²s/dφ², {unit}/rad²", f"d³s/dφ³, {unit}/rad³"]
    if rocker:
        Y[0] = np.degrees(Y[0])
        labels[0] = "swing ψ, deg"
    fig = _figure(h=8.0)
    axes = fig.subplots(4, 1, sharex=True)
    from laws.diagnostics import find_impacts

    impacts = find_impacts(prog)
    for k, ax in enumerate(axes):
        ax.plot(x, Y[k], color="#2b6cb0", lw=1.2)
        ax.set_ylabel(labels[k])  # the size of the other pictures' labels, not below the numbers' on the axis
        ax.grid(True, lw=0.3)
        _mark_phases(ax, prog.starts)
    # impacts as marked lines named once in a legend: text labels at each would pile up where impacts are close
    for imp in impacts:
        k = 1 if imp.kind == "hard" else 2
        what = "hard impact (velocity jump)" if imp.kind == "hard" else "soft impact (acceleration jump)"
        axes[k].axvline(np.degrees(imp.phi), color="#c53030", lw=1.0, label=what)
    for k in (1, 2):
        if axes[k].get_legend_handles_labels()[1]:
            legend_once(axes[k], fontsize=7, loc="upper right")
    axes[-1].set_xlabel("cam angle φ, deg")
    _title(axes[0], f"{design.name}: motion diagrams" + (f" at {design.rpm:g} rpm" if design.rpm else " (analogues)"))
    return fig


def plot_pressure(result, *, n: int = 721):
    """Pressure angle against the cam angle with the limits drawn (from the finished design, the kernel's)."""
    d = result.design
    prog = d.program
    fig = _figure(h=3.8)
    ax = fig.add_subplot()
    for i, p in enumerate(prog.phases):
        if p.kind == "dwell":
            continue
        u = np.linspace(0.0, 1.0, max(int(n * p.angle / TWO_PI), 8))
        g = pressure_angle(invert_phase(d, result.centre, i, u))
        ax.plot(np.degrees(prog.starts[i] + u * p.angle), np.degrees(g),
                color="#2f855a" if p.kind == "rise" else "#b7791f", lw=1.3, label=p.kind)
    draw_limits(ax, d)
    _mark_phases(ax, prog.starts)
    ax.set_xlabel("cam angle φ, deg")
    ax.set_ylabel("pressure angle γ, deg")
    _title(ax, f"{d.name}: pressure angle")
    ax.grid(True, lw=0.3)
    legend_once(ax, fontsize=8)
    return fig


def draw_limits(ax, design) -> None:
    """The allowable pressure angle drawn over each phase it limits, and nowhere else (degrees on ``ax``).

    The rise's limit over every rise; the return's over every return under form closure (force closure does
    not limit the return: nothing is drawn there, and the legend says so). Each kind is named once in the
    legend.
    """
    prog = design.program
    for i, lim in design.constrained_phases():
        kind = prog.phases[i].kind
        a = np.degrees(prog.starts[i])
        style = (dict(color="#c53030", ls="--") if kind == "rise" else dict(color="#c05621", ls="-."))
        ax.plot([a, a + np.degrees(prog.phases[i].angle)], [np.degrees(lim)] * 2, lw=1, **style,
                label=f"limit, {kind}")
    limited = {i for i, _ in design.constrained_phases()}
    if any(p.kind == "return" and i not in limited for i, p in enumerate(prog.phases)):
        ax.plot([], [], ls="none", label=f"return: no limit ({design.limits.closure} closure)")  # a note, no sample


def plot_flat_pressure(solution, *, n: int = 721):
    """Pressure angle of a flat-faced follower against the cam angle (fixed by the geometry).

    Parameters
    ----------
    solution : cams.faces.result.SolveResult
        A flat face's sized cam (its detail an :class:`optimize.flat.FlatFaceSolution`, read through it).
    """
    d = solution.design
    c = solution.curves(n)
    fig = _figure(h=4.0)
    ax = fig.add_subplot()
    ax.plot(np.degrees(c["phi"]), np.degrees(c["pressure"]), color="#2f855a", lw=1.3, label="pressure angle")
    why = ("face perpendicular to the axis" if d.follower.kind == "translating"
           else f"face offset {d.follower.face_offset:g} mm from the pivot")
    _mark_phases(ax, d.program.starts)
    top = max(5.0, 1.15 * np.degrees(np.nanmax(c["pressure"])))
    ax.set_ylim(-0.05 * top, top)
    ax.set_xlabel("cam angle φ, deg")
    ax.set_ylabel("pressure angle γ, deg")
    _title(ax, f"{d.name}: pressure angle, fixed by the geometry ({why})")
    ax.grid(True, lw=0.3)
    legend_once(ax, fontsize=8)
    return fig


def plot_curvature(solution, *, n: int = 721):
    """A flat-faced follower's cam: radius of curvature with its limit, and the contact's travel on the face.

    Parameters
    ----------
    solution : cams.faces.result.SolveResult
        A flat face's sized cam (its detail an :class:`optimize.flat.FlatFaceSolution`, read through it).
    """
    d = solution.design
    c = solution.curves(n)
    x = np.degrees(c["phi"])
    fig = _figure(h=6.0)
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    ax1.plot(x, c["rho"], color="#2b6cb0", lw=1.3, label="radius of curvature ρ")
    ax1.axhline(d.min_radius, color="#c53030", ls="--", lw=1, label=f"limits.min_radius = {d.min_radius:g} mm")
    ax1.plot(turn_degrees(solution.min_rho_at), solution.min_rho, "o", color="#c53030", ms=5,
             label=f"smallest ρ = {solution.min_rho:.3f} mm at {turn_degrees(solution.min_rho_at):.1f}°")
    ax1.set_ylim(min(0.0, np.nanmin(c["rho"])), 1.1 * np.nanmax(c["rho"]))
    ax1.set_ylabel("ρ, mm")
    _title(ax1, f"{d.name}: radius of curvature (R0 = {solution.R0:.3f} mm) and contact on the face")
    where = "from the axis" if d.follower.kind == "translating" else "from the pivot's foot"
    ax2.plot(x, c["contact"], color="#6b46c1", lw=1.3, label=f"contact position {where}")
    lo, hi = solution.face_range
    for v in (lo, hi):
        ax2.axhline(v, color="#6b46c1", ls=":", lw=0.8)
    ax2.plot([], [], color="#6b46c1", ls=":", lw=0.8, label=f"face width {solution.face_width:.3f} mm")
    ax2.set_ylabel("contact, mm")
    ax2.set_xlabel("cam angle φ, deg")
    for ax in (ax1, ax2):
        ax.grid(True, lw=0.3)
        legend_once(ax, fontsize=7, loc="best")
        _mark_phases(ax, d.program.starts)
    return fig


def no_forces(cam) -> str | None:
    """Why ``cam`` (a :class:`cams.cam.Cam`) has no forces to draw, or None when it has (:func:`plot_forces`)."""
    if cam.design.dynamics is None:
        return ("the design has no [dynamics] table (the follower's mass, load and spring); add one, with cam.rpm, "
                "to draw the forces")
    if cam.forces is None:
        return f"no forces to draw: {cam.forces_note}"
    return None


def plot_forces(cam):
    """The forces at a force-closed cam over one turn: contact force, spring and load, camshaft torque.

    Read through the face's pipeline (:attr:`cams.cam.Cam.forces`, a
    :class:`cams.dynamics.forces.DesignForces`): the contact force ``N`` (N);
    the closing spring ``F0 + k q`` and the constant load ``P`` (N, on the
    same axes; a rocker's are moments about its pivot, N m, on axes of their
    own); the camshaft torque (N m, positive: the shaft drives the cam). The
    abscissa is the cam angle from the timing datum (the start of the first
    ``[[motion]]`` row), degrees. At a rigid impact (a velocity jump) the
    force is unbounded: the curves break there and a dotted line marks it.

    Raises
    ------
    ValueError
        ``cam`` has no forces (:func:`no_forces` says why).
    """
    why = no_forces(cam)
    if why is not None:
        raise ValueError(why)
    df = cam.forces
    cf = df.forces
    d = cam.design
    rocker = d.follower.kind == "rocker"
    x, finite = _by_angle(cf.phi)

    load = float(d.dynamics.dynamics.load)
    fig = _figure(h=7.5 if rocker else 6.0)
    axes = fig.subplots(3 if rocker else 2, 1, sharex=True)
    ax_n, ax_t = axes[0], axes[-1]
    ax_n.plot(x, finite(cf.contact), color="#2b6cb0", lw=1.4, label="contact force")
    ax_s = axes[1] if rocker else ax_n
    what = "moment about the pivot" if rocker else "force"
    unit = "N·m" if rocker else "N"
    ax_s.plot(x, finite(cf.spring), color="#2f855a", lw=1.2, ls="--",
              label=f"spring {what} F0 + k q (k = {df.spring.rate:.4g} {'N·m/rad' if rocker else 'N/m'}, "
                    f"F0 = {df.spring.preload:.4g} {unit})")
    ax_s.plot(x, np.full_like(x, load), color="#b7791f", lw=1.2, ls="-.", label=f"load P = {load:.4g} {unit}")
    ax_t.plot(x, finite(cf.torque), color="#c53030", lw=1.3, label="camshaft torque (+: the shaft drives)")
    ax_t.axhline(0.0, color="0.3", lw=0.6)
    ax_n.set_ylabel("contact force, N")
    if rocker:
        ax_s.set_ylabel("moment about the pivot, N·m")
    else:
        ax_n.set_ylabel("force, N")
    ax_t.set_ylabel("camshaft torque, N·m")
    ax_t.set_xlabel("cam angle φ from the timing datum, deg")
    for k, imp in enumerate(cf.impacts):
        for ax in axes:
            ax.axvline(turn_degrees(imp.phi), color="#c53030", lw=1.0, ls=":",
                       label="rigid impact (force unbounded or contact lost)" if k == 0 else None)
    for ax in axes:
        ax.grid(True, lw=0.3)
        _mark_phases(ax, d.program.starts)
    for ax in axes[1:]:
        legend_once(ax, fontsize=7, loc="best")
    legend_above(ax_n)  # a translating follower's pane holds three curves: no room inside that covers none
    _suptitle(fig, f"{d.name}: forces at the cam at {cf.rpm:.4g} rpm")
    return fig


def no_contact(cam) -> str | None:
    """Why ``cam`` has no contact stress to draw, or None when it has (:func:`plot_contact`)."""
    if cam.design.contact is None:
        return ("the design has no [contact] table (the materials, and [cam] width); add one, with [dynamics] and "
                "cam.rpm, to draw the contact stress and the film")
    if cam.contact is None:
        return f"no contact to draw: {cam.contact_note}"
    return None


def plot_contact(cam):
    """The contact over one turn: the maximum Hertz pressure p0 (MPa) with the allowable, and the lubricant's
    minimum film thickness (µm) with the film the least film parameter asks for, against the cam angle from the
    timing datum (degrees); where the entrainment velocity falls to zero a dotted line marks it.

    Raises
    ------
    ValueError
        ``cam`` has no contact (:func:`no_contact` says why).
    """
    why = no_contact(cam)
    if why is not None:
        raise ValueError(why)
    co = cam.contact
    d = cam.design
    x, finite = _by_angle(co.phi)

    fig = _figure(h=6.0)
    ax_p, ax_h = fig.subplots(2, 1, sharex=True)
    ax_p.plot(x, finite(co.pressure), color="#2b6cb0", lw=1.4, label="maximum Hertz pressure p0")
    a = co.materials.allowable
    if a is not None:
        ax_p.axhline(a, color="#c53030", lw=1.0, ls="--", label=f"allowable {a:.4g} MPa")
    ax_p.set_ylabel("p0, MPa")
    if co.film is not None:
        ax_h.plot(x, finite(co.film), color="#2f855a", lw=1.4, label="minimum film thickness (Dowson-Higginson)")
        sp = co.spec
        if sp.cam_roughness is not None and sp.follower_roughness is not None:
            need = sp.min_film_parameter * float(np.hypot(sp.cam_roughness, sp.follower_roughness))
            ax_h.axhline(need, color="#c53030", lw=1.0, ls="--",
                         label=f"film for the film parameter {sp.min_film_parameter:g}: {need:.3g} µm")
        ax_h.set_ylabel("film, µm")
    else:
        ax_h.plot(x, finite(np.abs(co.entrainment)), color="#2f855a", lw=1.4, label="entrainment velocity")
        ax_h.set_ylabel("entrainment velocity, m/s")
    for k, z in enumerate(co.zero_entrainment):
        for ax in (ax_p, ax_h):
            ax.axvline(turn_degrees(z), color="#b7791f", lw=1.0, ls=":",
                       label="entrainment velocity zero" if k == 0 else None)
    ax_h.set_xlabel("cam angle φ from the timing datum, deg")
    for ax in (ax_p, ax_h):
        ax.grid(True, lw=0.3)
        _mark_phases(ax, d.program.starts)
        ax.set_ylim(bottom=0)
        legend_once(ax, fontsize=7, loc="best")
    _title(ax_p, f"{d.name}: contact stress and film at {co.rpm:.4g} rpm, face width {co.width:.4g} mm")
    return fig


def _draw(ax, cam, profile, phi: float) -> Callable[[float], list]:
    """The cam turned to ``phi`` with its follower, as its face draws it (:mod:`cams.present.faces`); returns the
    drawing's ``move(phi)`` (:meth:`cams.present.faces.Presenter.draw_mechanism`)."""
    from cams.present.faces import presenter

    return presenter(cam).draw_mechanism(ax, cam, profile, phi)


#: The profile picture's axes' width (inches) on an A4-wide figure, and the height of its title, axis labels and
#: legend below (inches), as the examples' fitted pictures have them: the height the fitting starts from
#: (:func:`_fit_height`'s ``guess``), so that it ends in one or two rounds instead of four.
PROFILE_AXES_WIDTH_IN, PROFILE_MARGINS_IN = 6.83, 1.27


def plot_profile(cam, *, phi: float | None = None):
    """The cam: working profile, pitch curve, base circle, and the follower at cam angle ``phi``.

    Parameters
    ----------
    cam : cams.cam.Cam
        Uses ``cam.profile`` (built on first use); nothing else is computed.
    phi : float, optional
        Cam angle (radians) at which the mechanism is drawn; default the middle
        of the first rise.
    """
    profile = cam.profile
    d = cam.design
    if phi is None:
        i = next(k for k, p in enumerate(d.program.phases) if p.kind == "rise")
        phi = d.program.starts[i] + 0.5 * d.program.phases[i].angle
    fig = _figure(w=A4_WIDTH_IN, h=6.0)
    ax = fig.add_subplot()
    _draw(ax, cam, profile, phi)
    _title(ax, f"{d.name}: cam at φ = {np.degrees(phi):.1f}°")
    _legend_below(fig, ax)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()  # the drawing's extent, to scale (equal aspect)
    title_lines = ax.get_title().count("\n")  # a long name's title wrapped: a line of 11 pt each
    guess = PROFILE_AXES_WIDTH_IN * (y1 - y0) / (x1 - x0) + PROFILE_MARGINS_IN + title_lines * 11 * 1.2 / 72
    return _fit_height(fig, ax, max_h=8.5, guess=guess)


def _animation_box(cam, profile) -> tuple[np.ndarray, np.ndarray]:
    """Corners of a view that holds the mechanism at every cam angle (fixed frame, length unit).

    The cam turns about its centre, so it stays inside the circle through its
    farthest point (working profile, pitch curve plus the roller, a groove's
    outer wall); the follower (roller, face, stem) is taken at every lift.
    """
    from cams.present.faces import presenter

    d = cam.design
    span = 0.05 * max(float(np.max(np.abs(profile.work))), d.scale)
    centre, reach, follower = presenter(cam).animation_extent(cam, profile)
    cam_box = np.asarray(centre)[None] + reach * np.array([[-1.0, -1.0], [1.0, 1.0]])
    allp = np.concatenate([cam_box, follower])
    return allp.min(axis=0) - span, allp.max(axis=0) + span


def animate_profile(cam, path, *, frames: int = 72, fps: int = 12, title: str = "",
                    progress: Callable[[int, int], None] | None = None) -> Path:
    """One turn of the cam with its follower as an animated GIF (Pillow).

    The mechanism is drawn once, its layout fixed, the still parts (axes, grid, base circle, centre) rendered
    once; each frame puts back that background, moves the moving parts (:meth:`cams.present.faces.Presenter.
    draw_mechanism`'s ``move``) and draws them and the angle's title alone. ``title``
    (:meth:`cams.assess.Assessment.title`) marks a failing cam's animation; ``progress`` is called as
    ``progress(frames_written, frames)`` after each frame.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from PIL import Image

    profile = cam.profile
    fig = mark_failing(_figure(w=5.0, h=5.0), title)
    canvas = FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    lo, hi = _animation_box(cam, profile)
    move = _draw(ax, cam, profile, 0.0)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    angle = ax.set_title("φ = 0°")
    # the height fitted to the view (a wide one leaves no empty bands above and below), the constrained layout
    # computed once: every frame has the same decorations
    _fit_height(fig, ax, max_h=6.0, min_h=2.5)
    fix_layout(fig)
    # each frame draws what lies in the axes, the grid among it at its own depth, as the axes would (by zorder,
    # stably): the still parts too (the base circle, the centre), lest the turned cam cover them
    inside = [*ax.patches, *ax.lines, *ax.collections]
    grid = [t.gridline for axis in (ax.xaxis, ax.yaxis) for t in axis.get_major_ticks() if t.gridline.get_visible()]
    depth = {id(g): ax.xaxis.get_zorder() for g in grid}
    order = sorted([*inside, *grid], key=lambda a: depth.get(id(a), a.get_zorder()))
    for a in [*inside, angle]:
        a.set_animated(True)
    for g in grid:
        g.set_visible(False)
    canvas.draw()  # the background: the figure, the axes' frame, ticks and labels
    background = canvas.copy_from_bbox(fig.bbox)
    for g in grid:
        g.set_visible(True)
    renderer = canvas.get_renderer()
    images = []
    for k in range(frames):
        canvas.restore_region(background)
        move(TWO_PI * k / frames)
        angle.set_text(f"φ = {360 * k / frames:.0f}°")
        for a in [*order, angle]:
            a.draw(renderer)
        images.append(Image.frombuffer("RGBA", canvas.get_width_height(), bytes(canvas.buffer_rgba()),
                                       "raw", "RGBA", 0, 1))
        if progress is not None:
            progress(k + 1, frames)
    path = Path(path)
    paletted = _paletted(images)
    paletted[0].save(path, format="GIF", save_all=True, append_images=paletted[1:], duration=int(1000 / fps),
                     loop=0)
    return path


def _paletted(images: list, *, samples: int = 4) -> list:
    """The frames ``images`` (Pillow, RGBA, opaque) in one palette of 256 colours, cut from ``samples`` frames
    spread over the turn, each frame then mapped to its nearest colours (no dithering: a line keeps its colour from
    frame to frame).

    Pillow would otherwise cut each frame's own palette, which took 60 % of an animation's time; the drawing's
    colours are the same in every frame (the parts move, they do not change colour), so one palette serves all.
    """
    from PIL import Image

    rgb = [im.convert("RGB") for im in images]
    picked = rgb[:: max(1, len(rgb) // samples)][:samples]
    w, h = rgb[0].size
    sheet = Image.new("RGB", (w, h * len(picked)))
    for k, im in enumerate(picked):
        sheet.paste(im, (0, h * k))
    # maximum coverage: the background's white stays white (a median cut averaged it with the near-whites of the
    # lines' anti-aliased edges: 252)
    palette = sheet.quantize(colors=256, method=Image.Quantize.MAXCOVERAGE)
    return [im.quantize(palette=palette, dither=Image.Dither.NONE) for im in rgb]


#: The pictures of a cam by kind (a face's presenter names the kind it draws under each picture name,
#: :attr:`cams.present.faces.Presenter.pictures`): each takes the :class:`cams.cam.Cam`.
PICTURES = {
    "zone": lambda cam: plot_zone(cam.solution, tradeoff=cam.tradeoff),
    "motion": lambda cam: plot_motion(cam.design),
    "pressure": lambda cam: plot_pressure(cam.solution),
    "flat_pressure": lambda cam: plot_flat_pressure(cam.solution),
    "curvature": lambda cam: plot_curvature(cam.solution),
    "profile": lambda cam: plot_profile(cam),
    "forces": lambda cam: plot_forces(cam),
    "contact": lambda cam: plot_contact(cam),
    "vibration": lambda cam: plot_vibration(cam),
}


def no_vibration(cam) -> str | None:
    """Why ``cam`` has no vibration to draw, or None when it has (:func:`plot_vibration`)."""
    spec = cam.design.dynamics
    if spec is None or spec.dynamics.train_stiffness is None:
        return (
            "the design has no follower train ([dynamics] train_stiffness, with cam.rpm); add one to draw its vibration"
        )
    if cam.vibration is None:
        return f"no vibration to draw: {cam.forces_note or 'no forces at the cam'}"
    return None


def plot_vibration(cam):
    """Three panes over one turn at the design's speed, cam angle from the timing datum (deg) on the abscissa.

    The output's displacement against the rigid motion (mm, or deg for a rocker) with their difference on a
    second axis (µm, or millidegrees); the output's acceleration against the rigid one (m/s², rad/s²); the dynamic
    contact force against the rigid one (N), with the event-driven one where contact is lost.

    Raises
    ------
    ValueError
        ``cam`` has no vibration (:func:`no_vibration` says why).
    """
    why = no_vibration(cam)
    if why is not None:
        raise ValueError(why)
    v = cam.vibration
    d = cam.design
    rocker = d.follower.kind == "rocker"
    to = np.degrees if rocker else (lambda a: np.asarray(a))
    unit, acc_unit, acc_scale = ("deg", "rad/s²", 1.0) if rocker else ("mm", "m/s²", 1e-3)
    x = np.degrees(v.phi)
    fig = _figure(h=8.0)
    ax_s, ax_a, ax_n = fig.subplots(3, 1, sharex=True)
    ax_s.plot(x, to(v.s), color="0.45", lw=1.2, ls="--", label="rigid motion")
    ax_s.plot(x, to(v.q), color="#2b6cb0", lw=1.2, label="output (elastic train, steady state)")
    ax_e = ax_s.twinx()
    diff = (to(v.q) - to(v.s)) * 1e3
    ax_e.plot(x, diff, color="#c05621", lw=0.9, label="output - rigid")
    ax_e.set_ylabel(f"output - rigid, {'mdeg' if rocker else 'µm'}")
    ax_s.set_ylabel(f"displacement, {unit}")
    ax_a.plot(x, v.d2s * acc_scale, color="0.45", lw=1.2, ls="--", label="rigid acceleration")
    ax_a.plot(x, v.d2q * acc_scale, color="#2b6cb0", lw=1.0, label="output's acceleration")
    ax_a.set_ylabel(f"acceleration, {acc_unit}")
    df = cam.forces
    if df is not None:
        ax_n.plot(
            x,
            np.where(np.isfinite(df.forces.contact), df.forces.contact, np.nan),
            color="0.45",
            lw=1.2,
            ls="--",
            label="rigid contact force",
        )
    ax_n.plot(
        x,
        np.where(np.isfinite(v.contact), v.contact, np.nan),
        color="#2b6cb0",
        lw=1.2,
        label="dynamic contact force (contact assumed)",
    )
    if v.flight is not None:
        amp = v.contact / np.where(v.load != 0, v.load, np.nan)
        o = np.argsort(np.degrees(v.flight.phi))
        ax_n.plot(
            np.degrees(v.flight.phi)[o],
            (v.flight.load * amp)[o],
            color="#c53030",
            lw=1.0,
            label="with separation (event-driven)",
        )
    if v.contact_lost_at is not None:
        ax_n.axvline(np.degrees(v.contact_lost_at), color="#c53030", lw=1.0, ls=":", label="contact lost")
    ax_n.axhline(0.0, color="0.3", lw=0.6)
    ax_n.set_ylabel("contact force, N")
    ax_n.set_xlabel("cam angle φ from the timing datum, deg")
    for ax in (ax_s, ax_a, ax_n):
        ax.grid(True, lw=0.3)
        _mark_phases(ax, d.program.starts)
    for ax in (ax_a, ax_n):
        legend_once(ax, fontsize=7, loc="best")
    # the displacement pane's two scales under one legend, above the pane: "best" weighs one scale's curves
    # only, and a legend inside would cover the other's (a dwell's flat line runs the whole width)
    legend_above(ax_s, ax_e)
    _suptitle(fig, f"{d.name}: follower train at {v.rpm:.4g} rpm, natural frequency {v.natural_frequency:.4g} Hz")
    return fig


#: How long each kind of picture takes to draw, relative to the others (CPU seconds x 10 on the examples): the
#: order in which processes drawing side by side take them up (:func:`cams.present.forked.forked_map`).
EFFORT = {"zone": 8, "vibration": 6, "motion": 5, "forces": 5, "profile": 4, "contact": 4, "curvature": 4,
          "pressure": 2, "flat_pressure": 2}

#: The pictures drawn only for a design that has their data, each with why not (None: it has it).
NEEDS = {
    "forces": lambda cam: no_forces(cam),
    "contact": lambda cam: no_contact(cam),
    "vibration": lambda cam: no_vibration(cam),
}


def missing(kind: str, cam) -> str | None:
    """Why ``cam`` has no picture of ``kind`` to draw (its data is not in the design), or None when it has."""
    why = NEEDS.get(kind)
    return None if why is None else why(cam)


def picture(kind: str, cam):
    """The picture of ``kind`` (:data:`PICTURES`) of ``cam``: a matplotlib ``Figure``."""
    return PICTURES[kind](cam)
