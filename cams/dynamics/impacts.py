"""Rigid impacts: the program's velocity jumps, where the follower's acceleration is infinite.

Rigid impacts
-------------
Where the program's velocity analogue ``dq/dphi`` jumps (a *hard impact* of
:func:`laws.diagnostics.find_impacts`: a constant-velocity law meeting a
dwell) the follower's acceleration is infinite, so no finite force model
applies there (DYNACAM shows the force as infinite):

* a jump *up* (``dq'`` > 0, e.g. the start of a linear rise, the end of a
  linear return) needs an impulse from the cam: the contact force and the
  camshaft torque are unbounded (:attr:`CamForces.unbounded`);
* a jump *down* (the end of a linear rise, the start of a linear return)
  needs an infinite pull from the spring: the follower leaves the cam at any
  speed (:attr:`CamForces.separation`, a jump speed of 0).

:class:`CamForces` lists them (:attr:`CamForces.impacts`); its sampled
arrays hold the forces *between* the impacts, its ``ok`` is False with any
of them, and its report gives the unbounded values as such (``inf``, with
the finite values between the impacts under ``between_impacts``).
:func:`jump_speed` returns 0 rpm at a jump down.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.model.design import Design

__all__ = ["RigidImpact", "rigid_impacts"]


@dataclass(frozen=True)
class RigidImpact:
    """A velocity jump of the follower (a hard impact): infinite acceleration at one cam angle.

    Attributes
    ----------
    phi : float
        Cam angle, radians from the program's start, in [0, 2 pi).
    jump : float
        ``dq/dphi`` after minus before: radians per radian (rocker) or design
        length unit per radian (translating).
    rocker : bool
        The follower is a rocker (``q`` an angle).
    """

    phi: float
    jump: float
    rocker: bool

    @property
    def separation(self) -> bool:
        """A jump down: the spring would have to pull infinitely hard, the follower leaves the cam at any speed."""
        return self.jump < 0

    @property
    def effect(self) -> str:
        """``"impulse"`` (jump up: unbounded contact force) or ``"separation"`` (jump down: contact lost)."""
        return "separation" if self.separation else "impulse"

    @property
    def unit(self) -> str:
        """Unit of :meth:`shown_jump` (JSON, text): ``"deg/s"`` for a rocker, ``"mm/s"`` otherwise."""
        return "deg/s" if self.rocker else "mm/s"

    def velocity_jump(self, omega: float, length_unit: float = 1e-3) -> float:
        """The follower's velocity jump at the cam speed ``omega`` (rad/s).

        rad/s for a rocker, mm/s for a translating follower; ``length_unit``
        (metres per design unit) converts the design's unit to mm.
        """
        v = self.jump * abs(omega)
        return float(v) if self.rocker else float(v * length_unit * 1e3)

    def shown_jump(self, omega: float, length_unit: float = 1e-3) -> float:
        """:meth:`velocity_jump` in the :attr:`unit` shown to the user: deg/s (rocker) or mm/s."""
        v = self.velocity_jump(omega, length_unit)
        return float(np.degrees(v)) if self.rocker else v

    def to_dict(self, omega: float, length_unit: float = 1e-3) -> dict:
        """JSON-ready: cam angle in degrees, the velocity jump at ``omega`` (in :attr:`unit`) and its effect."""
        return {"cam_angle_deg": float(np.degrees(self.phi)), "velocity_jump": self.shown_jump(omega, length_unit),
                "unit": self.unit, "effect": self.effect}


def rigid_impacts(design: Design) -> tuple[RigidImpact, ...]:
    """The program's velocity jumps (:func:`laws.diagnostics.find_impacts`, hard ones), sorted by cam angle.

    Any follower, roller or flat face: a rocker's (``kind == "rocker"``) jumps are in rad/s.

    Examples
    --------
    >>> from cams.model.design import CamDesign, Limits
    >>> from cams.model.follower import Translating
    >>> from laws.program import Phase, Program
    >>> prog = Program((Phase("rise", np.pi, "linear"), Phase("return", np.pi, "cycloidal")), 20.0)
    >>> d = CamDesign(Translating(5.0, offset=0.0), prog, Limits(np.radians(30)))
    >>> [(round(float(np.degrees(i.phi))), i.effect) for i in rigid_impacts(d)]
    [(0, 'impulse'), (180, 'separation')]
    """
    from laws.diagnostics import find_impacts

    rocker = design.follower.kind == "rocker"
    return tuple(RigidImpact(float(i.phi), float(i.size), rocker)
                 for i in find_impacts(design.program) if i.kind == "hard")
