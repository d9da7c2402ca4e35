"""The two-cylinder mechanism of seed 000: :class:`OpposedTwin` and its kinematics.

Frames: :mod:`cams.machine.linkage.machines`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.machine.linkage.common import LinkageBase, LinkStates, Pair, still
from cams.machine.linkage.primitives import (
    Angle,
    AssemblyError,
    Point,
    Slide,
    acute_angle,
    crank,
    ground,
    on_link,
    rrp,
)
from laws.errors import check_number

__all__ = ["OpposedTwin", "OpposedTwinKinematics"]


# --------------------------------------------------------------------------- two-cylinder mechanism
@dataclass(frozen=True, eq=False)
class OpposedTwinKinematics:
    """Points and links of :class:`OpposedTwin` (seed 000's names: 1 crank, 2/4 rods, 3/5 pistons).

    ``transmission`` is the smaller of the two pistons' transmission angles,
    radians; the machine's output is piston 3 (B, right cylinder).
    """

    phi: np.ndarray
    A: Point
    C: Point
    B: Point
    D: Point
    rod2: Angle
    rod4: Angle
    S2: Point
    S4: Point
    piston3: Slide
    piston5: Slide
    transmission: np.ndarray


@dataclass(frozen=True, eq=False)
class OpposedTwin(LinkageBase):
    """Two-cylinder mechanism of seed 000: one crank with pins A and C, two rods, two pistons.

    Frame: origin at the crank centre O; both pistons move on the x axis, B on
    the +x side (right cylinder), D on the -x side (left). The crank pin C
    leads A by ``phase`` (counter-clockwise): seed 000 draws OC perpendicular
    to OA; with C at +90 deg its graphical velocities are reproduced (with
    -90 deg they are not, see tests).

    Parameters
    ----------
    crank : float
        l_OA = l_OC.
    rod : float
        l_AB = l_CD.
    rod_cg : float
        l_AS2 = l_CS4.
    phase : float, optional
        Angle from OA to OC, radians (default pi/2).
    crank_sense : {+1, -1}
    rpm : float or None
    """

    crank: float
    rod: float
    rod_cg: float
    phase: float = np.pi / 2
    crank_sense: int = 1
    rpm: float | None = None

    kind = "opposed_twin"
    _output = "piston3"  # x_B of piston 3 (B, right cylinder)
    links = ("crank", "rod2", "piston3", "rod4", "piston5")  # seed 000: links 1..5
    pairs = (
        Pair("O", "revolute", "crank"),
        Pair("A", "revolute", "rod2", "crank"),
        Pair("B", "revolute", "piston3", "rod2"),
        Pair("B_guide", "prismatic", "piston3"),
        Pair("C", "revolute", "rod4", "crank"),
        Pair("D", "revolute", "piston5", "rod4"),
        Pair("D_guide", "prismatic", "piston5"),
    )

    def __post_init__(self):
        check_number("linkage.crank", self.crank, lo=0.0, strict=True)
        check_number("linkage.rod", self.rod, lo=0.0, strict=True)
        check_number("linkage.rod_cg", self.rod_cg)
        check_number("linkage.phase", self.phase)
        self._check_common()
        if not self.rod > self.crank:
            raise AssemblyError("linkage.rod",
                                f"the rods must be longer than the crank ({self.crank:.6g}), got {self.rod:.6g}")

    def kinematics(self, phi, *, omega: float | None = None) -> OpposedTwinKinematics:
        """Positions, velocities and accelerations at crank angles ``phi`` (angle of OA, radians)."""
        w = self._w(omega)
        phi = np.asarray(phi, dtype=float)
        x_axis = Angle(0.0, 0.0, 0.0)
        A, _ = crank(ground(0j), self.crank, phi, omega=w)
        C, _ = crank(ground(0j), self.crank, phi + self.phase, omega=w)
        B, rod2, p3 = rrp(A, self.rod, ground(0j), x_axis, branch=1, field="linkage.rod")
        D, rod4, p5 = rrp(C, self.rod, ground(0j), x_axis, branch=-1, field="linkage.rod")
        S2, S4 = on_link(A, rod2, self.rod_cg), on_link(C, rod4, self.rod_cg)
        mu = np.minimum(np.pi / 2 - acute_angle(rod2.angle, 0.0), np.pi / 2 - acute_angle(rod4.angle, 0.0))
        return OpposedTwinKinematics(phi, A, C, B, D, rod2, rod4, S2, S4, p3, p5, mu)

    def lengths(self) -> dict:
        """Dimensions under the seed's names."""
        return self._lengths(
            l_OA=self.crank,
            l_AB=self.rod,
            l_AS2=self.rod_cg,
            phase_deg=float(np.degrees(self.phase)),
        )

    def link_states(self, phi: np.ndarray, omega: float, cg) -> LinkStates:
        """The links' motion for the forces (:meth:`LinkageBase.link_states`): both pistons slide along x."""
        k = self.kinematics(phi, omega=omega)
        zero = np.zeros_like(phi)
        O = Point(zero + 0j, zero + 0j, zero + 0j)
        crank_ = Angle(k.phi + zero, np.full_like(phi, omega), zero.copy())
        cgs = {
            "crank": on_link(O, crank_, cg("crank", 0.0)),
            "rod2": on_link(k.A, k.rod2, cg("rod2", self.rod_cg)),
            "piston3": k.B,
            "rod4": on_link(k.C, k.rod4, cg("rod4", self.rod_cg)),
            "piston5": k.D,
        }
        angles = {"crank": crank_, "rod2": k.rod2, "piston3": still(phi), "rod4": k.rod4, "piston5": still(phi)}
        points = {"O": O.pos, "A": k.A.pos, "B": k.B.pos, "B_guide": k.B.pos, "C": k.C.pos, "D": k.D.pos,
                  "D_guide": k.D.pos}
        x = np.ones_like(phi, dtype=complex)
        return LinkStates(cgs, angles, points, {"B_guide": x, "D_guide": x})
