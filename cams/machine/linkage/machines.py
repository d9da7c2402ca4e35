"""The seeds' linkages as ready-made machines, built group by group from :mod:`cams.machine.linkage`.

* :class:`SlottingMachine` -- seed 003 (插床): crank O2A, block A on the guide
  bar O3B (RPR dyad), link BC and the tool slider C on the guide y-y (RRP).
* :class:`CrankSlider` -- seed 002: crank OA, rod AB, slider B (RRP).
* :class:`OpposedTwin` -- seed 000: a two-cylinder mechanism, cranks OA and
  OC at 90 degrees on one shaft, rods AB and CD, pistons B and D on one axis
  on opposite sides of O (two RRP dyads).
* :class:`SlottedLeverPump` -- seed 004: crank O1A, block A on the swinging
  lever O2C (RPR), the piston driven from C through a block in its slot (RPP,
  a Scotch yoke).

Frames and signs
----------------
Every machine has its crank centre at the origin; angles are radians,
counter-clockwise from +x; ``crank_sense`` is +1 when the crank turns
counter-clockwise, -1 clockwise. For the slotted-lever machines the +x axis
points from the bar's pivot (O3, resp. O2 in the pump) to the crank centre,
so the pivot sits at ``(-L, 0)`` and the bar's mid-position lies along x;
the output moves along y. Lengths are in the caller's unit (mm in machine
files); velocities and accelerations are time derivatives for the crank's
``omega`` (rad/s), by default the machine's own (from ``rpm`` and the sense),
or ``crank_sense * 1 rad/s`` (analogues per radian of crank rotation) when
no rpm is given.

Each machine exposes ``kinematics(phi)`` (every point and link),
``output(phi)`` (the working member's coordinate, the protocol of
:func:`cams.machine.linkage.analyse`), ``transmission(phi)`` and ``lengths()``.
"""

from cams.machine.linkage.common import LinkageBase, LinkStates, Pair, describe_angles
from cams.machine.linkage.crank_slider import CrankSlider, CrankSliderKinematics
from cams.machine.linkage.opposed_twin import OpposedTwin, OpposedTwinKinematics
from cams.machine.linkage.pump import PumpKinematics, SlottedLeverPump
from cams.machine.linkage.slotting import SlottingKinematics, SlottingMachine

__all__ = [
    "SlottingMachine",
    "SlottingKinematics",
    "CrankSlider",
    "CrankSliderKinematics",
    "OpposedTwin",
    "OpposedTwinKinematics",
    "SlottedLeverPump",
    "PumpKinematics",
    "MACHINES",
    "Pair",
    "LinkStates",
    "describe_angles",
]

MACHINES: dict[str, type[LinkageBase]] = {
    SlottingMachine.kind: SlottingMachine,
    CrankSlider.kind: CrankSlider,
    OpposedTwin.kind: OpposedTwin,
    SlottedLeverPump.kind: SlottedLeverPump,
}
"""Machine classes by their ``kind`` (the machine file's ``linkage.type``)."""
