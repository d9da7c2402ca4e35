"""Planar linkage kinematics: primitives (crank, Assur dyads), synthesis and cycle analysis.

* :mod:`cams.machine.linkage.primitives` -- vectorized positions, velocities and
  accelerations of the input crank and the RRR, RRP, RPR and RPP dyads;
* :mod:`cams.machine.linkage.synthesis` -- lengths from course data (time ratio,
  stroke, centre distance);
* :mod:`cams.machine.linkage.analysis` -- dead positions, stroke, time ratio and
  transmission angle of a one-input machine.

The ready-made machines of the seeds live in :mod:`cams.machine.linkage.machines`.
"""

from cams.machine.linkage.analysis import (
    WORKING,
    Machine,
    StrokeReport,
    analyse,
    dead_positions,
)
from cams.machine.linkage.primitives import (
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
from cams.machine.linkage.synthesis import (
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
