"""The cycle diagram: the tool and the cam's follower on one crank-angle axis, with the feeding-vs-cutting check.

Its picture: :func:`cams.present.machine_plots.cycle_diagram_figure`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.machine.linkage.analysis import Machine
from cams.machine.timing.cycle import CuttingZone, Windows
from cams.machine.timing.placement import CamTiming
from laws.program import Program
from laws.units import TWO_PI

__all__ = ["CycleDiagram", "cycle_diagram"]



@dataclass(frozen=True, eq=False)
class CycleDiagram:
    """Data of the cycle diagram (цикловая диаграмма / 运动循环图) on one crank-angle axis.

    Attributes
    ----------
    crank : ndarray
        Cycle angle, radians, over the repeating period (q crank turns).
    tool : ndarray
        The tool's distance from its position at cycle angle 0 (length): 0 at
        position 1, H at the start of the working stroke.
    follower : ndarray
        The cam follower's displacement: swing in radians (rocker) or lift
        (translating).
    cutting : ndarray of bool
        The tool is in the work: moving in the working direction with its
        travel between approach and 1 - overrun of the stroke (from the motion
        itself, not from :class:`Windows`).
    feeding : ndarray of bool
        The follower is in a rise.
    overlap : bool
        Feeding and cutting at the same sample anywhere.
    follower_unit : str
        ``"rad"`` or the length unit.
    return_overlap : bool
        The follower's return (not a feed) happens partly during the cut;
        harmless for a ratchet feed, reported as a note.
    """

    crank: np.ndarray
    tool: np.ndarray
    follower: np.ndarray
    cutting: np.ndarray
    feeding: np.ndarray
    overlap: bool
    follower_unit: str
    return_overlap: bool = False

    def to_dict(self, *, step_deg: float = 5.0) -> dict:
        """JSON-ready samples every ``step_deg`` degrees (follower in degrees for a rocker)."""
        deg = np.degrees(self.crank)
        pick = np.isclose(np.mod(deg + 1e-9, step_deg), 0.0, atol=1e-6)
        f = np.degrees(self.follower) if self.follower_unit == "rad" else self.follower
        return {
            "step_deg": step_deg,
            "crank_deg": [round(float(x), 6) for x in deg[pick]],
            "tool": [float(x) for x in self.tool[pick]],
            "follower": [float(x) for x in f[pick]],
            "follower_unit": "deg" if self.follower_unit == "rad" else self.follower_unit,
        }


def cycle_diagram(
    linkage: Machine,
    win: Windows,
    cutting: CuttingZone,
    program: Program,
    timing: CamTiming,
    *,
    per_turn: int = 3600,
    follower_unit: str = "rad",
) -> CycleDiagram:
    """Tool and follower on one crank-angle axis, with the feeding-vs-cutting check.

    Parameters
    ----------
    linkage : Machine
        The machine's linkage.
    win : Windows
    cutting : CuttingZone
    program : Program
    timing : CamTiming
    per_turn : int, optional
        Samples per crank turn (multiple of 72 keeps the 5-degree JSON grid exact).
    follower_unit : str
        ``"rad"`` for a rocker, else the length unit.

    Returns
    -------
    CycleDiagram
    """
    q = timing.period[1]
    c = np.linspace(0.0, TWO_PI * q, per_turn * q + 1)
    out = linkage.output(win.frame_angle(c))
    rep = win.stroke
    tool = np.abs(out.s - rep.s_end)
    travel = np.abs(out.s - rep.s_start)
    H = rep.stroke
    moving_work = np.sign(out.ds * win.sense) == rep.direction  # d/dt = ds/dphi * omega, omega ~ sense
    tol = 1e-9 * H
    cut = moving_work & (travel >= cutting.approach * H - tol) & (travel <= (1 - cutting.overrun) * H + tol)
    cam = timing.ratio * (c - timing.mount)
    mo = program.evaluate(cam)
    idx = program.phase_of(cam)
    kinds = np.array([p.kind for p in program.phases])[idx]
    feeding = kinds == "rise"
    # a sample exactly on a window's edge may be both (the cut's first instant and the rise's last):
    # ignore zero-length contact
    inner_cut = cut & np.roll(cut, 1) & np.roll(cut, -1)
    overlap = bool(np.any(inner_cut & feeding))
    ret = bool(np.any(inner_cut & (kinds == "return")))
    return CycleDiagram(c, tool, mo.s, cut, feeding, overlap, follower_unit, ret)
