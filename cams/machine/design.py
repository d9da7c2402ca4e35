"""The machine designed: a machine file's machine (:class:`MachineSpec`) -> windows, timing, the cam, the diagram.

:func:`design_machine` runs the pipeline of :mod:`cams.machine.timing` and sizes the cam. It sits above the
timing and the kinetostatics (its :class:`MachineSpec` carries the ``[forces]`` table's
:class:`~cams.machine.kinetostatics.loads.ForceSpec`), so neither package imports the other through it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from cams.cam import Cam
from cams.machine.kinetostatics.loads import ForceOptions, ForceSpec
from cams.machine.linkage.analysis import Machine, StrokeReport
from cams.machine.timing.cycle import CuttingZone, Windows, deg, windows
from cams.machine.timing.diagram import CycleDiagram, cycle_diagram
from cams.machine.timing.placement import CamTiming, Drive, Timing, place_cam
from cams.model.design import CamDesign
from cams.model.follower import Rocker
from laws.errors import InputError

if TYPE_CHECKING:
    from cams.assess import Assessment
    from cams.solve import SolveResult

__all__ = ["MachineSpec", "MachineResult", "design_machine"]


@dataclass(frozen=True)
class MachineSpec:
    """A machine with its feed cam, as read from a machine file.

    Parameters
    ----------
    name : str
    linkage : Machine
        One of :mod:`cams.machine.linkage.machines`.
    cutting : CuttingZone
    drive : Drive
    timing : Timing
    cam : CamDesign
        The cam's design; its ``cam_sense`` and ``rpm`` follow the crank and the drive.
    units : str
        Length unit of the file.
    forces : ForceSpec or None
        The linkage's masses, loads and friction (a machine file's ``[forces]``
        table); None: no linkage forces.
    force_options : ForceOptions
        How the forces are sampled and the flywheel sized (``[forces]``'s
        samples, passes, delta, interpolation).

    Raises
    ------
    InputError
        ``forces`` not a :class:`ForceSpec` (or None), ``force_options`` not a
        :class:`ForceOptions`.
    """

    name: str
    linkage: Machine
    cutting: CuttingZone
    drive: Drive
    timing: Timing
    cam: CamDesign
    units: str = "mm"
    forces: ForceSpec | None = None
    force_options: ForceOptions = field(default_factory=ForceOptions)

    def __post_init__(self) -> None:
        if self.forces is not None and not isinstance(self.forces, ForceSpec):
            raise InputError("forces", f"must be a ForceSpec or None, got {type(self.forces).__name__}")
        if not isinstance(self.force_options, ForceOptions):
            raise InputError("forces", f"options must be a ForceOptions, got {type(self.force_options).__name__}")


@dataclass(frozen=True)
class MachineResult:
    """Everything :func:`design_machine` finds.

    ``bore``: with ``[cam] bore_radius``, the profile check of the bore:
    ``{"bore_radius", "min_work_radius", "clear"}`` (lengths in the file's
    unit; ``clear``: the working profile's smallest radius exceeds the bore's;
    None when no profile could be built).

    ``assessment``: the feed cam judged by the rule every command shares
    (:func:`cams.assess.assess_cam`): verified, buildable (a working profile,
    no undercut, a valid closed profile, the bore, ``[dynamics]``) and certified;
    :func:`design_machine` always sets it (a result without one is not :attr:`ok`).
    """

    spec: MachineSpec
    stroke: StrokeReport
    windows: Windows
    timing: CamTiming
    solve: SolveResult
    diagram: CycleDiagram
    bore: dict | None = None
    assessment: Assessment | None = None

    @property
    def overlap(self) -> bool:
        """True when feeding overlaps cutting somewhere (a failed check)."""
        return self.diagram.overlap

    @property
    def notes(self) -> list[str]:
        """Remarks: the bore check's outcome (a bore the profile cuts into fails :attr:`ok`) and those that do not
        fail."""
        out = []
        b = self.bore
        if b is not None:
            u = self.spec.units
            if b["clear"]:
                out.append(f"bore radius {b['bore_radius']:g} {u}: the working profile's smallest radius "
                           f"{b['min_work_radius']:.4f} {u} clears it")
            else:
                out.append(f"bore radius {b['bore_radius']:g} {u} is NOT clear of the working profile, whose smallest "
                           f"radius is {b['min_work_radius']:.4f} {u}: choose a smaller bore (cam.bore_radius)")
        if self.diagram.return_overlap:
            out.append("the follower's return overlaps the cut (no feed then with a ratchet drive); "
                       "placement = 'early' or a shorter return keeps it out")
        return out

    @property
    def ok(self) -> bool:
        """No overlap and a usable feed cam (:attr:`cams.assess.Assessment.usable`: certified, verified and
        buildable, the bore included), as every other command judges a cam."""
        return not self.overlap and self.assessment is not None and bool(self.assessment.usable)

    def to_dict(self) -> dict:
        """JSON-ready report: lengths in the file's unit, angles in degrees."""
        lk = self.spec.linkage
        syn = getattr(lk, "synthesis", None)
        return {
            "name": self.spec.name,
            "units": self.spec.units,
            "linkage": lk.lengths(),
            "synthesis": None if syn is None else syn.to_dict(),
            "analysis": self.stroke.to_dict(),
            "windows": self.windows.to_dict(),
            "drive": self.spec.drive.to_dict(),
            "timing": {**self.timing.to_dict(), "margin_deg": deg(self.spec.timing.margin),
                       "placement": self.spec.timing.placement},
            "cam": self.solve.to_dict(),
            **({} if self.assessment is None else self.assessment.to_dict()),
            "overlap": self.overlap,
            "bore": self.bore,
            "notes": self.notes,
            "diagram": self.diagram.to_dict(),
        }


def design_machine(spec: MachineSpec, *, method: str | None = None) -> MachineResult:
    """Windows, cam timing, the cam's design and the cycle diagram of a machine.

    Parameters
    ----------
    spec : MachineSpec
    method : str, optional
        Override of the cam solver's method.

    Returns
    -------
    MachineResult
        With ``[cam] bore_radius`` its ``bore`` compares the bore with the
        sized cam's working profile (as ``cams check`` does).
    """
    from cams.solve import solve

    win = windows(spec.linkage, spec.cutting)
    tm = place_cam(win, spec.cam.program, spec.drive, spec.timing)
    design = spec.cam if method is None else spec.cam.with_(method=method)
    res = solve(design, objective=design.objective)
    unit = "rad" if isinstance(spec.cam.follower, Rocker) else spec.units
    dia = cycle_diagram(spec.linkage, win, spec.cutting, spec.cam.program, tm, follower_unit=unit)
    cam = Cam(design, solution=res)  # the cam just sized: assessed, not solved again
    assessment = cam.assessment  # one rule for every command (cams.assess): verified, buildable, certified
    return MachineResult(spec, win.stroke, win, tm, res, dia, _bore(cam), assessment)


def _bore(cam: Cam) -> dict | None:
    """The profile check of ``[cam] bore_radius`` (None without one, or without a profile): the working profile's
    smallest radius vs the bore."""
    bore = cam.options.bore_radius
    checks = cam.computed("checks")  # None: a knife edge in a groove, or no profile at the tolerance
    if bore is None or checks is None:
        return None
    rmin = cam.profile.min_work_radius
    return {"bore_radius": float(bore), "min_work_radius": float(rmin), "clear": bool(rmin > bore)}
