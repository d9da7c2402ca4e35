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
        for k, i in enumerate(at):
            ax.plot(np.real(R[i]), np.imag(R[i]), "o", ms=3, color="C3")
            ax.annotate(str(k + 1), (np.real(R[i]), np.imag(R[i])), fontsize=7, xytext=(3, 3),
                        textcoords="offset points")
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
    return fig


def flywheel_figure(fw: FlywheelResult, *, title: str = "flywheel") -> Figure:
    """Reduced moments, works, energy and the crank's speed over the cycle (seed 004's energy curves).

    Parameters
    ----------
    fw : cams.machine.flywheel.FlywheelResult
    title : str
    """
    deg = np.degrees(fw.phi)
    fig = _figure((8, 9))
    axes = fig.subplots(4, 1, sharex=True)
    axes[0].plot(deg, fw.resisting, label="Mr")
    axes[0].plot(deg, fw.driving, label="Md")
    axes[0].set_ylabel("reduced moment, N m")
    axes[1].plot(deg, fw.work_resisting, label="Ar")
    axes[1].plot(deg, fw.work_driving, label="Ad")
    axes[1].set_ylabel("work, J")
    axes[2].plot(deg, fw.energy, color="C2", label="dE = Ad - Ar")
    axes[2].set_ylabel("energy change, J")
    axes[3].plot(deg, fw.omega, color="C3", label=f"omega, J_F = {fw.flywheel_inertia:.4g} kg m^2")
    axes[3].axhline(fw.omega_mean, color="0.5", lw=0.8)
    axes[3].set_ylabel("omega, rad/s")
    axes[3].set_xlabel(f"{fw.reference}, deg")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper right")
    axes[0].set_title(f"{title}: delta = {fw.delta:g}, n = {fw.rpm:.4g} rpm")
    fig.tight_layout()
    return fig


class _Picked:
    """The arrays of a :class:`cams.dynamics.forces.CamForces` indexed by ``o`` (for plotting in another order)."""

    def __init__(self, cf, o):
        self._cf, self._o = cf, o

    def __getattr__(self, name):
        v = getattr(self._cf, name)
        return v[self._o] if isinstance(v, np.ndarray) and v.shape == self._cf.phi.shape else v


def cam_forces_figure(cf: CamForces, *, title: str = "cam forces", timing: CamTiming | None = None) -> Figure:
    """The cam's contact, lateral and spring forces and the camshaft torque, rigid impacts marked.

    Parameters
    ----------
    cf : cams.dynamics.forces.CamForces
    title : str
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
    ax1.plot(deg, picked.spring, "--", label="spring")
    ax1.set_ylabel("force, N (N m rocker)")
    ax1.legend(loc="upper right")
    ax2.plot(deg, np.where(np.isfinite(picked.torque), picked.torque, np.nan), color="C3", label="camshaft torque")
    ax2.set_ylabel("torque, N m")
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
    if impacts:
        ax1.legend(loc="upper right")
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
    ax1.set_title(f"{title} at {cf.rpm:.4g} rpm")
    fig.tight_layout()
    return fig


def machine_figures(diagram: CycleDiagram | None, forces: MachineForces | None, *, title: str = "") -> dict:
    """Every picture of a machine, by the name its file ends with (``cycle``, ``forces``, ``hodographs``...).

    Parameters
    ----------
    diagram : cams.machine.timing.CycleDiagram or None
    forces : cams.machine.kinetostatics.MachineForces or None
        The linkage's forces, its flywheel and the cam's forces, each drawn when present.
    title : str
        The machine's name.

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
            out["cam_forces"] = cam_forces_figure(forces.cam, title=f"{title}: cam forces", timing=forces.cam_timing)
    return out


def write_machine_plots(folder: str | Path, stem: str, diagram: CycleDiagram | None, forces: MachineForces | None, *,
                        title: str = "", field: str = "--plot") -> list[Path]:
    """Write the machine's pictures (:func:`machine_figures`) into ``folder``, each whole or not at all.

    Each is a PNG named ``stem`` + ``_`` + its name (``cycle``, ``forces``...).

    ``field`` names the option in an error. Returns the paths written, in order.
    """
    from cams.io.files import atomic_write

    d = Path(folder)
    paths = []
    for name, fig in machine_figures(diagram, forces, title=title).items():
        paths.append(atomic_write(d / f"{stem}_{name}.png", field, partial(fig.savefig, format="png")))
    return paths
