"""The crank-slider mechanism (seed 002): :class:`CrankSlider` and its kinematics.

Frames: :mod:`cams.machine.linkage.machines`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.machine.linkage.common import (
    LinkageBase,
    LinkStates,
    Pair,
    check_sign,
    still,
    verify_course,
)
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
from cams.machine.linkage.synthesis import crank_slider_crank
from laws.errors import check_number

__all__ = ["CrankSlider", "CrankSliderKinematics"]


# --------------------------------------------------------------------------- crank-slider
@dataclass(frozen=True, eq=False)
class CrankSliderKinematics:
    """Points and links of :class:`CrankSlider`.

    Attributes
    ----------
    phi : ndarray
    A : Point
        Crank pin.
    crank, rod : Angle
        Crank OA and rod (direction A -> B); ``rod.omega`` is the seed's omega_2.
    B : Point
        Slider (piston) pin.
    slider : Slide
        x_B along the slider's line and its derivatives.
    S : Point or None
        The rod's centre of mass S2 (when ``rod_cg`` is given).
    transmission : ndarray
        90 deg minus the angle between the rod and the slider's line, radians.
    """

    phi: np.ndarray
    A: Point
    crank: Angle
    rod: Angle
    B: Point
    slider: Slide
    S: Point | None
    transmission: np.ndarray


@dataclass(frozen=True, eq=False)
class CrankSlider(LinkageBase):
    """Crank-slider mechanism (seed 002), central or offset.

    Frame: origin at the crank centre O, the slider's line is ``y = offset``
    directed along +x.

    Parameters
    ----------
    crank : float
        l_OA.
    rod : float
        l_AB, > l_OA + |offset|.
    offset : float, optional
        e, the slider line's y.
    slider_side : {+1, -1}
        Slider on the +x side of the crank (+1; the seed's F = -1) or -x.
    rod_cg : float or None
        l_AS2, distance of the rod's centre of mass from A.
    crank_sense : {+1, -1}
    rpm : float or None
    """

    crank: float
    rod: float
    offset: float = 0.0
    slider_side: int = 1
    rod_cg: float | None = None
    crank_sense: int = 1
    rpm: float | None = None

    kind = "crank_slider"
    _output = "slider"  # x_B along the slider's line
    links = ("crank", "rod", "slider")  # seed 002: links 1..3
    pairs = (
        Pair("O", "revolute", "crank"),
        Pair("A", "revolute", "rod", "crank"),
        Pair("B", "revolute", "slider", "rod"),
        Pair("B_guide", "prismatic", "slider"),
    )

    def __post_init__(self):
        check_number("linkage.crank", self.crank, lo=0.0, strict=True)
        check_number("linkage.rod", self.rod, lo=0.0, strict=True)
        check_number("linkage.offset", self.offset)
        check_sign("linkage.slider_side", self.slider_side, ("right", "left"))
        if self.rod_cg is not None:
            check_number("linkage.rod_cg", self.rod_cg)
        self._check_common()
        need = self.crank + abs(self.offset)
        if not self.rod > need:
            raise AssemblyError(
                "linkage.rod",
                f"a rod of {self.rod:.6g} cannot follow the crank all the way round; "
                f"it needs l_AB > l_OA + |e| = {need:.6g}",
            )

    @classmethod
    def from_stroke(cls, stroke: float, rod: float, *, offset: float = 0.0, **kw) -> CrankSlider:
        """Synthesis from the stroke H and the rod (seed 002, formula 1.1: l_OA = H/2 when central).

        Examples
        --------
        >>> CrankSlider.from_stroke(0.35, 1.4).crank
        0.175
        """
        m = cls(crank=crank_slider_crank(stroke, rod, offset), rod=rod, offset=offset, **kw)
        verify_course(m, stroke=float(stroke), allowed="a shorter stroke, a longer rod or a smaller offset")
        return m

    @property
    def extreme_positions(self) -> tuple[float, float]:
        """x_B at the dead positions, (far, near) from O along the slider side (seed 1.2, 1.3)."""
        e = self.offset
        far = np.sqrt((self.rod + self.crank) ** 2 - e**2)
        near = np.sqrt((self.rod - self.crank) ** 2 - e**2)
        return float(self.slider_side * far), float(self.slider_side * near)

    def kinematics(self, phi, *, omega: float | None = None) -> CrankSliderKinematics:
        """Positions, velocities and accelerations at crank angles ``phi`` (radians)."""
        w = self._w(omega)
        phi = np.asarray(phi, dtype=float)

        def run(p):
            A, cr = crank(ground(0j), self.crank, p, omega=w)
            B, rod, sl = rrp(A, self.rod, ground(1j * self.offset), Angle(0.0, 0.0, 0.0), branch=self.slider_side,
                             field="linkage.rod")
            S = None if self.rod_cg is None else on_link(A, rod, self.rod_cg)
            mu = np.pi / 2 - acute_angle(rod.angle, 0.0)
            return CrankSliderKinematics(p, A, cr, rod, B, sl, S, mu)

        return self._assembled(run, phi)

    def lengths(self) -> dict:
        """Dimensions under the seed's names."""
        return self._lengths(
            l_OA=self.crank,
            l_AB=self.rod,
            e=self.offset,
            l_AS2=self.rod_cg,
            slider_side="right" if self.slider_side == 1 else "left",
        )

    def link_states(self, phi: np.ndarray, omega: float, cg) -> LinkStates:
        """The links' motion for the forces (:meth:`LinkageBase.link_states`): the slider slides along x."""
        k = self.kinematics(phi, omega=omega)
        zero = np.zeros_like(phi)
        O = Point(zero + 0j, zero + 0j, zero + 0j)
        rod_cg = self.rod_cg if self.rod_cg is not None else self.rod / 2
        cgs = {"crank": on_link(O, k.crank, cg("crank", 0.0)), "rod": on_link(k.A, k.rod, cg("rod", rod_cg)),
               "slider": k.B}
        angles = {"crank": k.crank, "rod": k.rod, "slider": still(phi)}
        points = {"O": O.pos, "A": k.A.pos, "B": k.B.pos, "B_guide": k.B.pos}
        return LinkStates(cgs, angles, points, {"B_guide": np.ones_like(phi, dtype=complex)})
