"""Pictures of the machine side: the cycle diagram, the linkage's forces and hodographs, the flywheel, the cam's forces.

Every picture function returns a :class:`matplotlib.figure.Figure` built
without pyplot (no backend is chosen, no pyplot state is kept);
:func:`write_machine_plots` writes them as PNGs, each whole or not at all
(:func:`cams.io.files.atomic_write`; inside :func:`cams.io.files.all_or_nothing`
all of them together or none). Angles are drawn in degrees: the cycle angle
from position 1 (the machine's windows), or the cam angle from the start of its
program.
"""

from __future__ import annotations

from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from cams.machine.kinetostatics.coupling import CAM_ANGLE, CYCLE_ANGLE
from laws.units import TWO_PI

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

    from cams.dynamics.forces import CamForces
    from cams.machine.flywheel import FlywheelResult
    from cams.machine.kinetostatics.coupling import MachineForces
    from cams.machine.kinetostatics.result import ForceResult
    from cams.machine.timing import CamTiming, CycleDiagram

__all__ = ["cycle_diagram_figure", "forces_figure", "hodograph_figure", "flywheel_figure", "cam_forces_figure",
           "machine_figures", "write_machine_plots"]



def _figure(figsize: tuple[float, float]) -> Figure:
    from matplotlib.figure import Figure

    return Figure(figsize=figsize)


def cycle_diagram_figure(diagram: CycleDiagram, *, title: str = "cycle diagram") -> Figure:
    """The cycle diagram: the tool and the follower over the cycle angle, cutting and feeding shaded.

    Parameters
    ----------
    diagram : cams.machine.timing.CycleDiagram
    title : str
    """
    deg = np.degrees(diagram.crank)
    fig = _figure((9, 5.5))
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    ax1.plot(deg, diagram.tool, color="C0")
    ax1.set_ylabel("tool from position 1, mm")
    f = np.degrees(diagram.follower) if diagram.follower_unit == "rad" else diagram.follower
    ax2.plot(deg, f, color="C1")
    ax2.set_ylabel("follower, " + ("deg" if diagram.follower_unit == "rad" else diagram.follower_unit))
    ax2.set_xlabel("cycle angle from position 1 (crank rotation), deg")
    for ax in (ax1, ax2):
        ax.fill_between(deg, 0, 1, where=diagram.cutting, transform=ax.get_xaxis_transform(), color="C3", alpha=0.15,
                        label="cutting")
        ax.fill_between(deg, 0, 1, where=diagram.feeding, transform=ax.get_xaxis_transform(), color="C2", alpha=0.25,
                        label="feeding")
        ax.grid(True, alpha=0.3)
    ax1.legend(loc="upper right")
    ax1.set_title(title + ("  -- OVERLAP" if diagram.overlap else ""))
    fig.tight_layout()
    return fig


def forces_figure(result: ForceResult, *, title: str = "forces") -> Figure:
    """The reactions' magnitudes and the balancing moment (force analysis and Zhukovsky's lever) over the cycle.

    Parameters
    ----------
    result : cams.machine.kinetostatics.ForceResult
        Angles: its :attr:`~cams.machine.kinetostatics.ForceResult.rotation`, named by its ``angle_reference``.
    title : str
    """
    c = np.degrees(result.rotation)
    o = np.argsort(c)
    fig = _figure((8, 6.5))
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    for j in result.model.joints:
        ax1.plot(c[o], result.magnitude(j.name)[o], label=j.name)
    ax1.set_ylabel("|reaction|, N")
    ax1.legend(loc="upper right", ncol=2, fontsize="small")
    ax2.plot(c[o], result.balancing_moment[o], label="M_b (force analysis)")
    ax2.plot(c[o], result.virtual_moment[o], "--", label="M_b (Zhukovsky)")
    ax2.set_ylabel("balancing moment, N m")
    ax2.set_xlabel(f"{result.angle_reference}, deg")
    ax2.legend(loc="upper right")
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
    ax1.set_title(title)
    fig.tight_layout()
    return fig


def hodograph_figure(result: ForceResult, *, title: str = "hodographs", marks: int = 12) -> Figure:
    """Hodographs of the reactions: the tip of each pair's reaction vector over the cycle.

    One panel a pair, in the order of the model's joints: ``R_x`` against
    ``R_y`` in N (frame axes), the reaction on the pair's first body from its
    second, as stored in ``result.reactions`` (the panel's first line, in
    crank-rotation order). ``marks`` positions equally spaced in crank
    rotation from the first crank angle are numbered 1, 2, ... as in the
    seeds' plans (position 1 at the first crank angle); the figure's subtitle
    names the angle (``result.angle_reference``).
    """
    c = result.rotation
    o = np.argsort(c)
    joints = result.model.joints
    cols = min(4, len(joints))
    rows = -(-len(joints) // cols)
    fig = _figure((3.2 * cols, 3.2 * rows))
    axes = fig.subplots(rows, cols, squeeze=False)
    cyc = result.model.cycle
    at = [int(np.argmin(np.abs(np.mod(c - cyc * k / marks + cyc / 2, cyc) - cyc / 2))) for k in range(marks)]
    for ax, j in zip(axes.ravel(), joints, strict=False):
        R = result.reactions[j.name]
        ax.plot(np.real(R)[o], np.imag(R)[o], lw=1.2)
        ax.plot([0.0], [0.0], "k+", ms=8)
        ax.plot(np.real(R[at]), np.imag(R[at]), "o", ms=3, color="C3")
        ax.set_title(f"{j.name} ({j.kind})", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, alpha=0.3)
        ax.tick_params(labelsize=7)
        ax.set_xlabel("R_x, N", fontsize=8)
        ax.set_ylabel("R_y, N", fontsize=8)
    for ax in axes.ravel()[len(joints):]:
        ax.set_visible(False)
    fig.suptitle(f"{title}\npoints 1..{marks} every {np.degrees(cyc) / marks:g} deg of {result.angle_reference}, "
                 "point 1 at 0 deg",
                 fontsize=10)
    fig.tight_layout()
    # numbered once the layout is final: the labels are placed where they neither cover each other nor a point
    for ax, j in zip(axes.ravel(), joints, strict=False):
        R = result.reactions[j.name][at]
        number_points(ax, np.column_stack([np.real(R), np.imag(R)]), fontsize=7, avoid=np.zeros((1, 2)))
    return fig


#: Where a point's number may go: offsets (points, radians) in growing rings, the first one up and to the right.
_RINGS = [(r, np.radians(a)) for r in (9, 14, 20, 28, 38, 52, 70) for a in range(45, 405, 45 if r < 20 else 30)]


def _runs(numbers: list[int]) -> str:
    """``[4, 6, 7, 8]`` as ``"4, 6-8"``: consecutive numbers as a range."""
    parts, start = [], None
    for k, n in enumerate(numbers):
        if start is None:
            start = n
        if k + 1 == len(numbers) or numbers[k + 1] != n + 1:
            parts.append(str(n) if n == start else f"{start}-{n}" if n > start + 1 else f"{start}, {n}")
            start = None
    return ", ".join(parts)


def number_points(ax, points: np.ndarray, *, fontsize: float = 7, near: float = 5.0,
                  avoid: np.ndarray | None = None) -> list:
    """Number ``points`` (data coordinates, shape (n, 2)) 1..n on ``ax``, each label clear of the others.

    Points within ``near`` pixels of each other (as drawn) share one label (``"6-12"``). Each label takes the
    first place, in growing rings around its point, whose box lies inside the axes and meets no label placed
    before, no numbered point and none of the points ``avoid`` (data coordinates, e.g. a marked origin); a
    label set off from its point gets a leader line. Call it once the figure's layout and the axes' limits
    are final. Returns the annotations.
    """
    fig = ax.get_figure()
    fig.draw_without_rendering()  # the limits (aspect applied) and the layout as they will be drawn
    pix = ax.transData.transform(points)
    groups: list[list[int]] = []
    for k in range(len(points)):
        for g in groups:
            if np.min(np.hypot(*(pix[g] - pix[k]).T)) <= near:
                g.append(k)
                break
        else:
            groups.append([k])
    frame = ax.get_window_extent()
    marks = pix if avoid is None else np.concatenate([pix, ax.transData.transform(avoid)])
    dots = [(x - 4, y - 4, x + 4, y + 4) for x, y in marks]
    taken: list[tuple[float, float, float, float]] = []

    def clear(b) -> bool:
        inside = b.x0 >= frame.x0 + 1 and b.y0 >= frame.y0 + 1 and b.x1 <= frame.x1 - 1 and b.y1 <= frame.y1 - 1
        return inside and not any(b.x0 < q[2] + 1 and b.x1 > q[0] - 1 and b.y0 < q[3] + 1 and b.y1 > q[1] - 1
                                  for q in (*taken, *dots))

    out = []
    for g in groups:
        label = _runs([k + 1 for k in g])
        centre = pix[g].mean(axis=0)
        anchor = points[g[int(np.argmin(np.hypot(*(pix[g] - centre).T)))]]
        text = ax.annotate(label, anchor, fontsize=fontsize, xytext=(0, 0), textcoords="offset points",
                           ha="center", va="center")
        for r, a in _RINGS:
            text.xyann = (r * np.cos(a), r * np.sin(a))
            box = text.get_window_extent()
            if clear(box):
                break
        else:  # nowhere clear: beside the point, over whatever is there
            text.xyann = (_RINGS[0][0] * np.cos(_RINGS[0][1]), _RINGS[0][0] * np.sin(_RINGS[0][1]))
            box = text.get_window_extent()
        if np.hypot(*text.xyann) > _RINGS[0][0] + 1:  # set off: a leader line to its point
            xy = text.xyann
            text.remove()
            text = ax.annotate(label, anchor, fontsize=fontsize, xytext=xy, textcoords="offset points",
                               ha="center", va="center",
                               arrowprops=dict(arrowstyle="-", lw=0.5, color="0.45", shrinkA=0, shrinkB=2))
        taken.append((box.x0, box.y0, box.x1, box.y1))
        out.append(text)
    return out


def flywheel_figure(fw: FlywheelResult, *, title: str = "flywheel") -> Figure:
    """Reduced moments, works, the energy with the construction of the excess work, and the crank's speed.

    The third panel draws the energy change ``dE = Ad - Ar`` and, when the linkage has an inertia ``J`` of
    its own, the energy the flywheel itself must take, ``dE - 1/2 J omega^2`` at the largest and the
    smallest speed: the excess work ``dA`` is the height between the largest of the first and the smallest
    of the second (the Wittenbauer construction's segment; for ``J = 0``, between the largest and the
    smallest ``dE``), marked with both points and ``J_F = dA / (omega_m^2 delta)``.

    Parameters
    ----------
    fw : cams.machine.flywheel.FlywheelResult
    title : str
    """
    deg = np.degrees(fw.phi)
    fig = _figure((8, 10))
    axes = fig.subplots(4, 1, sharex=True, height_ratios=(1, 1, 1.6, 1))
    axes[0].plot(deg, fw.resisting, label="Mr")
    axes[0].plot(deg, fw.driving, label="Md")
    axes[0].set_ylabel("reduced moment, N m")
    axes[1].plot(deg, fw.work_resisting, label="Ar")
    axes[1].plot(deg, fw.work_driving, label="Ad")
    axes[1].set_ylabel("work, J")
    _excess_work_panel(axes[2], fw, deg)
    axes[3].plot(deg, fw.omega, color="C3", label=f"omega, J_F = {fw.flywheel_inertia:.4g} kg m^2")
    axes[3].axhline(fw.omega_mean, color="0.5", lw=0.8, label=f"omega_m = {fw.omega_mean:.4g} rad/s")
    axes[3].set_ylabel("omega, rad/s")
    axes[3].set_xlabel(f"{fw.reference}, deg")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    for ax in (axes[0], axes[1], axes[3]):  # where no curve runs: the works end high at the right, the speed too
        ax.legend(loc="best", fontsize="small")
    axes[0].set_title(f"{title}: delta = {fw.delta:g}, n = {fw.rpm:.4g} rpm")
    fig.tight_layout()
    return fig


def _excess_work_panel(ax, fw: FlywheelResult, deg: np.ndarray) -> None:
    """The energy change and the construction of the excess work (see :func:`flywheel_figure`)."""
    w_hi, w_lo = fw.omega_mean * (1 + fw.delta / 2), fw.omega_mean * (1 - fw.delta / 2)
    ax.plot(deg, fw.energy, color="C2", label="dE = Ad - Ar")
    if np.any(fw.inertia != 0):
        hi_curve, lo_curve = fw.energy - 0.5 * fw.inertia * w_hi**2, fw.energy - 0.5 * fw.inertia * w_lo**2
        ax.plot(deg, hi_curve, color="C0", lw=1.0, ls="--", label="dE - J omega_max^2 / 2")
        ax.plot(deg, lo_curve, color="C1", lw=1.0, ls="-.", label="dE - J omega_min^2 / 2")
    else:
        hi_curve = lo_curve = fw.energy
    i, k = int(np.argmax(hi_curve)), int(np.argmin(lo_curve))
    top, bottom = float(hi_curve[i]), float(lo_curve[k])
    ax.plot(deg[i], top, "^", color="C3", ms=6, label=f"largest, at {deg[i]:.1f} deg (omega_max)")
    ax.plot(deg[k], bottom, "v", color="C4", ms=6, label=f"smallest, at {deg[k]:.1f} deg (omega_min)")
    for y in (top, bottom):
        ax.axhline(y, color="0.45", lw=0.7, ls=":")
    # the excess work between the two levels, at the angle midway between the two points
    x = 0.5 * (deg[i] + deg[k])
    ax.annotate("", xy=(x, top), xytext=(x, bottom), arrowprops=dict(arrowstyle="<->", color="k", lw=1.0))
    ax.annotate("ΔE", (x, 0.5 * (top + bottom)), xytext=(4, 0), textcoords="offset points", va="center")
    ax.set_ylabel("energy, J")
    # the value where the legend goes, clear of the curves
    ax.legend(loc="best", fontsize="x-small", ncol=2, title_fontsize="small",
              title=f"excess work ΔE = {fw.excess_work:.4g} J: J_F = ΔE / (omega_m^2 delta) = "
                    f"{fw.flywheel_inertia:.4g} kg m^2")


class _Picked:
    """The arrays of a :class:`cams.dynamics.forces.CamForces` indexed by ``o`` (for plotting in another order)."""

    def __init__(self, cf, o):
        self._cf, self._o = cf, o

    def __getattr__(self, name):
        v = getattr(self._cf, name)
        return v[self._o] if isinstance(v, np.ndarray) and v.shape == self._cf.phi.shape else v


def cam_forces_figure(cf: CamForces, *, title: str = "cam forces", timing: CamTiming | None = None,
                      follower: str = "rocker") -> Figure:
    """The cam's contact, lateral and spring forces and the camshaft torque, rigid impacts marked.

    Forces (N) and moments (N m) are on axes of their own: a rocker's torsional spring on a second scale
    beside the contact force's, the camshaft torque on the panel below.

    Parameters
    ----------
    cf : cams.dynamics.forces.CamForces
    title : str
    follower : {"rocker", "translating"}
        The cam's follower: a rocker's spring is a moment about its pivot (N m), a translating one's a force.
    timing : cams.machine.timing.CamTiming or None
        With the cam's timing the axis is the cycle angle from position 1
        (every cam sample at each cycle angle where it occurs over the
        repeating period); without, the cam angle from the start of its program.
    """
    o: slice | np.ndarray
    if timing is None:
        deg, o = np.degrees(cf.phi), slice(None)
        xlabel = f"{CAM_ANGLE}, deg"
    else:
        p, q = timing.period
        c = np.concatenate([timing.mount + (cf.phi + TWO_PI * j) / timing.ratio for j in range(p)])
        deg = np.degrees(np.mod(c, TWO_PI * q))
        o = np.argsort(deg)
        deg = deg[o]
        o = np.tile(np.arange(cf.phi.size), p)[o]
        xlabel = f"{CYCLE_ANGLE}, deg" + (f" (over {q} crank turns)" if q > 1 else "")
    picked = _Picked(cf, o)
    N = np.where(np.isfinite(picked.contact), picked.contact, np.nan)
    fig = _figure((8, 5.5))
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    ax1.plot(deg, N, label="contact force N")
    ax1.plot(deg, np.where(np.isfinite(picked.contact), picked.lateral, np.nan), label="lateral N sin(gamma)")
    ax1.set_ylabel("force, N")
    if follower == "rocker":  # a moment: its own scale, on the right
        twin = ax1.twinx()
        twin.plot(deg, picked.spring, "--", color="C2", label="spring moment (right scale)")
        twin.set_ylabel("spring moment about the pivot, N m")
        twin.set_ylim(bottom=min(0.0, float(np.nanmin(picked.spring)) * 1.1),
                      top=max(1e-9, float(np.nanmax(picked.spring))) * 1.1)
        spring_handles = twin.get_legend_handles_labels()
    else:
        ax1.plot(deg, picked.spring, "--", color="C2", label="spring force")
        spring_handles = ([], [])
    ax2.plot(deg, np.where(np.isfinite(picked.torque), picked.torque, np.nan), color="C3", label="camshaft torque")
    ax2.set_ylabel("camshaft torque, N m")
    ax2.set_xlabel(xlabel)
    impacts = getattr(cf, "impacts", ())
    for n, imp in enumerate(impacts):  # rigid impacts: unbounded force (or contact lost) there
        xs = [np.degrees(imp.phi)] if timing is None else np.degrees(
            np.mod(timing.mount + (imp.phi + TWO_PI * np.arange(timing.period[0])) / timing.ratio,
                   TWO_PI * timing.period[1]))
        for x in xs:
            for ax in (ax1, ax2):
                ax.axvline(x, color="C3", lw=1.0, ls=":",
                           label=("rigid impact (unbounded / contact lost)"
                                  if ax is ax1 and n == 0 and x == xs[0] else None))
    h, lab = ax1.get_legend_handles_labels()
    ax1.legend(h + spring_handles[0], lab + spring_handles[1], loc="upper right", fontsize="small")
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
    ax1.set_title(f"{title} at {cf.rpm:.4g} rpm")
    fig.tight_layout()
    return fig


def machine_figures(diagram: CycleDiagram | None, forces: MachineForces | None, *, title: str = "",
                    follower: str = "rocker") -> dict:
    """Every picture of a machine, by the name its file ends with (``cycle``, ``forces``, ``hodographs``...).

    Parameters
    ----------
    diagram : cams.machine.timing.CycleDiagram or None
    forces : cams.machine.kinetostatics.MachineForces or None
        The linkage's forces, its flywheel and the cam's forces, each drawn when present.
    title : str
        The machine's name.
    follower : {"rocker", "translating"}
        The cam's follower (:func:`cam_forces_figure`).

    Returns
    -------
    dict of str to Figure
        In the order they are written.
    """
    out: dict = {}
    if diagram is not None:
        out["cycle"] = cycle_diagram_figure(diagram, title=title)
    if forces is not None:
        if forces.linkage is not None:
            out["forces"] = forces_figure(forces.linkage, title=f"{title}: reactions and balancing moment")
            out["hodographs"] = hodograph_figure(forces.linkage, title=f"{title}: hodographs of the reactions")
        if forces.flywheel is not None:
            out["flywheel"] = flywheel_figure(forces.flywheel, title=f"{title}: energy")
        if forces.cam is not None:
            out["cam_forces"] = cam_forces_figure(forces.cam, title=f"{title}: cam forces", timing=forces.cam_timing,
                                                  follower=follower)
    return out


def write_machine_plots(folder: str | Path, stem: str, diagram: CycleDiagram | None, forces: MachineForces | None, *,
                        title: str = "", field: str = "--plot", follower: str = "rocker") -> list[Path]:
    """Write the machine's pictures (:func:`machine_figures`) into ``folder``, each whole or not at all.

    Each is a PNG named ``stem`` + ``_`` + its name (``cycle``, ``forces``...).

    ``field`` names the option in an error; ``follower`` is the cam's (:func:`cam_forces_figure`). Returns the
    paths written, in order.
    """
    from cams.io.files import atomic_write

    d = Path(folder)
    paths = []
    for name, fig in machine_figures(diagram, forces, title=title, follower=follower).items():
        paths.append(atomic_write(d / f"{stem}_{name}.png", field, partial(fig.savefig, format="png")))
    return paths
