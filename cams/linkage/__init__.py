"""Planar linkage kinematics: primitives (crank, Assur dyads), synthesis and cycle analysis.

* :mod:`cams.linkage.primitives` -- vectorized positions, velocities and
  accelerations of the input crank and the RRR, RRP, RPR and RPP dyads;
* :mod:`cams.linkage.synthesis` -- lengths from course data (time ratio,
  stroke, centre distance);
* :mod:`cams.linkage.analysis` -- dead positions, stroke, time ratio and
  transmission angle of a one-input machine.

The ready-made machines of the seeds live in :mod:`cams.linkage.machines`.
"""

from cams.linkage.analysis import WORKING, Machine, StrokeReport, analyse, dead_positions
from cams.linkage.primitives import (
    Angle,
    AssemblyError,
    Point,
    Slide,
    acute_angle,
    crank,
    cross,
    ground,
    on_link,
    pllp,
    plpp,
    rpp,
    rpr,
    rrp,
    rrr,
    solve_real,
)
from cams.linkage.synthesis import (
    SlottedLeverSynthesis,
    crank_slider_crank,
    slotted_lever_synthesis,
    swing_from_time_ratio,
    time_ratio_from_swing,
)

__all__ = [
    "Angle",
    "AssemblyError",
    "Machine",
    "Point",
    "Slide",
    "SlottedLeverSynthesis",
    "StrokeReport",
    "WORKING",
    "acute_angle",
    "analyse",
    "crank",
    "crank_slider_crank",
    "cross",
    "dead_positions",
    "ground",
    "on_link",
    "pllp",
    "plpp",
    "rpp",
    "rpr",
    "rrp",
    "rrr",
    "slotted_lever_synthesis",
    "solve_real",
    "swing_from_time_ratio",
    "time_ratio_from_swing",
]
