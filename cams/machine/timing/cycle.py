"""The cycle's windows: where on the crank's cycle the tool cuts and where it is out of the work.

Cycle angle ``c``: the crank's rotation, in its own sense, from the dead
position that ends the working stroke (position 1); frame crank angle
``phi = origin + sense * c`` (:mod:`cams.machine.timing`). Radians inside,
degrees in ``to_dict``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.machine.linkage.analysis import WORKING, Machine, StrokeReport, analyse
from cams.model.follower import rotation_word
from laws.errors import InputError, check_option, show_value
from laws.units import TWO_PI

__all__ = ["CuttingZone", "Windows", "windows", "deg"]



def deg(x: float) -> float:
    """An angle in radians as a float in degrees (for reports)."""
    return float(np.degrees(x))


def _frac(field_: str, v) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not np.isfinite(v) or not 0 <= v < 1:
        raise InputError(field_, f"must be a fraction of the stroke in [0, 1), got {show_value(v)}")
    return float(v)


@dataclass(frozen=True)
class CuttingZone:
    """Where the tool is in the work: a part of the working stroke.

    Parameters
    ----------
    approach : float
        Fraction of the stroke H the tool travels in the air before it cuts
        (overrun at the start), in [0, 1).
    overrun : float
        Fraction of H after the cut ends (overrun at the end), in [0, 1).
    working : {"slow", "fast", "forward", "backward"}
        Which stroke is the working one (see :func:`cams.machine.linkage.analyse`).
    """

    approach: float = 0.0
    overrun: float = 0.0
    working: str = "slow"

    def __post_init__(self):
        _frac("cutting.approach", self.approach)
        _frac("cutting.overrun", self.overrun)
        if self.approach + self.overrun >= 1:
            raise InputError("cutting", "approach + overrun must be < 1 (a part of the stroke is cut), "
                             f"got {self.approach + self.overrun:g}")
        check_option("cutting.working", self.working, WORKING)


@dataclass(frozen=True)
class Windows:
    """The crank cycle's windows (cycle angles, radians).

    Attributes
    ----------
    stroke : StrokeReport
        The output's dead positions, stroke and time ratio.
    origin : float
        Frame crank angle of cycle angle 0: the dead position ending the
        working stroke (seed 003's position 1).
    sense : int
        The crank's sense of rotation.
    working_start : float
        Cycle angle where the working stroke begins (= the return span).
    cut_start, cut_end : float
        Cycle angles where the tool enters and leaves the work (seed 003's
        positions 5' and 12').
    """

    stroke: StrokeReport
    origin: float
    sense: int
    working_start: float
    cut_start: float
    cut_end: float

    @property
    def cutting(self) -> tuple[float, float]:
        """(start, end) of the cut, cycle angles."""
        return self.cut_start, self.cut_end

    @property
    def out_of_work(self) -> tuple[float, float]:
        """(start, end) of the tool's out-of-work window, start in [0, 2 pi); it runs through position 1
        (end > 2 pi)."""
        start = self.cut_end - TWO_PI if self.cut_end >= TWO_PI else self.cut_end
        return start, self.cut_start + TWO_PI - (self.cut_end - start)

    def frame_angle(self, c):
        """Frame crank angle of cycle angles ``c``."""
        return self.origin + self.sense * np.asarray(c, dtype=float)

    def cycle_angle(self, phi):
        """Cycle angle in [0, 2 pi) of frame crank angles ``phi``."""
        return np.mod(self.sense * (np.asarray(phi, dtype=float) - self.origin), TWO_PI)

    def to_dict(self) -> dict:
        """JSON-ready: cycle angles in degrees."""
        o = self.out_of_work
        return {
            "origin_frame_deg": deg(np.mod(self.origin, TWO_PI)),
            "crank_rotation": rotation_word(self.sense),
            "return": [0.0, deg(self.working_start)],
            "working": [deg(self.working_start), 360.0],
            "cutting": [deg(self.cut_start), deg(self.cut_end)],
            "out_of_work": [deg(o[0]), deg(o[1])],
            "out_of_work_span": deg(o[1] - o[0]),
        }


def windows(linkage: Machine, cutting: CuttingZone, *, samples: int = 720) -> Windows:
    """The cycle's windows from the linkage's motion.

    Parameters
    ----------
    linkage : Machine
        A linkage of :mod:`cams.machine.linkage.machines`.
    cutting : CuttingZone
        The cut as a part of the working stroke.
    samples : int, optional
        Grid of the stroke analysis.

    Returns
    -------
    Windows
    """
    from laws.search import bracketed_root

    rep = analyse(linkage, working=cutting.working, samples=samples)
    sense = linkage.crank_sense
    origin = rep.end
    ws = rep.return_span
    H = rep.stroke

    def travel(c):  # distance from the working stroke's start, along the working stroke
        return abs(float(linkage.output(np.array([origin + sense * c])).s[0]) - rep.s_start)

    def at(frac):
        if frac <= 0:
            return ws
        if frac >= 1:
            return TWO_PI
        return bracketed_root(lambda c: travel(c) - frac * H, ws, TWO_PI, xtol=1e-13, rtol=1e-15)

    return Windows(rep, origin, sense, ws, at(cutting.approach), at(1 - cutting.overrun))
