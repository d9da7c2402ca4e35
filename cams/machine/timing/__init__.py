"""The cam in its machine: windows of the cycle, the cam's timing and the cycle diagram.

By stage: :mod:`~cams.machine.timing.cycle` (the cycle's windows), :mod:`~cams.machine.timing.placement`
(the drive and the cam's rises placed) and :mod:`~cams.machine.timing.diagram` (the cycle diagram); this module
re-exports them. The machine designed (:class:`~cams.machine.design.MachineSpec`,
:class:`~cams.machine.design.MachineResult`) is :mod:`cams.machine.design`, above this package and the
kinetostatics.

The pipeline (:func:`cams.machine.design.design_machine`): the linkage's stroke analysis
(:func:`cams.machine.linkage.analyse`) -> the cutting and out-of-work windows on the
crank's cycle (:func:`windows`) -> the cam's rises placed inside the
out-of-work window with a margin, which fixes the cam's mounting angle
(:func:`place_cam`) -> the cam sized as by ``cams solve``
(:func:`cams.solve.solve`) -> the cycle diagram with an independent check
that feeding never overlaps cutting (:func:`cycle_diagram`).

Cycle angle
-----------
``c`` is the crank's rotation, in its own sense of rotation, from the dead
position that *ends* the working stroke (seed 003's position 1: the tool at
its lower limit, the slider's "下极限"). So the return stroke is
``[0, return_span]`` and the working stroke ``[return_span, 2 pi]``. Frame crank
angle ``phi = origin + sense * c``. Intervals are ``(start, end)`` with start
in [0, 2 pi) and ``end > start``; an end beyond 2 pi means the interval runs
past position 1 into the next cycle. Radians inside, degrees in
``to_dict``.

Cam angle
---------
The cam turns ``ratio`` times per crank turn (1 on the crank's shaft,
Z_crank / Z_cam through a gear pair). Its program angle (``laws.program``:
radians from the start of the first phase, in the cam's sense) is
``ratio * (c - mount)``: ``mount`` is the cycle angle at which the cam starts
its program.
"""


from cams.machine.timing.cycle import CuttingZone, Windows, windows
from cams.machine.timing.diagram import CycleDiagram, cycle_diagram
from cams.machine.timing.placement import (
    PLACEMENTS,
    CamTiming,
    Drive,
    Timing,
    check_follower_direction,
    place_cam,
)

__all__ = [
    "CuttingZone",
    "Drive",
    "Timing",
    "Windows",
    "CamTiming",
    "CycleDiagram",
    "windows",
    "place_cam",
    "check_follower_direction",
    "cycle_diagram",
    "PLACEMENTS",
]
