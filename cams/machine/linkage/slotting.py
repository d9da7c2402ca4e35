"""The slotting machine's six-bar linkage (seed 003): :class:`SlottingMachine` and its kinematics.

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
    AssemblyError,
    Point,
    Slide,
    acute_angle,
    crank,
    ground,
    on_link,
    rpr,
    rrp,
)
from cams.machine.linkage.synthesis import (
    MAX_TIME_RATIO,
    SlottedLeverSynthesis,
    rounded_down,
    slotted_lever_synthesis,
    slotting_time_ratio_limit,
)
from laws.errors import check_number

__all__ = ["SlottingMachine", "SlottingKinematics"]


# --------------------------------------------------------------------------- slotting machine
@dataclass(frozen=True, eq=False)
class SlottingKinematics:
    """Every point and link of :class:`SlottingMachine` at crank angles ``phi``.

    Attributes
    ----------
    phi : ndarray
        Crank angles, radians (frame).
    A : Point
        Crank pin (block 3 on the bar).
    crank, bar, rod : Angle
        Crank O2A, guide bar (direction O3 -> A), link BC (direction B -> C).
    slide : Slide
        The block's distance from O3 along the bar, the relative sliding
        velocity v_A3A2 (here: of the block relative to the bar) and
        acceleration a^r.
    B, C : Point
        Bar pin B and tool point C.
    tool : Slide
        The tool's coordinate y_C along y-y and its derivatives.
    transmission : ndarray
        Transmission angle at C: 90 deg minus the angle between BC and y-y, radians
        (the bar's is 90 deg throughout).
    """

    phi: np.ndarray
    A: Point
    crank: Angle
    bar: Angle
    slide: Slide
    B: Point
    rod: Angle
    C: Point
    tool: Slide
    transmission: np.ndarray

    @property
    def coriolis(self) -> np.ndarray:
        """Magnitude of the block's Coriolis acceleration on the turning bar, 2 |omega_3 v_rel|."""
        return 2 * np.abs(self.bar.omega * self.slide.ds)


@dataclass(frozen=True, eq=False)
class SlottingMachine(SwingingLever):
    """The slotting machine's six-bar linkage (seed 003, 六杆插床机构).

    Frame: origin at the crank centre O2 (the feed cam's shaft), +x from the
    bar pivot O3 to O2, so ``O3 = (-L, 0)``; the tool's guide y-y is the line
    ``x = guide_x``, the tool moves along y.

    Parameters
    ----------
    crank : float
        l_O2A, > 0 and < ``centre_distance``.
    centre_distance : float
        L_O2O3.
    bar : float
        l_O3B.
    rod : float
        l_BC.
    guide_x : float
        x of the tool's guide y-y.
    bar_side : {-1, +1}
        -1: B on the far side of O3 from the crank (the usual 插床 layout, and
        the only one possible when l_O3B falls in the block's travel); +1: B
        on the crank's side.
    tool_side : {+1, -1}
        Branch of the RRP dyad: C on the +y side of B (+1) or the -y side.
    crank_sense : {+1, -1}
        Crank turns counter-clockwise (+1) or clockwise.
    rpm : float or None
        Crank speed, rev/min.
    synthesis : SlottedLeverSynthesis or None
        Course data the lengths came from (informational).

    Raises
    ------
    InputError
        Non-positive lengths, a crank not shorter than L, B inside the block's
        travel.
    AssemblyError
        BC cannot reach y-y at some crank angle; the message gives those
        angles and the shortest l_BC that fits.
    """

    crank: float
    centre_distance: float
    bar: float
    rod: float
    guide_x: float
    bar_side: int = -1
    tool_side: int = 1
    crank_sense: int = 1
    rpm: float | None = None
    synthesis: SlottedLeverSynthesis | None = field(default=None, compare=False)

    kind = "slotting"
    _output = "tool"  # y_C of the tool along y-y
    links = ("crank", "block", "bar", "rod", "tool")  # seed 003: links 1..5
    pairs = (
        Pair("O2", "revolute", "crank"),
        Pair("A", "revolute", "block", "crank"),
        Pair("A_slot", "prismatic", "block", "bar"),
        Pair("O3", "revolute", "bar"),
        Pair("B", "revolute", "rod", "bar"),
        Pair("C", "revolute", "tool", "rod"),
        Pair("C_guide", "prismatic", "tool"),
    )

    def __post_init__(self):
        lengths = (("crank", self.crank), ("centre_distance", self.centre_distance), ("bar", self.bar),
                   ("rod", self.rod))
        for f, v in lengths:
            check_number(f"linkage.{f}", v, lo=0.0, strict=True)
        check_number("linkage.guide_x", self.guide_x)
        check_sign("linkage.bar_side", self.bar_side, ("same", "opposite"))
        check_sign("linkage.tool_side", self.tool_side, ("above", "below"))
        self._check_common()
        swing_bar_checks(self.crank, self.centre_distance, self.bar, self.bar_side, "guide bar", "linkage.bar")
        # BC must reach y-y at every swing: x_B = -L + side*bar*cos(beta), |beta| <= theta/2;
        # the farthest B is at the bar's mid-position (crank at 0 or 180 deg) or at its ends (dead positions)
        half = self.half_swing
        xb = -self.centre_distance + self.bar_side * self.bar * np.array([1.0, np.cos(half)])
        dev = np.abs(self.guide_x - xb)
        need = float(np.max(dev))
        if self.rod < need:
            try:
                self._check_assembly()
                where = "0, 180" if dev[0] >= dev[1] else f"{90 + np.degrees(half):.1f}, {270 - np.degrees(half):.1f}"
                where = f"near {where} deg"
            except AssemblyError as e:
                where = e.message.rsplit("fails at crank angles ", 1)[-1]
            raise AssemblyError(
                "linkage.rod",
                f"link BC of {self.rod:.6g} cannot reach the guide y-y at crank angles {where}; "
                f"it needs l_BC >= {need:.6g} (or y-y moved toward B's arc)",
            )

    @classmethod
    def from_course(
        cls,
        time_ratio: float,
        stroke: float,
        centre_distance: float,
        rod_ratio: float,
        *,
        bar_side: int = -1,
        tool_side: int = 1,
        crank_sense: int = 1,
        rpm: float | None = None,
    ) -> SlottingMachine:
        """Synthesis from the course data (seed 003, table 1-1): K, H, L_O2O3, l_BC/l_O3B.

        The guide y-y goes through the middle of the sagitta of B's arc (the
        seed's "most favourable" position for BC driving the tool).

        Examples
        --------
        >>> m = SlottingMachine.from_course(2.0, 100.0, 150.0, 1.0)
        >>> round(m.crank, 9), round(m.bar, 9), round(m.rod, 9)
        (75.0, 100.0, 100.0)
        """
        check_sign("linkage.bar_side", bar_side, ("same", "opposite"))
        syn = slotted_lever_synthesis(time_ratio, stroke, centre_distance, rod_ratio)
        assert syn.rod is not None and syn.rod_ratio is not None  # a rod_ratio gives the rod
        m = cls(
            crank=syn.crank,
            centre_distance=syn.centre_distance,
            bar=syn.bar,
            rod=syn.rod,
            guide_x=-syn.centre_distance + bar_side * syn.guide_distance,
            bar_side=bar_side,
            tool_side=tool_side,
            crank_sense=crank_sense,
            rpm=rpm,
            synthesis=syn,
        )
        kmax = min(slotting_time_ratio_limit(syn.rod_ratio), MAX_TIME_RATIO)
        verify_course(m, stroke=syn.stroke, time_ratio=syn.time_ratio,
                  allowed=f"a slotting linkage with rod_ratio = {syn.rod_ratio:.6g} allows 1 < K < "
                          f"{rounded_down(kmax)}")
        return m

    def kinematics(self, phi, *, omega: float | None = None) -> SlottingKinematics:
        """Positions, velocities and accelerations at crank angles ``phi`` (radians)."""
        w = self._w(omega)
        phi = np.asarray(phi, dtype=float)

        def run(p):
            A, cr = crank(ground(0j), self.crank, p, omega=w)
            bar, slide = rpr(A, ground(-self.centre_distance + 0j), field="linkage.bar")
            B = on_link(ground(-self.centre_distance + 0j), bar, self.bar_side * self.bar)
            up = Angle(np.pi / 2, 0.0, 0.0)
            C, rod, tool = rrp(B, self.rod, ground(self.guide_x + 0j), up, branch=self.tool_side, field="linkage.rod")
            mu = np.pi / 2 - acute_angle(rod.angle, np.pi / 2)
            return SlottingKinematics(p, A, cr, bar, slide, B, rod, C, tool, mu)

        return self._assembled(run, phi)

    def lengths(self) -> dict:
        """The linkage's dimensions under the seed's names (length unit of the machine)."""
        return self._lengths(
            l_O2A=self.crank,
            L_O2O3=self.centre_distance,
            l_O3B=self.bar,
            l_BC=self.rod,
            x_yy=self.guide_x,
            swing_deg=float(np.degrees(2 * self.half_swing)),
            bar_side="same" if self.bar_side == 1 else "opposite",
            tool_side="above" if self.tool_side == 1 else "below",
        )

    def link_states(self, phi: np.ndarray, omega: float, cg) -> LinkStates:
        """The links' motion for the forces (:meth:`LinkageBase.link_states`): the tool slides on y-y."""
        k = self.kinematics(phi, omega=omega)
        zero = np.zeros_like(phi)
        O2 = Point(zero + 0j, zero + 0j, zero + 0j)
        O3 = Point(zero - self.centre_distance + 0j, zero + 0j, zero + 0j)
        cgs = {
            "crank": on_link(O2, k.crank, cg("crank", 0.0)),
            "block": k.A,
            "bar": on_link(O3, k.bar, self.bar_side * cg("bar", self.bar / 2)),
            "rod": on_link(k.B, k.rod, cg("rod", self.rod / 2)),
            "tool": k.C,
        }
        angles = {"crank": k.crank, "block": k.bar, "bar": k.bar, "rod": k.rod, "tool": still(phi)}
        points = {"O2": O2.pos, "A": k.A.pos, "A_slot": k.A.pos, "O3": O3.pos, "B": k.B.pos, "C": k.C.pos,
                  "C_guide": k.C.pos}
        axes = {"A_slot": k.bar.unit, "C_guide": np.full_like(phi, 1j, dtype=complex)}
        return LinkStates(cgs, angles, points, axes)
