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

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from cams.machine.linkage.primitives import (
    Angle,
    AssemblyError,
    Point,
    Slide,
    acute_angle,
    crank,
    ground,
    on_link,
    rpp,
    rpr,
    rrp,
)
from cams.machine.linkage.analysis import analyse
from cams.model.follower import rotation_word
from laws.errors import show_value as _show
from cams.machine.linkage.synthesis import (
    MAX_TIME_RATIO,
    SlottedLeverSynthesis,
    _below,
    crank_slider_crank,
    slotted_lever_synthesis,
    slotting_time_ratio_limit,
)
from laws.errors import InfeasibleError, InputError
from laws.units import rpm_to_omega

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

TWO_PI = 2 * np.pi
_CHECK_GRID = np.linspace(0.0, TWO_PI, 1440, endpoint=False)


def describe_angles(phi: np.ndarray, mask: np.ndarray, *, periodic: bool = False) -> str:
    """Contiguous runs of ``phi[mask]`` as text in degrees, e.g. ``"10.0-35.5 deg"``.

    Parameters
    ----------
    phi : ndarray
        Crank angles, radians, increasing.
    mask : ndarray of bool
        Selected entries.
    periodic : bool, optional
        ``phi`` covers one turn: a run touching both ends is one run across 0.

    Examples
    --------
    >>> describe_angles(np.radians([0, 10, 20, 30, 40]), np.array([0, 1, 1, 0, 1], bool))
    '10.0-20.0, 40.0 deg'
    >>> describe_angles(np.radians([0, 90, 180, 270]), np.array([1, 0, 0, 1], bool), periodic=True)
    '270.0-0.0 deg'
    """
    deg = np.degrees(np.ravel(phi))
    mask = np.ravel(np.broadcast_to(mask, np.shape(deg))).astype(bool)
    runs, start = [], None
    for k, m in enumerate(mask):
        if m and start is None:
            start = k
        if (not m or k == len(mask) - 1) and start is not None:
            runs.append([start, k if m else k - 1])
            start = None
    if periodic and len(runs) > 1 and runs[0][0] == 0 and runs[-1][1] == len(mask) - 1:
        runs[0][0] = runs.pop()[0]
    text = [f"{deg[a]:.1f}" if a == b else f"{deg[a]:.1f}-{deg[b]:.1f}" for a, b in runs]
    return ", ".join(text) + " deg"


def _num(field_: str, v) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float, np.floating, np.integer)) or not np.isfinite(v):
        raise InputError(field_, f"must be a number, got {_show(v)}")
    return float(v)


def _pos(field_: str, v) -> float:
    v = _num(field_, v)
    if v <= 0:
        raise InputError(field_, f"must be > 0, got {_show(v)}")
    return v


def _sign(field_: str, v, words=("+1", "-1")) -> None:
    if v not in (1, -1):
        raise InputError(field_, f"must be +1 or -1 ({words[0]} or {words[1]}), got {_show(v)}")


@dataclass(frozen=True)
class Pair:
    """A lower pair of a machine's topology.

    Attributes
    ----------
    name : str
        The seed's name of the pair (``"O2"``, ``"A_slot"``...).
    kind : {"revolute", "prismatic"}
    first : str
        The link the pair's reaction acts on (a prismatic pair: the link that slides).
    second : str or None
        The other link (a prismatic pair: the one that carries the guide); None for ground.
    """

    name: str
    kind: str
    first: str
    second: str | None = None


@dataclass(frozen=True, eq=False)
class LinkStates:
    """The moving links' motion at crank angles, for the forces (machine length unit, frame of the machine).

    Attributes
    ----------
    cg : dict of str to Point
        The centre of mass of each moving link.
    angle : dict of str to Angle
        The angle of each moving link (a sliding block turns with its guide; a slider: zero).
    point : dict of str to ndarray (complex)
        Each pair's point: the revolute's centre, the prismatic guide's reference point.
    axis : dict of str to ndarray (complex)
        Each prismatic pair's guide direction (unit, fixed in the pair's second link).
    """

    cg: dict
    angle: dict
    point: dict
    axis: dict


def _still(phi: np.ndarray) -> Angle:
    """The angle of a link that does not turn (a slider), zero at every crank angle."""
    z = np.zeros_like(phi)
    return Angle(z, z.copy(), z.copy())


class _Base:
    """Shared plumbing: crank speed, error context, checks, the output protocol, the topology.

    Each machine declares its own topology for the forces: its moving links
    (``links``, the seeds' numbering 1..n), its lower pairs (``pairs``) and
    :meth:`link_states`; a link that slides on a guide (the first link of a
    prismatic pair, :meth:`guided`) has its centre of mass at its pin.
    """

    #: The moving links, in the seed's order (link 1 is the crank).
    links: tuple[str, ...] = ()
    #: The lower pairs.
    pairs: tuple[Pair, ...] = ()

    crank_sense: int
    rpm: float | None
    kind: str
    #: Name of the working member's :class:`Slide` among the kinematics' fields.
    _output: str

    @classmethod
    def guided(cls) -> tuple[str, ...]:
        """Links that slide on a guide (the first link of a prismatic pair): the bodies a load can act on.

        Their centre of mass is their pin: it moves with the pin, so a ``cg`` does not apply to them.
        """
        return tuple(dict.fromkeys(p.first for p in cls.pairs if p.kind == "prismatic"))

    @classmethod
    def pair_kind(cls, name: str) -> str:
        """``"revolute"`` or ``"prismatic"``: the kind of the pair ``name``."""
        return next(p.kind for p in cls.pairs if p.name == name)

    def link_states(self, phi: np.ndarray, omega: float, cg) -> LinkStates:  # pragma: no cover - every machine has its own
        """Motion of the moving links' centres of mass and of the pairs at crank angles ``phi`` (radians).

        ``omega``: the crank's speed, rad/s (signed). ``cg(name, default)``: the
        distance of a turning link's centre of mass from its first joint along
        the link (machine length unit), ``default`` when the forces give none.
        """
        raise NotImplementedError

    def _check_common(self) -> None:
        _sign("linkage.crank_rotation", self.crank_sense, ("ccw", "cw"))
        if self.rpm is not None:
            _pos("linkage.rpm", self.rpm)

    @property
    def omega(self) -> float:
        """Crank angular velocity, rad/s, signed; ``crank_sense`` when no rpm is set."""
        if self.rpm is None:
            return float(self.crank_sense)
        return float(self.crank_sense * rpm_to_omega(self.rpm))

    def _w(self, omega: float | None) -> float:
        return self.omega if omega is None else float(omega)

    def _assembled(self, fn, phi):
        """Run ``fn(phi)``; re-raise an :class:`AssemblyError` with the crank angles where it fails."""
        try:
            return fn(phi)
        except AssemblyError as e:
            periodic = phi is _CHECK_GRID
            where = describe_angles(phi, e.mask, periodic=periodic) if e.mask is not None else "some positions"
            raise AssemblyError(e.field, f"{e.message}; fails at crank angles {where}", e.mask) from None

    def _check_assembly(self) -> None:
        self._assembled(lambda p: self.kinematics(p, omega=1.0), _CHECK_GRID)

    def output(self, phi, omega: float = 1.0) -> Slide:
        """The working member's coordinate along its path and its derivatives (see each machine's frame)."""
        return getattr(self.kinematics(phi, omega=omega), self._output)

    def transmission(self, phi) -> np.ndarray:
        """Transmission angle at crank angles ``phi``, radians (the kinematics' ``transmission``)."""
        return self.kinematics(phi, omega=1.0).transmission

    def _lengths(self, **dims) -> dict:
        """``lengths()``: the type, the machine's ``dims`` under the seed's names, its crank's sense and speed."""
        return {
            "type": self.kind,
            **dims,
            "crank_rotation": rotation_word(self.crank_sense),
            "rpm": self.rpm,
        }


def _verify_course(machine, *, stroke: float, time_ratio: float | None = None, allowed: str = "") -> None:
    """Check a synthesized linkage against its course data: its own stroke and time ratio to 1e-9 (relative).

    Raises
    ------
    InputError
        On ``linkage.time_ratio`` (or ``linkage.stroke``) when the linkage's
        motion does not have the asked stroke or time ratio; ``allowed`` (the
        allowed range) is appended to the message.
    """
    tail = f"; {allowed}" if allowed else ""
    field_ = "linkage.stroke" if time_ratio is None else "linkage.time_ratio"
    try:
        rep = analyse(machine, working="slow")
    except InfeasibleError as e:
        if isinstance(e, AssemblyError):
            raise
        raise InputError(field_, f"the synthesized linkage does not move as asked ({str(e).split(': ', 1)[-1]}){tail}") from None
    if time_ratio is not None and not abs(rep.time_ratio - time_ratio) <= 1e-9 * time_ratio:
        raise InputError(
            "linkage.time_ratio",
            f"the synthesized linkage has K = {rep.time_ratio:.10g} and stroke {rep.stroke:.10g}, not the asked "
            f"K = {time_ratio:.10g} and stroke {stroke:.10g}{tail}",
        )
    if not abs(rep.stroke - stroke) <= 1e-9 * stroke:
        raise InputError(
            field_,
            f"the synthesized linkage has a stroke of {rep.stroke:.10g}, not the asked {stroke:.10g}{tail}",
        )


class _SwingingLever(_Base):
    """A crank driving a slotted bar or lever that swings about a pivot at ``(-centre_distance, 0)``."""

    crank: float
    centre_distance: float

    @property
    def half_swing(self) -> float:
        """Half the bar's (lever's) swing, theta/2 = asin(l_crank / L), radians."""
        return float(np.arcsin(self.crank / self.centre_distance))

    def dead_position_hints(self) -> np.ndarray:
        """Frame crank angles of the bar's extreme positions (the crank perpendicular to the bar), radians.

        ``cos phi = -l_crank / L``: ``pi/2 + theta/2`` and ``3 pi/2 - theta/2``;
        :func:`cams.machine.linkage.analysis.dead_positions` brackets them exactly.
        """
        h = self.half_swing
        return np.array([np.pi / 2 + h, 1.5 * np.pi - h])


def _swing_bar_checks(crank_: float, L: float, bar: float, side: int, name: str, field_: str) -> None:
    if crank_ >= L:
        raise InputError(
            "linkage.crank",
            f"l = {crank_:.6g} must be shorter than the centre distance {L:.6g} for a swinging {name} "
            "(a longer crank makes the bar rotate fully)",
        )
    if side == 1 and (L - crank_) <= bar <= (L + crank_):
        raise InputError(
            field_,
            f"with the pin on the crank's side of the pivot, {bar:.6g} lies inside the block's travel "
            f"[{L - crank_:.6g}, {L + crank_:.6g}] along the {name}; use the opposite side or a length "
            f"< {L - crank_:.6g} or > {L + crank_:.6g}",
        )


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
class SlottingMachine(_SwingingLever):
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
        for f, v in (("crank", self.crank), ("centre_distance", self.centre_distance), ("bar", self.bar), ("rod", self.rod)):
            _pos(f"linkage.{f}", v)
        _num("linkage.guide_x", self.guide_x)
        _sign("linkage.bar_side", self.bar_side, ("same", "opposite"))
        _sign("linkage.tool_side", self.tool_side, ("above", "below"))
        self._check_common()
        _swing_bar_checks(self.crank, self.centre_distance, self.bar, self.bar_side, "guide bar", "linkage.bar")
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
    ) -> "SlottingMachine":
        """Synthesis from the course data (seed 003, table 1-1): K, H, L_O2O3, l_BC/l_O3B.

        The guide y-y goes through the middle of the sagitta of B's arc (the
        seed's "most favourable" position for BC driving the tool).

        Examples
        --------
        >>> m = SlottingMachine.from_course(2.0, 100.0, 150.0, 1.0)
        >>> round(m.crank, 9), round(m.bar, 9), round(m.rod, 9)
        (75.0, 100.0, 100.0)
        """
        _sign("linkage.bar_side", bar_side, ("same", "opposite"))
        syn = slotted_lever_synthesis(time_ratio, stroke, centre_distance, rod_ratio)
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
        _verify_course(m, stroke=syn.stroke, time_ratio=syn.time_ratio,
                       allowed=f"a slotting linkage with rod_ratio = {syn.rod_ratio:.6g} allows 1 < K < {_below(kmax)}")
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
        """The links' motion for the forces (:meth:`_Base.link_states`): the tool slides on y-y."""
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
        angles = {"crank": k.crank, "block": k.bar, "bar": k.bar, "rod": k.rod, "tool": _still(phi)}
        points = {"O2": O2.pos, "A": k.A.pos, "A_slot": k.A.pos, "O3": O3.pos, "B": k.B.pos, "C": k.C.pos,
                  "C_guide": k.C.pos}
        axes = {"A_slot": k.bar.unit, "C_guide": np.full_like(phi, 1j, dtype=complex)}
        return LinkStates(cgs, angles, points, axes)


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
class CrankSlider(_Base):
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
        _pos("linkage.crank", self.crank)
        _pos("linkage.rod", self.rod)
        _num("linkage.offset", self.offset)
        _sign("linkage.slider_side", self.slider_side, ("right", "left"))
        if self.rod_cg is not None:
            _num("linkage.rod_cg", self.rod_cg)
        self._check_common()
        need = self.crank + abs(self.offset)
        if not self.rod > need:
            raise AssemblyError(
                "linkage.rod",
                f"a rod of {self.rod:.6g} cannot follow the crank all the way round; it needs l_AB > l_OA + |e| = {need:.6g}",
            )

    @classmethod
    def from_stroke(cls, stroke: float, rod: float, *, offset: float = 0.0, **kw) -> "CrankSlider":
        """Synthesis from the stroke H and the rod (seed 002, formula 1.1: l_OA = H/2 when central).

        Examples
        --------
        >>> CrankSlider.from_stroke(0.35, 1.4).crank
        0.175
        """
        m = cls(crank=crank_slider_crank(stroke, rod, offset), rod=rod, offset=offset, **kw)
        _verify_course(m, stroke=float(stroke), allowed="a shorter stroke, a longer rod or a smaller offset")
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
            B, rod, sl = rrp(A, self.rod, ground(1j * self.offset), Angle(0.0, 0.0, 0.0), branch=self.slider_side, field="linkage.rod")
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
        """The links' motion for the forces (:meth:`_Base.link_states`): the slider slides along x."""
        k = self.kinematics(phi, omega=omega)
        zero = np.zeros_like(phi)
        O = Point(zero + 0j, zero + 0j, zero + 0j)
        rod_cg = self.rod_cg if self.rod_cg is not None else self.rod / 2
        cgs = {"crank": on_link(O, k.crank, cg("crank", 0.0)), "rod": on_link(k.A, k.rod, cg("rod", rod_cg)), "slider": k.B}
        angles = {"crank": k.crank, "rod": k.rod, "slider": _still(phi)}
        points = {"O": O.pos, "A": k.A.pos, "B": k.B.pos, "B_guide": k.B.pos}
        return LinkStates(cgs, angles, points, {"B_guide": np.ones_like(phi, dtype=complex)})


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
class OpposedTwin(_Base):
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
        _pos("linkage.crank", self.crank)
        _pos("linkage.rod", self.rod)
        _num("linkage.rod_cg", self.rod_cg)
        _num("linkage.phase", self.phase)
        self._check_common()
        if not self.rod > self.crank:
            raise AssemblyError("linkage.rod", f"the rods must be longer than the crank ({self.crank:.6g}), got {self.rod:.6g}")

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
        """The links' motion for the forces (:meth:`_Base.link_states`): both pistons slide along x."""
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
        angles = {"crank": crank_, "rod2": k.rod2, "piston3": _still(phi), "rod4": k.rod4, "piston5": _still(phi)}
        points = {"O": O.pos, "A": k.A.pos, "B": k.B.pos, "B_guide": k.B.pos, "C": k.C.pos, "D": k.D.pos, "D_guide": k.D.pos}
        x = np.ones_like(phi, dtype=complex)
        return LinkStates(cgs, angles, points, {"B_guide": x, "D_guide": x})


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
class SlottedLeverPump(_SwingingLever):
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
            _pos(f"linkage.{f}", v)
        _num("linkage.guide_x", self.guide_x)
        _sign("linkage.lever_side", self.lever_side, ("same", "opposite"))
        self._check_common()
        _swing_bar_checks(self.crank, self.centre_distance, self.lever, self.lever_side, "slotted lever", "linkage.lever")

    @classmethod
    def from_course(
        cls, time_ratio: float, stroke: float, centre_distance: float, *, lever_side: int = -1, **kw
    ) -> "SlottedLeverPump":
        """Synthesis from K, H and O1O2 (seed 004, section 1.4): theta, l_O1A = L sin(theta/2), l_O2C = H / (2 sin(theta/2)).

        Examples
        --------
        >>> m = SlottedLeverPump.from_course(2.0, 250.0, 525.0)
        >>> round(m.crank, 9), round(m.lever, 9)
        (262.5, 250.0)
        """
        syn = slotted_lever_synthesis(time_ratio, stroke, centre_distance)
        m = cls(crank=syn.crank, centre_distance=syn.centre_distance, lever=syn.bar, lever_side=lever_side, synthesis=syn, **kw)
        _verify_course(m, stroke=syn.stroke, time_ratio=syn.time_ratio,
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
        """The links' motion for the forces (:meth:`_Base.link_states`): the piston slides along y at ``guide_x``."""
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
        angles = {"crank": k.crank, "block": k.lever, "lever": k.lever, "pin_block": _still(phi), "piston": _still(phi)}
        points = {"O1": O1.pos, "A": k.A.pos, "A_slot": k.A.pos, "O2": O2.pos, "C": k.C.pos, "C_slot": k.C.pos, "E": E.pos}
        axes = {"A_slot": k.lever.unit, "C_slot": np.ones_like(phi, dtype=complex),
                "E": np.full_like(phi, 1j, dtype=complex)}
        return LinkStates(cgs, angles, points, axes)


MACHINES = {
    SlottingMachine.kind: SlottingMachine,
    CrankSlider.kind: CrankSlider,
    OpposedTwin.kind: OpposedTwin,
    SlottedLeverPump.kind: SlottedLeverPump,
}
"""Machine classes by their ``kind`` (the machine file's ``linkage.type``)."""
