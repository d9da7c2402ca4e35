"""The pump with a swinging slotted lever (seed 004): :class:`SlottedLeverPump` and its kinematics.

Frames: :mod:`cams.machine.linkage.machines`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from cams.machine.linkage.common import (
    LinkStates,
    Pair,
    SwingingLever,
    check_sign,
    still,
    swing_bar_checks,
    verify_course,
)
from cams.machine.linkage.primitives import (
    Angle,
    Point,
    Slide,
    acute_angle,
    crank,
    ground,
    on_link,
    rpp,
    rpr,
)
from cams.machine.linkage.synthesis import (
    MAX_TIME_RATIO,
    SlottedLeverSynthesis,
    slotted_lever_synthesis,
)
from laws.errors import check_number

__all__ = ["SlottedLeverPump", "PumpKinematics"]


# --------------------------------------------------------------------------- pump
@dataclass(frozen=True, eq=False)
class PumpKinematics:
    """Points and links of :class:`SlottedLeverPump`.

    Attributes
    ----------
    phi : ndarray
    A : Point
        Crank pin (block on the lever).
    crank, lever : Angle
        Crank O1A and lever (direction O2 -> A).
    slide : Slide
        The block's distance from O2 along the lever and its relative motion.
    C : Point
        The lever's pin C.
    piston : Slide
        Piston coordinate along its (y) guide and its derivatives.
    block : Slide
        The pin's block in the piston's slot (x).
    transmission : ndarray
        90 deg minus the angle between the lever and the slot, radians.
    """

    phi: np.ndarray
    A: Point
    crank: Angle
    lever: Angle
    slide: Slide
    C: Point
    piston: Slide
    block: Slide
    transmission: np.ndarray

    @property
    def coriolis(self) -> np.ndarray:
        """Magnitude of the block's Coriolis acceleration, 2 |omega_3 v_rel|."""
        return 2 * np.abs(self.lever.omega * self.slide.ds)


@dataclass(frozen=True, eq=False)
class SlottedLeverPump(SwingingLever):
    """Pump with a swinging slotted lever (seed 004): O1A, lever O2C, piston by a Scotch yoke.

    Frame: origin at the crank centre O1, +x from the lever's pivot O2 to O1
    (``O2 = (-L, 0)``); the piston moves along y on the line ``x = guide_x``
    and carries a slot along x in which the lever's pin C slides (seed 004's
    pairs: A3 and C5 sliding, E the piston's guide).

    Parameters
    ----------
    crank : float
        l_O1A < L.
    centre_distance : float
        L = O1O2.
    lever : float
        l_O2C.
    lever_side : {-1, +1}
        C on the far side of O2 from the crank (-1) or the crank's side (+1).
    guide_x : float, optional
        x of the piston's guide (does not affect the piston's motion).
    crank_sense : {+1, -1}
    rpm : float or None
    synthesis : SlottedLeverSynthesis or None
    """

    crank: float
    centre_distance: float
    lever: float
    lever_side: int = -1
    guide_x: float = 0.0
    crank_sense: int = 1
    rpm: float | None = None
    synthesis: SlottedLeverSynthesis | None = field(default=None, compare=False)

    kind = "slotted_lever_pump"
    _output = "piston"  # the piston's coordinate along its y guide
    links = ("crank", "block", "lever", "pin_block", "piston")  # seed 004: links 1..5
    pairs = (
        Pair("O1", "revolute", "crank"),
        Pair("A", "revolute", "block", "crank"),
        Pair("A_slot", "prismatic", "block", "lever"),
        Pair("O2", "revolute", "lever"),
        Pair("C", "revolute", "pin_block", "lever"),
        Pair("C_slot", "prismatic", "pin_block", "piston"),
        Pair("E", "prismatic", "piston"),
    )

    def __post_init__(self):
        for f, v in (("crank", self.crank), ("centre_distance", self.centre_distance), ("lever", self.lever)):
            check_number(f"linkage.{f}", v, lo=0.0, strict=True)
        check_number("linkage.guide_x", self.guide_x)
        check_sign("linkage.lever_side", self.lever_side, ("same", "opposite"))
        self._check_common()
        swing_bar_checks(self.crank, self.centre_distance, self.lever, self.lever_side, "slotted lever",
                          "linkage.lever")

    @classmethod
    def from_course(
        cls, time_ratio: float, stroke: float, centre_distance: float, *, lever_side: int = -1, **kw
    ) -> SlottedLeverPump:
        """Synthesis from K, H and O1O2 (seed 004, section 1.4).

        theta, l_O1A = L sin(theta/2), l_O2C = H / (2 sin(theta/2)).

        Examples
        --------
        >>> m = SlottedLeverPump.from_course(2.0, 250.0, 525.0)
        >>> round(m.crank, 9), round(m.lever, 9)
        (262.5, 250.0)
        """
        syn = slotted_lever_synthesis(time_ratio, stroke, centre_distance)
        m = cls(crank=syn.crank, centre_distance=syn.centre_distance, lever=syn.bar, lever_side=lever_side,
                synthesis=syn, **kw)
        verify_course(m, stroke=syn.stroke, time_ratio=syn.time_ratio,
                       allowed=f"a slotted-lever pump allows 1 < K <= {MAX_TIME_RATIO:g}")
        return m

    def kinematics(self, phi, *, omega: float | None = None) -> PumpKinematics:
        """Positions, velocities and accelerations at crank angles ``phi`` (radians)."""
        w = self._w(omega)
        phi = np.asarray(phi, dtype=float)

        def run(p):
            O2 = ground(-self.centre_distance + 0j)
            A, cr = crank(ground(0j), self.crank, p, omega=w)
            lev, slide = rpr(A, O2, field="linkage.lever")
            C = on_link(O2, lev, self.lever_side * self.lever)
            piston, block = rpp(C, self.guide_x + 0j, np.pi / 2, 0.0)
            mu = np.pi / 2 - acute_angle(lev.angle, 0.0)
            return PumpKinematics(p, A, cr, lev, slide, C, piston, block, mu)

        return self._assembled(run, phi)

    def lengths(self) -> dict:
        """Dimensions under the seed's names."""
        return self._lengths(
            l_O1A=self.crank,
            L_O1O2=self.centre_distance,
            l_O2C=self.lever,
            x_E=self.guide_x,
            swing_deg=float(np.degrees(2 * self.half_swing)),
            lever_side="same" if self.lever_side == 1 else "opposite",
        )

    def link_states(self, phi: np.ndarray, omega: float, cg) -> LinkStates:
        """The links' motion for the forces (:meth:`LinkageBase.link_states`): the piston slides along y at
        ``guide_x``."""
        k = self.kinematics(phi, omega=omega)
        zero = np.zeros_like(phi)
        O1 = Point(zero + 0j, zero + 0j, zero + 0j)
        O2 = Point(zero - self.centre_distance + 0j, zero + 0j, zero + 0j)
        E = Point(self.guide_x + 1j * k.piston.s, 1j * k.piston.ds, 1j * k.piston.d2s)
        cgs = {
            "crank": on_link(O1, k.crank, cg("crank", 0.0)),
            "block": k.A,
            "lever": on_link(O2, k.lever, self.lever_side * cg("lever", self.lever / 2)),
            "pin_block": k.C,
            "piston": E,
        }
        angles = {"crank": k.crank, "block": k.lever, "lever": k.lever, "pin_block": still(phi), "piston": still(phi)}
        points = {"O1": O1.pos, "A": k.A.pos, "A_slot": k.A.pos, "O2": O2.pos, "C": k.C.pos, "C_slot": k.C.pos,
                  "E": E.pos}
        axes = {"A_slot": k.lever.unit, "C_slot": np.ones_like(phi, dtype=complex),
                "E": np.full_like(phi, 1j, dtype=complex)}
        return LinkStates(cgs, angles, points, axes)
