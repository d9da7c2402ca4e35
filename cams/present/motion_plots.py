"""Pictures of a motion design (``[optimize]``): the designed laws and cam beside the original ones.

:func:`plot_motion_design` draws, for a :class:`cams.cam.Cam` whose design has
an ``[optimize]`` table:

- the normalized laws ``S, S', S'', S'''`` of each free phase against ``u``,
  the designed one beside the original (and beside the first stage's, when
  the second stage smoothed it: ``optimization["smoothing"]``);
- the pressure angle over the cycle of both cams, each at its own centre,
  against the limits (roller followers; the kernel's inversion);
- the two cams overlaid to scale in the cam frame (pitch curves and working
  profiles; a flat face's profiles).

matplotlib is imported inside the function; it returns a ``Figure``.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from cams.kinematics.inversion import invert_phase, pressure_angle
from cams.present.faces import presenter_of_face
from cams.present.plots import draw_limits, legend_above
from cams.present.text import bound_words, objective_unit
from laws.units import TWO_PI

__all__ = ["plot_motion_design"]

_NEW, _OLD, _FIRST = "#2b6cb0", "#a0aec0", "#dd6b20"


def _first_stage(smoothing: dict | None) -> dict:
    """The first stage's laws by phase when the second stage's replaced them (else empty)."""
    if not smoothing or not smoothing.get("smoothed"):
        return {}
    from laws.spline import SplineLaw

    return {t["phase"]: SplineLaw(tuple(t["breaks"]), tuple(tuple(r) for r in t["coefficients"]))
            for t in smoothing["first_stage_laws"]}


def _laws_panel(fig, grid, given, designed, free, first=None) -> None:
    u = np.linspace(0.0, 1.0, 401)
    names = ("S", "dS/du", "d²S/du²", "d³S/du³")
    for k in range(4):
        ax = fig.add_subplot(grid[k // 2, k % 2])
        # every free phase normalized alike; the legend names them all (phases as `free` counts them)
        old_names = ", ".join(f"{i}: {given.program.law_of(i).name}" for i in free)
        for i in free:
            ax.plot(u, given.program.law_of(i).evaluate(u)[k], color=_OLD, lw=1.6,
                    label=f"original (phase {old_names})" if i == free[0] else None)
            if first and i in first:
                ax.plot(u, first[i].evaluate(u)[k], color=_FIRST, lw=0.9, ls="--",
                        label="first stage (the optimum found)" if i == free[0] else None)
            ax.plot(u, designed.program.law_of(i).evaluate(u)[k], color=_NEW, lw=1.1,
                    label=f"designed (phase {', '.join(map(str, free))})" if i == free[0] else None)
        ax.set_ylabel(names[k], fontsize=8)
        ax.grid(True, lw=0.3)
        ax.tick_params(labelsize=7)
        if k >= 2:
            ax.set_xlabel("u (normalized phase)", fontsize=8)
        if k == 0 and free:
            # above the pane: inside, its long names would cover the laws
            ax.legend(fontsize=7, loc="lower left", bbox_to_anchor=(0.0, 1.0), frameon=False)
        elif k == 0:
            ax.text(0.5, 0.5, "no free phase: the laws as given", ha="center", va="center", fontsize=8,
                    transform=ax.transAxes)


def _pressure_panel(ax, given, designed, centres, n: int = 721) -> None:
    for design, centre, colour, label in ((given, centres[0], _OLD, "original"),
                                          (designed, centres[1], _NEW, "designed")):
        first = True
        for i, p in enumerate(design.program.phases):
            if p.kind == "dwell":
                continue
            u = np.linspace(0.0, 1.0, max(int(n * p.angle / TWO_PI), 8))
            g = pressure_angle(invert_phase(design, centre, i, u))
            ax.plot(np.degrees(design.program.starts[i] + u * p.angle), np.degrees(np.abs(g)), color=colour,
                    lw=1.6 if colour == _OLD else 1.1, label=label if first else None)
            first = False
    draw_limits(ax, designed)
    ax.set_xlim(0, 360)
    ax.set_xlabel("cam angle φ, deg", fontsize=8)
    ax.set_ylabel("|pressure angle|, deg", fontsize=8)
    ax.grid(True, lw=0.3)
    ax.tick_params(labelsize=7)
    # above the pane: the curves' peaks can lie anywhere along the turn, and a legend inside would cover them
    legend_above(ax, ncol=4)


def _cams_panel(ax, given, designed, sizes) -> None:
    pitched = False
    for design, size, colour, label in ((given, sizes[0], _OLD, "original"), (designed, sizes[1], _NEW,
                                                                                "designed")):
        work, pitch, R0 = presenter_of_face(design.face).outline(design, size)
        if pitch is not None:
            ax.plot(pitch[:, 0], pitch[:, 1], color=colour, lw=0.8, ls="--")
            pitched = True
        ax.plot(work[:, 0], work[:, 1], color=colour, lw=1.6 if colour == _OLD else 1.1,
                label=f"{label}: R0 = {R0:.3f} mm")
    if pitched:  # each cam's colour, dashed
        ax.plot([], [], color="0.4", lw=0.8, ls="--", label="pitch curves (dashed)")
    ax.plot(0, 0, "k+", ms=10)
    ax.set_aspect("equal")
    ax.grid(True, lw=0.3)
    ax.tick_params(labelsize=7)
    ax.set_xlabel("x, mm (cam frame)", fontsize=8)
    ax.set_ylabel("y, mm", fontsize=8)
    # beside the cams (the view is as tall as the pane, narrower than it): inside, it would cover an outline
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))


def plot_motion_design(cam):
    """The designed laws and cam beside the original ones (see the module notes).

    Parameters
    ----------
    cam : cams.cam.Cam
        Of a design with an ``[optimize]`` table; its solution holds the
        motion design's report (``optimization``) with the original cam's
        centre (roller) or R0 (flat face).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    sol = cam.solution
    if sol.optimization is None:
        raise ValueError("the cam's design has no [optimize] table")
    info = sol.optimization.to_dict()
    given = replace(cam.given, optimize=None)
    designed = sol.design
    free = tuple(info["free"])
    ref = info["reference"]
    face = presenter_of_face(designed.face)
    # a face without a pressure-angle limit (a flat face's is the geometry's) has no pressure-angle panel
    panel = face.pressure_panel
    fig = Figure(figsize=(7.5, 10.0 if panel else 8.5), layout="constrained")
    grid = fig.add_gridspec(4 if panel else 3, 2, height_ratios=(1, 1, 1.1, 2.2) if panel else (1, 1, 2.2))
    _laws_panel(fig, grid, given, designed, free, _first_stage(info.get("smoothing")))
    if panel and ref is not None:
        _pressure_panel(fig.add_subplot(grid[2, :]), given, designed,
                        (np.array([ref["centre"]["x"], ref["centre"]["y"]]), sol.centre))
    if ref is not None:
        sizes = (face.reference_size(ref), face.size_of(sol))
        _cams_panel(fig.add_subplot(grid[3 if panel else 2, :]), given, designed, sizes)
    unit = " " + objective_unit(info)
    if info["lower_bound"] is None:
        how = f"a local optimum ({info['iterations']} iterations)"
    else:
        how = f"proven lower bound {bound_words(info)}"  # as cams solve prints it
        if not info["bound_proven"]:
            how += " (none above 0 proven)"
    sm = info.get("smoothing")
    smooth = ""
    if sm and sm["smoothed"] and sm["jerk_variation_before"] is not None and sm["jerk_variation_after"] is not None:
        smooth = (f"\nsmoothed within {sm['slack']:g} of the first stage's {sm['value_before']:.6g}{unit}: "
                  f"the total variation of S''' {sm['jerk_variation_before']:.0f} -> {sm['jerk_variation_after']:.0f}")
    fig.suptitle(f"{designed.name}: motion designed\n{info['objective']} {info['value']:.6g}{unit}, {how}; degree "
                 f"{info['degree']}, {info['spans']} spans, C{info['continuity']}{smooth}", fontsize=9)
    return fig
