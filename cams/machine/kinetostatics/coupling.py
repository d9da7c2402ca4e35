"""The forces of a machine with its cam: the linkage's kinetostatics, its flywheel and the cam's forces.

:func:`machine_forces` samples the linkage at cycle angles from position 1
(:class:`cams.machine.timing.Windows`), so that every angle it reports is a
cycle angle, and maps the cam's angles to cycle angles through the cam's
timing (:class:`cams.machine.timing.CamTiming`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from cams.machine.kinetostatics.loads import cycle_turns
from cams.machine.kinetostatics.result import ForceResult
from cams.machine.kinetostatics.solve import analyse_forces
from laws.errors import InputError
from laws.units import TWO_PI

if TYPE_CHECKING:
    from cams.dynamics.forces import CamForces
    from cams.dynamics.jump import JumpSpeed
    from cams.machine.flywheel import FlywheelResult
    from cams.machine.timing import CamTiming
    from cams.model.dynamics import Spring

__all__ = ["MachineForces", "machine_forces", "CYCLE_ANGLE", "CAM_ANGLE"]


@dataclass(frozen=True, eq=False)
class MachineForces:
    """Forces of a machine with its cam: the linkage, its flywheel, the cam.

    Attributes
    ----------
    linkage : ForceResult or None
        Without a ``[forces]`` table: None.
    flywheel : cams.machine.flywheel.FlywheelResult or None
        With ``[forces] delta``.
    cam : cams.dynamics.forces.CamForces or None
        With a ``[dynamics]`` table and force closure.
    spring : cams.dynamics.forces.Spring or None
    jump : cams.dynamics.forces.JumpSpeed or None
    notes : tuple of str
    """

    linkage: ForceResult | None = None
    flywheel: FlywheelResult | None = None
    cam: CamForces | None = None
    spring: Spring | None = None
    jump: JumpSpeed | None = None
    notes: tuple[str, ...] = ()
    cam_timing: CamTiming | None = None

    @property
    def ok(self) -> bool:
        """The cam keeps contact and does not jam (True without cam forces)."""
        return self.cam is None or bool(self.cam.ok)

    def cycle_angles(self, cam_angle) -> np.ndarray:
        """Cycle angles (radians from position 1, in [0, 2 pi q)) at which the cam is at ``cam_angle``.

        The cam's program angle ``theta`` is reached at ``mount + (theta + 2 pi j) / ratio``
        for each of its ``p`` turns ``j`` in the repeating period of ``q`` crank
        turns (:class:`cams.machine.timing.CamTiming`); sorted. Empty without the cam's timing.
        """
        t = self.cam_timing
        if t is None:
            return np.zeros(0)
        p, q = t.period
        c = t.mount + (float(cam_angle) + TWO_PI * np.arange(p)) / t.ratio
        return np.sort(np.mod(c, TWO_PI * q))

    def to_dict(self) -> dict:
        """JSON-ready report."""
        out: dict = {"notes": list(self.notes)}
        if self.linkage is not None:
            out["linkage"] = self.linkage.to_dict()
        if self.flywheel is not None:
            fw = self.flywheel.to_dict()
            fw.pop("curves")
            out["flywheel"] = fw
        if self.cam is not None:
            from cams.dynamics.jump import jump_dict

            spring = self.spring
            assert spring is not None  # found with the cam's forces (cams.dynamics.forces.design_forces)
            cam = {**self.cam.to_dict(), "spring": spring.to_dict(self.cam.length_unit),
                   **jump_dict(self.jump), "ok": bool(self.cam.ok)}
            if "between_impacts" in cam and self.jump is not None:
                cam["between_impacts"]["jump_rpm"] = self.jump.between_impacts_rpm
            if self.cam_timing is not None:
                cam["angle_reference"] = (f"*_at_deg, cam_angle_deg: {CAM_ANGLE}; "
                                          f"*_at_cycle_deg, cycle_deg: {CYCLE_ANGLE} "
                                          f"(every time the cam is there in {self.cam_timing.period[1]} crank turn(s))")

                def cyc(a):
                    return None if a is None else [float(np.degrees(c)) for c in self.cycle_angles(np.radians(a))]

                for key in ("max_contact_at", "max_torque_at", "max_driving_torque_at", "max_braking_torque_at",
                            "jump_at"):
                    cam[key + "_cycle_deg"] = cyc(cam.get(key + "_deg"))
                for imp in cam["impacts"]:
                    imp["cycle_deg"] = cyc(imp["cam_angle_deg"])
            else:
                cam["angle_reference"] = f"*_at_deg, cam_angle_deg: {CAM_ANGLE}"
            out["cam"] = cam
        return out


CYCLE_ANGLE = "cycle angle from position 1"
"""How a machine's reports name their crank angles: the crank's rotation from position 1
(:mod:`cams.machine.timing`)."""
CAM_ANGLE = "cam angle from the start of its program"


def machine_forces(spec, centre=None, *, found=None) -> MachineForces:
    """Forces of a machine file's machine (:class:`cams.machine.design.MachineSpec`).

    Parameters
    ----------
    spec : MachineSpec
        ``spec.forces`` and ``spec.force_options`` (from ``[forces]``) give the linkage's data;
        ``spec.cam.dynamics`` (from ``[dynamics]``) the follower's.
    centre : array_like or None
        The cam's centre (``SolveResult.centre``); needed for the cam's forces.
    found : cams.machine.design.MachineResult, optional
        What :func:`cams.machine.design.design_machine` found for ``spec``: its
        windows, cam timing and (without ``centre``) the cam's centre are
        used, not found again.

    Returns
    -------
    MachineForces
        The linkage's forces sampled at ``opt.samples`` equal steps a turn of
        the cycle angle from position 1 (:class:`cams.machine.timing.Windows`), so
        that their angles (``rotation``, ``to_dict``'s ``at_deg``, the plots)
        and the flywheel's are cycle angles, as the machine's windows; over
        two turns (0 to 720 degrees) with a gas table of period 720; the cam's
        timing (:class:`cams.machine.timing.CamTiming`) to map the cam's angles to
        cycle angles.
    """

    from cams.dynamics.forces import design_forces
    from cams.machine.timing import place_cam, windows

    notes = []
    lk = fw = cf = spring = jump = None
    if found is not None:
        win = found.windows
        centre = found.solve.centre if centre is None else centre
    else:
        win = windows(spec.linkage, spec.cutting)
    fs, opt = spec.forces, spec.force_options
    if fs is not None:
        turns = cycle_turns(fs)
        c = np.linspace(0.0, TWO_PI * turns, opt.samples * turns, endpoint=False)
        lk = analyse_forces(spec.linkage, fs, phi=win.frame_angle(c), passes=opt.passes, origin=win.origin)
        lk = replace(lk, reference=CYCLE_ANGLE)
        if turns == 2:
            notes.append("a gas table of period 720 deg: the linkage's forces and the flywheel cover two crank turns, "
                         "cycle angles 0 to 720 deg from position 1 (the table's angle 0 where the crank first passes "
                         "its start)")
        if opt.delta is not None:
            try:
                fw = lk.flywheel(delta=opt.delta, interpolation=opt.interpolation, cycle=TWO_PI * turns)
            except InputError as e:
                if e.field != "flywheel.inertia":
                    raise
                # nothing keeps the crank turning where neither the linkage nor a flywheel has inertia
                raise InputError("forces.links", "the machine has no inertia at some crank angle, so no flywheel can "
                                 "be sized for forces.delta: give the links' masses and the crank's moment of inertia "
                                 "([forces.links.crank] inertia)") from None
    else:
        notes.append("no [forces] table: no linkage forces")
    if spec.cam.dynamics is not None and centre is None:
        notes.append("no cam centre: no cam forces")
    elif centre is not None:
        df, note = design_forces(spec.cam, centre)
        if note:
            notes.append(note)
        if df is not None:
            from cams.dynamics.forces import impact_note

            cf, spring, jump = df.forces, df.spring, df.jump
            note = impact_note(cf)
            if note:
                notes.append(note)
    timing = None
    if cf is not None:
        timing = found.timing if found is not None else place_cam(win, spec.cam.program, spec.drive, spec.timing)
    return MachineForces(lk, fw, cf, spring, jump, tuple(notes), timing)
