"""Kinetostatics of the seeds' linkages: reactions in every pair and the balancing moment over the cycle.

Method (seeds 000, 002, 004: "кинетостатика", d'Alembert)
---------------------------------------------------------
Every moving link is in equilibrium under its external loads, its weight,
its inertia force ``-m a_S`` at the centre of mass S and inertia moment
``-J_S epsilon``, and the reactions of the pairs it belongs to; the input
crank also carries the balancing moment ``M_b`` (уравновешивающий момент), the
moment the drive must apply for the crank to turn at its constant speed. For
a one-input linkage without redundant constraints the ``3 n`` equations
(n moving links) determine the ``2 p`` reaction components (p lower pairs)
and ``M_b``: one linear system per crank angle, solved for all angles at once
(``numpy.linalg.solve`` on a stack), instead of group by group as in the seeds'
force plans -- the unknowns are the same.

Pairs
-----
* revolute: the force ``R`` (complex ``Rx + i Ry``) on the pair's first link
  from its second, at the pair's centre;
* prismatic: the normal force ``N`` along ``n = i u`` (``u``: the guide's
  direction, fixed in the second link) at a reference point of the guide and
  a couple ``M`` (together: the normal force acting at ``M / N`` along ``u``
  from the reference point).

The second link gets the opposite force and couple. Ground is link 0.

Friction
--------
* constant loads, e.g. seal friction on a piston (seed 002's 60 N):
  :class:`ConstantFriction`;
* proportional to the reactions (seed 002's "two-stage method", seed 004's
  2.6): in a revolute pair a moment ``mu r |R|`` (journal radius ``r``)
  opposing the relative rotation, in a prismatic pair a force ``mu |N|``
  along the guide opposing the relative sliding. The first pass solves
  without them; each following pass applies the friction of the previous
  pass's reactions (``passes=2`` is the seeds' method; more passes iterate to
  the fixed point). The power lost in each pair is ``|M_f omega_rel|`` or
  ``|F_f v_rel|`` (seed 004, 2.6).

Virtual work (Zhukovsky's lever)
--------------------------------
The balancing moment also follows from the power of all loads, inertia and
friction included, without any reaction:
``M_b omega_1 = -sum(F . v + M omega)`` -- Zhukovsky's lever is the graphical
form of this sum (moments about the pole of the velocity plan turned by 90
degrees). :attr:`ForceResult.virtual_moment` computes it independently.

Reduced quantities (for :mod:`cams.machine.flywheel`)
---------------------------------------------
``J_red = sum(m |v_S|^2 + J_S omega^2) / omega_1^2`` and the reduced moment
of the external loads and weights ``Mr = -sum(F . v + M omega) / |omega_1|``
(positive resists), of friction ``Mf = (losses) / |omega_1|``.

Frames and units
----------------
The machine's frame (:mod:`cams.machine.linkage.machines`): origin at the crank centre,
angles counter-clockwise from +x; gravity acts along -y. Lengths are given in
the machine's unit and converted with ``length_unit`` (m per unit, 1e-3 for
mm); forces in N, moments in N m (counter-clockwise positive), masses in kg,
moments of inertia in kg m^2, the crank's speed from the machine's rpm.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np

from cams.machine.linkage.primitives import Angle, Point, on_link
from cams.machine.linkage.machines import CrankSlider, OpposedTwin, SlottedLeverPump, SlottingMachine
from laws.errors import show_value
from laws.errors import InputError, check_option
from laws.errors import check_number as _num
from laws.units import omega_to_rpm, rpm_to_omega

if TYPE_CHECKING:  # types only: the modules are imported where they are used
    from cams.dynamics.forces import CamForces, JumpSpeed, Spring
    from cams.machine.flywheel import FlywheelResult
    from cams.machine.linkage.analysis import Machine
    from cams.machine.timing import CamTiming

__all__ = [
    "LinkMass",
    "Friction",
    "GasPressure",
    "Resistance",
    "ConstantFriction",
    "ForceSpec",
    "Body",
    "Joint",
    "AppliedLoad",
    "Model",
    "ForceResult",
    "build_model",
    "solve_model",
    "analyse_forces",
    "ForceOptions",
    "MachineForces",
    "force_spec_from_dict",
    "machine_forces",
    "FORCES_KEYS",
    "LINKS",
    "JOINTS",
    "WINDOWS",
    "PINNED",
    "cycle_turns",
    "GUIDED",
]

TWO_PI = 2.0 * np.pi
G = 9.80665

LINKS = {
    "slotting": ("crank", "block", "bar", "rod", "tool"),
    "crank_slider": ("crank", "rod", "slider"),
    "opposed_twin": ("crank", "rod2", "piston3", "rod4", "piston5"),
    "slotted_lever_pump": ("crank", "block", "lever", "pin_block", "piston"),
}
"""Moving links of each machine kind (seed 003: 1..5; seed 002: 1..3; seed 000: 1..5; seed 004: 1..5)."""

JOINTS = {
    "slotting": ("O2", "A", "A_slot", "O3", "B", "C", "C_guide"),
    "crank_slider": ("O", "A", "B", "B_guide"),
    "opposed_twin": ("O", "A", "B", "B_guide", "C", "D", "D_guide"),
    "slotted_lever_pump": ("O1", "A", "A_slot", "O2", "C", "C_slot", "E"),
}
"""Pairs of each machine kind; a name ending in ``_slot`` or ``_guide`` (and the pump's E) is prismatic."""

WINDOWS = ("cut", "working", "always")

PINNED = ("block", "pin_block", "tool", "slider", "piston", "piston3", "piston5")
"""Links whose centre of mass is their pin: they slide (and a block turns with its guide), so ``cg`` does not apply."""

GUIDED = {
    "slotting": ("block", "tool"),
    "crank_slider": ("slider",),
    "opposed_twin": ("piston3", "piston5"),
    "slotted_lever_pump": ("block", "pin_block", "piston"),
}
"""Links of each machine kind that slide on a guide (the first link of a prismatic pair): the bodies a load can act on."""


# --------------------------------------------------------------------------- inputs
@dataclass(frozen=True)
class LinkMass:
    """Mass properties of one link.

    Parameters
    ----------
    mass : float
        kg, >= 0.
    inertia : float
        Moment of inertia about the centre of mass, kg m^2, >= 0.
    cg : float or None
        Centre of mass: distance from the link's first joint along the link,
        machine length unit (crank: from its centre; bar/lever: from its pivot
        toward B/C; rod: from its first pin). ``None``: the centre of rotation
        for the crank, the middle for bars, levers and rods (or the machine's
        ``rod_cg``). Blocks, sliders and pistons (:data:`PINNED`) have their
        centre of mass at their pin and refuse a ``cg`` (:func:`build_model`).
    """

    mass: float = 0.0
    inertia: float = 0.0
    cg: float | None = None

    def __post_init__(self):
        _num("forces.links.mass", self.mass, lo=0.0)
        _num("forces.links.inertia", self.inertia, lo=0.0)
        _num("forces.links.cg", self.cg, allow_none=True)


@dataclass(frozen=True)
class Friction:
    """Friction in one pair, proportional to its reaction.

    Parameters
    ----------
    coefficient : float
        mu >= 0 (seed 004 takes 1.3 f for a revolute pair with clearance).
    radius : float
        Journal radius of a revolute pair, machine length unit (not used by a
        prismatic pair; a machine file refuses it there).
    """

    coefficient: float
    radius: float = 0.0

    def __post_init__(self):
        _num("forces.friction.coefficient", self.coefficient, lo=0.0)
        _num("forces.friction.radius", self.radius, lo=0.0)


def _check_table(field_: str, angles, values, period: float) -> tuple[np.ndarray, np.ndarray]:
    try:
        a = np.asarray(angles, dtype=float)
        v = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise InputError(field_, "angles and values must be numbers") from None
    if a.ndim != 1 or a.shape != v.shape or a.size < 2:
        raise InputError(field_, f"needs matching lists of >= 2 angles and values, got {a.size} and {v.size}")
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(v))):
        raise InputError(field_, "angles and values must be finite")
    if np.any(np.diff(a) <= 0):
        raise InputError(field_, "angles must increase strictly")
    if abs(a[0]) > 1e-9 or abs(a[-1] - period) > 1e-9:
        raise InputError(
            field_,
            f"the table covers {a[0]:g}..{a[-1]:g} deg; it must cover the whole cycle, from 0 to {period:g} deg",
        )
    if abs(v[0] - v[-1]) > 1e-9 * max(1.0, float(np.max(np.abs(v)))):
        raise InputError(field_, f"the values at 0 and {period:g} deg differ ({v[0]:g} and {v[-1]:g}); the cycle must close")
    return a, v


@dataclass(frozen=True)
class GasPressure:
    """Gas pressure on a piston from an indicator diagram given over the crank angle (seed 000).

    The force ``p A`` (``A = pi d^2 / 4``) pushes the piston toward the
    crank centre along its axis.

    Parameters
    ----------
    body : str
        The piston (``"slider"``, ``"piston3"``, ``"piston5"``).
    angles : sequence of float
        Crank rotation (degrees, in the crank's sense) from the frame angle
        ``start``, from 0 to ``period`` inclusive. The table's angle 0 is the
        first time the crank passes ``start`` at or after the first crank
        angle analysed (a machine's position 1); with ``period`` 360 that is
        every time it passes ``start``.
    pressure : sequence of float
        Gauge pressure at those angles, Pa (negative: below the outside).
    bore : float
        Piston diameter d, machine length unit.
    start : float
        Frame crank angle (degrees) where the table's angle 0 is.
    period : float
        360 (one turn per cycle) or 720 (a four-stroke cycle: the model's
        default crank angles then cover two turns; give ``cycle_deg=720`` to
        the flywheel).
    """

    body: str
    angles: tuple
    pressure: tuple
    bore: float
    start: float = 0.0
    period: float = 360.0

    def __post_init__(self):
        _num("forces.loads.bore", self.bore, lo=0.0, strict=True)
        _num("forces.loads.start", self.start)
        if self.period not in (360.0, 720.0, 360, 720):
            raise InputError("forces.loads.period", f"must be 360 or 720 degrees, got {show_value(self.period)}")
        _check_table("forces.loads.angles", self.angles, self.pressure, float(self.period))


@dataclass(frozen=True)
class Resistance:
    """A constant force opposing a slider's motion inside a window of the cycle (seeds 003, 004).

    Parameters
    ----------
    body : str
        The working slider (the tool, the piston).
    force : float
        Magnitude, N, >= 0.
    window : {"cut", "working", "always"}
        "cut": while the tool is in the work (the working stroke less
        ``approach`` and ``overrun``, as :class:`cams.machine.timing.CuttingZone`);
        "working": the whole working stroke; "always": the whole cycle.
    approach, overrun : float
        Fractions of the stroke before and after the cut, in [0, 1) with a sum
        < 1; window "cut" only (other windows refuse non-zero values).
    working : {"slow", "fast", "forward", "backward"}
        Which stroke works (:func:`cams.machine.linkage.analyse`); not used by window
        "always".

    The windows "cut" and "working" follow the machine's working member
    (its ``output``: the tool, the slider, piston 3, the pump's piston).
    """

    body: str
    force: float
    window: str = "cut"
    approach: float = 0.0
    overrun: float = 0.0
    working: str = "slow"

    def __post_init__(self):
        from cams.machine.linkage.analysis import WORKING

        _num("forces.loads.force", self.force, lo=0.0)
        check_option("forces.loads.window", self.window, WINDOWS)
        for name in ("approach", "overrun"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)) or not np.isfinite(v) \
                    or not 0 <= v < 1:
                raise InputError(f"forces.loads.{name}", f"must be a fraction of the stroke in [0, 1), got {show_value(v)}")
            if self.window != "cut" and v != 0:
                raise InputError(f"forces.loads.{name}", f"applies to window = 'cut' only (the part of the working stroke "
                                 f"in the work); window = {self.window!r} does not use it")
        if self.approach + self.overrun >= 1:
            raise InputError("forces.loads.overrun", f"approach + overrun must be < 1 (a part of the stroke is cut), "
                             f"got {self.approach + self.overrun:g}")
        check_option("forces.loads.working", self.working, WORKING)


@dataclass(frozen=True)
class ConstantFriction:
    """A friction force of constant magnitude opposing a slider's motion (seed 002: seals, 60 N)."""

    body: str
    force: float

    def __post_init__(self):
        _num("forces.loads.force", self.force, lo=0.0)


Load = GasPressure | Resistance | ConstantFriction


@dataclass(frozen=True)
class ForceSpec:
    """Mass properties, loads and friction of a machine.

    Parameters
    ----------
    links : dict of str to LinkMass
        By link name (:data:`LINKS`); missing links are massless.
    loads : tuple of loads
        :class:`GasPressure`, :class:`Resistance`, :class:`ConstantFriction`.
    friction : dict of str to Friction
        By pair name (:data:`JOINTS`); missing pairs have none.
    gravity : float
        m/s^2 along -y (0: weights neglected).
    length_unit : float
        Metres per machine length unit.
    """

    links: dict = field(default_factory=dict)
    loads: tuple = ()
    friction: dict = field(default_factory=dict)
    gravity: float = G
    length_unit: float = 1e-3

    def __post_init__(self):
        _num("forces.gravity", self.gravity)
        _num("forces.length_unit", self.length_unit, lo=0.0, strict=True)
        for k, v in self.links.items():
            if not isinstance(v, LinkMass):
                raise InputError(f"forces.links.{k}", f"must be a LinkMass, got {type(v).__name__}")
        for k, v in self.friction.items():
            if not isinstance(v, Friction):
                raise InputError(f"forces.friction.{k}", f"must be a Friction, got {type(v).__name__}")
        for i, ld in enumerate(self.loads):
            if not isinstance(ld, (GasPressure, Resistance, ConstantFriction)):
                raise InputError(f"forces.loads[{i}]", f"must be a load, got {type(ld).__name__}")


# --------------------------------------------------------------------------- model
@dataclass(frozen=True, eq=False)
class Body:
    """A moving link: mass properties and the motion of its centre of mass (SI)."""

    name: str
    mass: float
    inertia: float
    cg: Point
    link: Angle


@dataclass(frozen=True, eq=False)
class Joint:
    """A lower pair between body ``a`` and body ``b`` (index, -1 for ground).

    ``point``: the revolute's centre or the prismatic guide's reference point
    (m); ``axis``: the guide's unit direction (prismatic), fixed in ``b``.
    """

    name: str
    kind: str
    a: int
    b: int
    point: np.ndarray
    axis: np.ndarray | None = None
    friction: Friction | None = None


@dataclass(frozen=True, eq=False)
class AppliedLoad:
    """A known load on a body: force (complex, N) at a point (complex, m) and a moment (N m)."""

    name: str
    body: int
    force: np.ndarray
    point: np.ndarray
    moment: np.ndarray
    kind: str = "external"  # "external" or "friction"


@dataclass(frozen=True, eq=False)
class Model:
    """Bodies, joints and loads of a linkage at crank angles ``phi`` (SI).

    ``cycle``: the crank rotation of one cycle of the loads, radians (4 pi
    with a gas table of period 720, else 2 pi). ``origin``: the frame crank
    angle the cycle is counted from (a gas table's angle 0 is the first pass
    of its ``start`` at or after it), radians.
    """

    kind: str
    phi: np.ndarray
    omega: float
    bodies: tuple
    joints: tuple
    loads: tuple
    driver: int
    gravity: float
    output: str
    sense: int
    machine: Machine | None = None
    cycle: float = TWO_PI
    origin: float = 0.0

    def index(self, name: str) -> int:
        """Index of a body by name."""
        for i, b in enumerate(self.bodies):
            if b.name == name:
                return i
        raise InputError("forces.loads.body", f"{name!r} is not a link of a {self.kind} linkage, must be one of "
                         + ", ".join(repr(b.name) for b in self.bodies))

    def velocity(self, k: int, P: np.ndarray) -> np.ndarray:
        """Velocity (m/s, complex) of the point P fixed to body ``k`` (0 for ground, k = -1)."""
        if k < 0:
            return np.zeros_like(P)
        b = self.bodies[k]
        return b.cg.vel + 1j * b.link.omega * (P - b.cg.pos)


def _scale(p: Point, u: float) -> Point:
    return Point(p.pos * u, p.vel * u, p.acc * u)


def _fixed(phi: np.ndarray) -> Angle:
    z = np.zeros_like(phi)
    return Angle(z, z.copy(), z.copy())


def _mass(spec: ForceSpec, name: str) -> LinkMass:
    return spec.links.get(name, LinkMass())


def _cg(spec: ForceSpec, name: str, default: float) -> float:
    c = _mass(spec, name).cg
    return default if c is None else c


def _bodies_joints(machine, spec: ForceSpec, phi: np.ndarray, omega: float):
    """Kinematic states (machine units) of every link's centre of mass and the pairs."""
    k = machine.kinematics(phi, omega=omega)
    zero = np.zeros_like(phi)
    if isinstance(machine, SlottingMachine):
        O2, O3 = Point(zero + 0j, zero + 0j, zero + 0j), Point(zero - machine.centre_distance + 0j, zero + 0j, zero + 0j)
        cgs = {
            "crank": on_link(O2, k.crank, _cg(spec, "crank", 0.0)),
            "block": k.A,
            "bar": on_link(O3, k.bar, machine.bar_side * _cg(spec, "bar", machine.bar / 2)),
            "rod": on_link(k.B, k.rod, _cg(spec, "rod", machine.rod / 2)),
            "tool": k.C,
        }
        links = {"crank": k.crank, "block": k.bar, "bar": k.bar, "rod": k.rod, "tool": _fixed(phi)}
        up = np.full_like(phi, 1j, dtype=complex)
        joints = [
            ("O2", "revolute", "crank", None, O2.pos, None),
            ("A", "revolute", "block", "crank", k.A.pos, None),
            ("A_slot", "prismatic", "block", "bar", k.A.pos, k.bar.unit),
            ("O3", "revolute", "bar", None, O3.pos, None),
            ("B", "revolute", "rod", "bar", k.B.pos, None),
            ("C", "revolute", "tool", "rod", k.C.pos, None),
            ("C_guide", "prismatic", "tool", None, k.C.pos, up),
        ]
        return cgs, links, joints, "tool", up
    if isinstance(machine, CrankSlider):
        O = Point(zero + 0j, zero + 0j, zero + 0j)
        rod_cg = machine.rod_cg if machine.rod_cg is not None else machine.rod / 2
        cgs = {
            "crank": on_link(O, k.crank, _cg(spec, "crank", 0.0)),
            "rod": on_link(k.A, k.rod, _cg(spec, "rod", rod_cg)),
            "slider": k.B,
        }
        links = {"crank": k.crank, "rod": k.rod, "slider": _fixed(phi)}
        x = np.ones_like(phi, dtype=complex)
        joints = [
            ("O", "revolute", "crank", None, O.pos, None),
            ("A", "revolute", "rod", "crank", k.A.pos, None),
            ("B", "revolute", "slider", "rod", k.B.pos, None),
            ("B_guide", "prismatic", "slider", None, k.B.pos, x),
        ]
        return cgs, links, joints, "slider", x
    if isinstance(machine, OpposedTwin):
        O = Point(zero + 0j, zero + 0j, zero + 0j)
        crank = Angle(k.phi + zero, np.full_like(phi, omega), zero.copy())
        cgs = {
            "crank": on_link(O, crank, _cg(spec, "crank", 0.0)),
            "rod2": on_link(k.A, k.rod2, _cg(spec, "rod2", machine.rod_cg)),
            "piston3": k.B,
            "rod4": on_link(k.C, k.rod4, _cg(spec, "rod4", machine.rod_cg)),
            "piston5": k.D,
        }
        links = {"crank": crank, "rod2": k.rod2, "piston3": _fixed(phi), "rod4": k.rod4, "piston5": _fixed(phi)}
        x = np.ones_like(phi, dtype=complex)
        joints = [
            ("O", "revolute", "crank", None, O.pos, None),
            ("A", "revolute", "rod2", "crank", k.A.pos, None),
            ("B", "revolute", "piston3", "rod2", k.B.pos, None),
            ("B_guide", "prismatic", "piston3", None, k.B.pos, x),
            ("C", "revolute", "rod4", "crank", k.C.pos, None),
            ("D", "revolute", "piston5", "rod4", k.D.pos, None),
            ("D_guide", "prismatic", "piston5", None, k.D.pos, x),
        ]
        return cgs, links, joints, "piston3", x
    if isinstance(machine, SlottedLeverPump):
        O1, O2 = Point(zero + 0j, zero + 0j, zero + 0j), Point(zero - machine.centre_distance + 0j, zero + 0j, zero + 0j)
        up = np.full_like(phi, 1j, dtype=complex)
        x = np.ones_like(phi, dtype=complex)
        E = Point(machine.guide_x + 1j * k.piston.s, 1j * k.piston.ds, 1j * k.piston.d2s)
        cgs = {
            "crank": on_link(O1, k.crank, _cg(spec, "crank", 0.0)),
            "block": k.A,
            "lever": on_link(O2, k.lever, machine.lever_side * _cg(spec, "lever", machine.lever / 2)),
            "pin_block": k.C,
            "piston": E,
        }
        links = {"crank": k.crank, "block": k.lever, "lever": k.lever, "pin_block": _fixed(phi), "piston": _fixed(phi)}
        joints = [
            ("O1", "revolute", "crank", None, O1.pos, None),
            ("A", "revolute", "block", "crank", k.A.pos, None),
            ("A_slot", "prismatic", "block", "lever", k.A.pos, k.lever.unit),
            ("O2", "revolute", "lever", None, O2.pos, None),
            ("C", "revolute", "pin_block", "lever", k.C.pos, None),
            ("C_slot", "prismatic", "pin_block", "piston", k.C.pos, x),
            ("E", "prismatic", "piston", None, E.pos, up),
        ]
        return cgs, links, joints, "piston", up
    raise InputError("linkage.type", f"forces are not available for {type(machine).__name__}")


def _message(e: InputError) -> str:
    """The message of an :class:`InputError` without its field."""
    text = str(e)
    return text[len(e.field) + 2:] if e.field and text.startswith(e.field + ": ") else text


def _guide(model: Model, name: str) -> np.ndarray:
    """The guide direction of a slider body (from its prismatic pair with ground)."""
    k = model.index(name)
    for j in model.joints:
        if j.kind == "prismatic" and j.a == k and j.b < 0:
            return j.axis
    for j in model.joints:
        if j.kind == "prismatic" and j.a == k:
            return j.axis
    raise InputError("forces.loads.body", f"{name!r} does not slide on a guide; loads along a guide need a slider or piston")


def _load_window(model: Model, ld: Resistance) -> np.ndarray:
    if ld.window == "always":
        return np.ones_like(model.phi, dtype=bool)
    from cams.machine.timing import CuttingZone, windows

    m = model.machine
    zone = CuttingZone(approach=ld.approach, overrun=ld.overrun, working=ld.working) if ld.window == "cut" else CuttingZone(working=ld.working)
    win = windows(m, zone)
    c = win.cycle_angle(model.phi)
    a, b = win.cut_start, win.cut_end
    return ((c >= a - 1e-12) & (c <= b + 1e-12)) | ((c + TWO_PI >= a - 1e-12) & (c + TWO_PI <= b + 1e-12))


def _external_loads(model: Model, spec: ForceSpec) -> list[AppliedLoad]:
    out = []
    u = spec.length_unit
    for i, ld in enumerate(spec.loads):
        try:
            k = model.index(ld.body)
            axis = _guide(model, ld.body)
        except InputError as e:
            raise InputError(f"forces.loads[{i}].body", _message(e)) from None
        b = model.bodies[k]
        if isinstance(ld, GasPressure):
            a, p = _check_table(f"forces.loads[{i}].angles", ld.angles, ld.pressure, float(ld.period))
            # the table's angle 0: the first time the crank passes `start` at or after the model's origin
            # (a property of the crank position, not of the angles asked for)
            first = np.mod(model.sense * (np.radians(ld.start) - model.origin), TWO_PI)
            rot = np.degrees(model.sense * (model.phi - model.origin) - first)
            pp = np.interp(np.mod(rot, ld.period), a, p)
            area = np.pi * (ld.bore * u) ** 2 / 4
            toward = -np.sign(np.real(np.conj(axis) * b.cg.pos))  # along the axis toward the crank centre
            out.append(AppliedLoad(f"gas on {ld.body}", k, pp * area * toward * axis, b.cg.pos, np.zeros_like(model.phi)))
        else:
            v = np.real(np.conj(axis) * b.cg.vel)
            on = np.ones_like(model.phi, dtype=bool) if isinstance(ld, ConstantFriction) else _load_window(model, ld)
            F = np.where(on, -np.sign(v) * ld.force, 0.0) * axis
            what = "resistance" if isinstance(ld, Resistance) else "constant friction"
            out.append(AppliedLoad(f"{what} on {ld.body}", k, F, b.cg.pos, np.zeros_like(model.phi)))
    return out


def cycle_turns(spec: ForceSpec) -> int:
    """Crank turns in one cycle of the loads: 2 with a gas table of period 720, else 1."""
    return 2 if any(isinstance(ld, GasPressure) and float(ld.period) == 720.0 for ld in spec.loads) else 1


def _pinned_cg(name: str, kind: str) -> str:
    turning = ", ".join(repr(n) for n in LINKS.get(kind, ()) if n not in PINNED)
    return (f"does not apply to the {name}: a sliding body's centre of mass is taken at its pin and moves with it; "
            f"cg applies to the links that turn about a joint ({turning})")


def build_model(machine, spec: ForceSpec, *, phi=None, samples: int = 360, rpm: float | None = None,
                origin: float = 0.0) -> Model:
    """The rigid-body model of a machine of :mod:`cams.machine.linkage.machines` at crank angles ``phi``.

    Parameters
    ----------
    machine : SlottingMachine, CrankSlider, OpposedTwin or SlottedLeverPump
    spec : ForceSpec
    phi : array_like, optional
        Frame crank angles, radians; default ``samples`` angles a turn over one
        cycle of the loads (two turns with a gas table of period 720).
    samples : int
        Crank angles per turn (ignored with ``phi``).
    rpm : float, optional
        Crank speed, rev/min; default the machine's.
    origin : float
        Frame crank angle (radians) the load cycle is counted from: a gas
        table's angle 0 is the first pass of its ``start`` at or after it
        (matters for a table of period 720 only). ``cams machine`` passes
        position 1's angle.

    Returns
    -------
    Model

    Raises
    ------
    InputError
        No crank speed, unknown link or pair names, a ``cg`` of a link whose
        centre of mass is its pin (:data:`PINNED`), a load on a link that does
        not slide, a load table that does not cover the cycle.
    """
    n = machine.rpm if rpm is None else rpm
    if n is None:
        raise InputError("linkage.rpm", "the forces need the crank's speed; give linkage.rpm")
    n = _num("linkage.rpm", n, lo=0.0, strict=True)
    omega = machine.crank_sense * rpm_to_omega(n)
    turns = cycle_turns(spec)
    if phi is None:
        if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 4:
            raise InputError("forces.samples", f"must be an integer >= 4, got {show_value(samples)}")
        phi = np.linspace(0.0, TWO_PI * turns, int(samples) * turns, endpoint=False)
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    kind = machine.kind
    names = LINKS[kind]
    for k, lm in spec.links.items():
        if k not in names:
            raise InputError(f"forces.links.{k}", f"is not a link of a {kind} linkage, must be one of {', '.join(map(repr, names))}")
        if k in PINNED and lm.cg is not None:
            raise InputError(f"forces.links.{k}.cg", _pinned_cg(k, kind))
    for k in spec.friction:
        if k not in JOINTS[kind]:
            raise InputError(f"forces.friction.{k}", f"is not a pair of a {kind} linkage, must be one of {', '.join(map(repr, JOINTS[kind]))}")
    cgs, links, joints, output, _ = _bodies_joints(machine, spec, phi, omega)
    u = spec.length_unit
    bodies = tuple(
        Body(nm, _mass(spec, nm).mass, _mass(spec, nm).inertia, _scale(cgs[nm], u), links[nm]) for nm in names
    )
    idx = {nm: i for i, nm in enumerate(names)}
    js = []
    for nm, kind_, a, b, P, axis in joints:
        fr = spec.friction.get(nm)
        if fr is not None and kind_ == "revolute":
            fr = Friction(fr.coefficient, fr.radius * u)
        js.append(Joint(nm, kind_, idx[a], -1 if b is None else idx[b], np.asarray(P) * u,
                        None if axis is None else np.asarray(axis, dtype=complex), fr))
    model = Model(kind, phi, float(omega), bodies, tuple(js), (), 0, float(spec.gravity), output, machine.crank_sense, machine,
                  TWO_PI * turns, float(origin))
    loads = tuple(_external_loads(model, spec))
    return replace(model, loads=loads)


# --------------------------------------------------------------------------- solution
def _cross(a, b):
    return np.imag(np.conj(a) * b)


def _relative(model: Model, j: Joint) -> np.ndarray:
    """Relative angular velocity omega_a - omega_b (revolute, rad/s) or sliding velocity of a on b along the guide (m/s)."""
    wa = model.bodies[j.a].link.omega
    wb = 0.0 if j.b < 0 else model.bodies[j.b].link.omega
    if j.kind == "revolute":
        return np.broadcast_to(wa - wb, model.phi.shape).astype(float)
    dv = model.velocity(j.a, j.point) - model.velocity(j.b, j.point)
    return np.real(np.conj(j.axis) * dv)


def _friction_loads(model: Model, reactions: dict) -> list[AppliedLoad]:
    out = []
    zero = np.zeros_like(model.phi)
    for j in model.joints:
        if j.friction is None or j.friction.coefficient == 0:
            continue
        rel = _relative(model, j)
        s = np.sign(rel)
        if j.kind == "revolute":
            M = -s * j.friction.coefficient * j.friction.radius * np.abs(reactions[j.name])
            out.append(AppliedLoad(f"friction in {j.name}", j.a, zero + 0j, j.point, M, "friction"))
            if j.b >= 0:
                out.append(AppliedLoad(f"friction in {j.name}", j.b, zero + 0j, j.point, -M, "friction"))
        else:
            F = -s * j.friction.coefficient * np.abs(reactions[j.name + ":N"]) * j.axis
            out.append(AppliedLoad(f"friction in {j.name}", j.a, F, j.point, zero.copy(), "friction"))
            if j.b >= 0:
                out.append(AppliedLoad(f"friction in {j.name}", j.b, -F, j.point, zero.copy(), "friction"))
    return out


def _solve(model: Model, loads) -> tuple[dict, np.ndarray]:
    K, B, J = model.phi.size, len(model.bodies), len(model.joints)
    nu = 2 * J + 1
    if 3 * B != nu:  # pragma: no cover - the machines are statically determinate
        raise InputError("linkage", f"{B} links and {J} pairs are not statically determinate")
    A = np.zeros((K, 3 * B, nu))
    rhs = np.zeros((K, 3 * B))
    S = [b.cg.pos for b in model.bodies]
    for c, j in enumerate(model.joints):
        for k, s in ((j.a, 1.0), (j.b, -1.0)):
            if k < 0:
                continue
            r = j.point - S[k]
            if j.kind == "revolute":
                A[:, 3 * k, 2 * c] = s
                A[:, 3 * k + 1, 2 * c + 1] = s
                A[:, 3 * k + 2, 2 * c] = -s * np.imag(r)
                A[:, 3 * k + 2, 2 * c + 1] = s * np.real(r)
            else:
                n = 1j * j.axis
                A[:, 3 * k, 2 * c] = s * np.real(n)
                A[:, 3 * k + 1, 2 * c] = s * np.imag(n)
                A[:, 3 * k + 2, 2 * c] = s * _cross(r, n)
                A[:, 3 * k + 2, 2 * c + 1] = s
    A[:, 3 * model.driver + 2, -1] = 1.0
    for k, b in enumerate(model.bodies):
        F = b.mass * (-1j * model.gravity) - b.mass * b.cg.acc
        rhs[:, 3 * k] -= np.real(F)
        rhs[:, 3 * k + 1] -= np.imag(F)
        rhs[:, 3 * k + 2] -= -b.inertia * b.link.alpha
    for ld in loads:
        k = ld.body
        rhs[:, 3 * k] -= np.real(ld.force)
        rhs[:, 3 * k + 1] -= np.imag(ld.force)
        rhs[:, 3 * k + 2] -= _cross(ld.point - S[k], ld.force) + ld.moment
    x = np.linalg.solve(A, rhs[..., None])[..., 0]
    out = {}
    for c, j in enumerate(model.joints):
        if j.kind == "revolute":
            out[j.name] = x[:, 2 * c] + 1j * x[:, 2 * c + 1]
        else:
            out[j.name + ":N"] = x[:, 2 * c]
            out[j.name + ":M"] = x[:, 2 * c + 1]
            out[j.name] = x[:, 2 * c] * 1j * j.axis
    return out, x[:, -1]


@dataclass(frozen=True, eq=False)
class ForceResult:
    """Reactions, balancing moment, friction and reduced quantities over the crank angles.

    Attributes
    ----------
    model : Model
        Bodies, joints and external loads (SI).
    reactions : dict of str to ndarray (complex)
        Force on each pair's first link from its second, N (``Rx + i Ry``);
        for a prismatic pair also ``name + ":N"`` (normal force along ``i u``)
        and ``name + ":M"`` (couple, N m).
    balancing_moment : ndarray
        M_b on the crank from the drive, N m, counter-clockwise positive.
    friction_loads : tuple of AppliedLoad
        The reaction-dependent friction of the last pass.
    passes : int
        Passes made (1: no reaction-dependent friction).
    change : float
        Largest change of |M_b| in the last pass, N m (0 for one pass).
    reference : str
        What the reported angles (:attr:`rotation`: the crank's rotation in
        its own sense from the first crank angle) are called, e.g. ``"cycle
        angle from position 1"`` when the first angle is a machine's position
        1; empty: ``"crank rotation from <phi[0]> deg (frame)"``.
    """

    model: Model
    reactions: dict
    balancing_moment: np.ndarray
    friction_loads: tuple
    passes: int
    change: float
    reference: str = ""

    @property
    def phi(self) -> np.ndarray:
        """Frame crank angles, radians."""
        return self.model.phi

    @property
    def rotation(self) -> np.ndarray:
        """The crank's rotation in its own sense from the first crank angle, radians in [0, 2 pi).

        In [0, 4 pi) when the loads' cycle is two turns (a gas table of period 720).
        """
        return np.mod(self.model.sense * (self.phi - self.phi[0]), self.model.cycle)

    @property
    def angle_reference(self) -> str:
        """The name of the angle of :attr:`rotation` in reports and plots."""
        return self.reference or f"crank rotation from {np.degrees(self.phi[0]) % 360:.1f} deg (frame)"

    @property
    def omega(self) -> float:
        """Crank angular velocity, rad/s (signed)."""
        return self.model.omega

    def magnitude(self, pair: str) -> np.ndarray:
        """|R| of a pair, N."""
        return np.abs(self.reactions[pair])

    def _powers(self, loads) -> np.ndarray:
        m = self.model
        P = np.zeros_like(m.phi)
        for ld in loads:
            v = m.velocity(ld.body, ld.point)
            P += np.real(np.conj(ld.force) * v) + ld.moment * m.bodies[ld.body].link.omega
        return P

    def _inertia_gravity_power(self) -> tuple[np.ndarray, np.ndarray]:
        m = self.model
        Pi = np.zeros_like(m.phi)
        Pg = np.zeros_like(m.phi)
        for b in m.bodies:
            Pi += np.real(np.conj(-b.mass * b.cg.acc) * b.cg.vel) - b.inertia * b.link.alpha * b.link.omega
            Pg += np.real(np.conj(b.mass * (-1j * m.gravity)) * b.cg.vel)
        return Pi, Pg

    @property
    def virtual_moment(self) -> np.ndarray:
        """M_b from the power of every load (Zhukovsky's lever), without the reactions, N m."""
        Pi, Pg = self._inertia_gravity_power()
        P = self._powers(self.model.loads) + self._powers(self.friction_loads) + Pi + Pg
        return -P / self.omega

    @property
    def friction_power(self) -> dict:
        """Power lost to reaction-dependent friction in each pair, W (>= 0).

        The power of the friction actually applied (for ``passes=2``: from the
        first pass's reactions, as in the seeds' two-stage method):
        ``|M_f omega_rel|`` in a revolute pair, ``|F_f v_rel|`` in a prismatic one.
        """
        m = self.model
        out: dict = {}
        for ld in self.friction_loads:
            v = m.velocity(ld.body, ld.point)
            P = np.real(np.conj(ld.force) * v) + ld.moment * m.bodies[ld.body].link.omega
            name = ld.name.removeprefix("friction in ")
            out[name] = out.get(name, 0.0) - P
        return out

    @property
    def reduced_inertia(self) -> np.ndarray:
        """J_red = sum(m |v_S|^2 + J omega^2) / omega_1^2, kg m^2."""
        m = self.model
        T2 = sum(b.mass * np.abs(b.cg.vel) ** 2 + b.inertia * b.link.omega**2 for b in m.bodies)
        return np.asarray(T2, dtype=float) / self.omega**2 + np.zeros_like(m.phi)

    @property
    def reduced_resisting(self) -> np.ndarray:
        """Reduced moment of the external loads and weights, N m (positive resists)."""
        _, Pg = self._inertia_gravity_power()
        return -(self._powers(self.model.loads) + Pg) / abs(self.omega)

    @property
    def reduced_friction(self) -> np.ndarray:
        """Reduced moment of the friction in the pairs (reaction-dependent), N m (>= 0)."""
        return -self._powers(self.friction_loads) / abs(self.omega)

    def residuals(self) -> np.ndarray:
        """Sum of forces (x, y) and of moments about the frame's origin on every body, shape (K, bodies, 3).

        Computed from the stored reactions and loads (not from the solver's
        matrix); zero to round-off when every link is in equilibrium.
        """
        m = self.model
        K = m.phi.size
        out = np.zeros((K, len(m.bodies), 3))

        def add(k, F, P, M):
            out[:, k, 0] += np.real(F)
            out[:, k, 1] += np.imag(F)
            out[:, k, 2] += _cross(P, F) + M

        zero = np.zeros(K)
        for k, b in enumerate(m.bodies):
            add(k, b.mass * (-1j * m.gravity) - b.mass * b.cg.acc, b.cg.pos, -b.inertia * b.link.alpha)
        for ld in (*m.loads, *self.friction_loads):
            add(ld.body, ld.force, ld.point, ld.moment)
        for j in m.joints:
            R = self.reactions[j.name]
            M = self.reactions.get(j.name + ":M", zero)
            add(j.a, R, j.point, M)
            if j.b >= 0:
                add(j.b, -R, j.point, -M)
        out[:, m.driver, 2] += self.balancing_moment
        return out

    def flywheel(self, *, delta: float, interpolation: str = "linear", friction: bool = True,
                 cycle_deg: float | None = None):
        """The flywheel for this machine (:func:`cams.machine.flywheel.flywheel`) from its reduced moments and inertia.

        The crank angles become the cycle's angles in the crank's sense from
        the first one. ``friction`` adds the pairs' friction to the resisting
        moment. ``cycle_deg``: the cycle, degrees; default the loads' own
        (:attr:`Model.cycle`: 720 with a gas table of period 720, which needs
        crank angles over two turns).
        """
        from cams.machine.flywheel import flywheel

        cycle = self.model.cycle if cycle_deg is None else np.radians(cycle_deg)
        cycle_deg = float(np.degrees(cycle))
        c = np.mod(self.model.sense * (self.phi - self.phi[0]), cycle)
        order = np.argsort(c)
        Mr = self.reduced_resisting + (self.reduced_friction if friction else 0.0)
        rpm = omega_to_rpm(abs(self.omega))
        return flywheel(c[order], Mr[order], self.reduced_inertia[order], rpm=rpm, delta=delta, interpolation=interpolation,
                        cycle_deg=cycle_deg, reference=self.angle_reference)

    def to_dict(self) -> dict:
        """JSON-ready summary: extremes of the reactions and the balancing moment, friction losses.

        The angles (``at_deg``) are :attr:`rotation` in degrees, named by ``angle_reference``.
        """
        deg = np.degrees(self.rotation)
        pairs = {}
        for j in self.model.joints:
            R = self.magnitude(j.name)
            k = int(np.argmax(R))
            pairs[j.name] = {"kind": j.kind, "max": float(R[k]), "at_deg": float(deg[k]), "mean": float(np.mean(R))}
        Mb = self.balancing_moment
        k = int(np.argmax(np.abs(Mb)))
        fp = {k_: float(np.mean(v)) for k_, v in self.friction_power.items()}
        return {
            "angle_reference": self.angle_reference,
            "rpm": omega_to_rpm(abs(self.omega)),
            "passes": self.passes,
            "balancing_moment": {"max_abs": float(abs(Mb[k])), "at_deg": float(deg[k]), "mean": float(np.mean(Mb)),
                                 "virtual_work_max_difference": float(np.max(np.abs(Mb - self.virtual_moment)))},
            "pairs": pairs,
            "friction_power_mean_W": fp,
            "friction_power_total_mean_W": float(sum(fp.values())),
            "drive_power_mean_W": float(np.mean(Mb * self.omega)),
        }

    def plot(self, path, *, title: str = "forces"):
        """Reactions and the balancing moment over the crank angle to ``path``; returns the path."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        c = np.degrees(self.rotation)
        o = np.argsort(c)
        fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(8, 6.5))
        for j in self.model.joints:
            ax1.plot(c[o], self.magnitude(j.name)[o], label=j.name)
        ax1.set_ylabel("|reaction|, N")
        ax1.legend(loc="upper right", ncol=2, fontsize="small")
        ax2.plot(c[o], self.balancing_moment[o], label="M_b (force analysis)")
        ax2.plot(c[o], self.virtual_moment[o], "--", label="M_b (Zhukovsky)")
        ax2.set_ylabel("balancing moment, N m")
        ax2.set_xlabel(f"{self.angle_reference}, deg")
        ax2.legend(loc="upper right")
        for ax in (ax1, ax2):
            ax.grid(True, alpha=0.3)
        ax1.set_title(title)
        fig.tight_layout()
        fig.savefig(path)
        plt.close(fig)
        return path

    def plot_hodographs(self, path, *, title: str = "hodographs", marks: int = 12):
        """Hodographs of the reactions (:meth:`hodograph_figure`) written to ``path``; returns the path."""
        import matplotlib.pyplot as plt

        fig = self.hodograph_figure(title=title, marks=marks)
        fig.savefig(path)
        plt.close(fig)
        return path

    def hodograph_figure(self, *, title: str = "hodographs", marks: int = 12):
        """Hodographs of the reactions: the tip of each pair's reaction vector over the cycle (a matplotlib figure).

        One panel a pair, in the order of the model's joints: ``R_x`` against
        ``R_y`` in N (frame axes), the reaction on the pair's first body from
        its second, as stored in :attr:`reactions` (the panel's first line,
        in crank-rotation order). ``marks`` positions equally spaced in crank
        rotation from the first crank angle are numbered 1, 2, ... as in the
        seeds' plans (position 1 at the first crank angle); the figure's
        subtitle names the angle (:attr:`angle_reference`).
        """
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        c = self.rotation
        o = np.argsort(c)
        joints = self.model.joints
        cols = min(4, len(joints))
        rows = -(-len(joints) // cols)
        fig, axes = plt.subplots(rows, cols, figsize=(3.2 * cols, 3.2 * rows), squeeze=False)
        cyc = self.model.cycle
        at = [int(np.argmin(np.abs(np.mod(c - cyc * k / marks + cyc / 2, cyc) - cyc / 2))) for k in range(marks)]
        for ax, j in zip(axes.ravel(), joints):
            R = self.reactions[j.name]
            ax.plot(np.real(R)[o], np.imag(R)[o], lw=1.2)
            ax.plot([0.0], [0.0], "k+", ms=8)
            for k, i in enumerate(at):
                ax.plot(np.real(R[i]), np.imag(R[i]), "o", ms=3, color="C3")
                ax.annotate(str(k + 1), (np.real(R[i]), np.imag(R[i])), fontsize=7, xytext=(3, 3), textcoords="offset points")
            ax.set_title(f"{j.name} ({j.kind})", fontsize=9)
            ax.set_aspect("equal", adjustable="datalim")
            ax.grid(True, alpha=0.3)
            ax.tick_params(labelsize=7)
            ax.set_xlabel("R_x, N", fontsize=8)
            ax.set_ylabel("R_y, N", fontsize=8)
        for ax in axes.ravel()[len(joints):]:
            ax.set_visible(False)
        fig.suptitle(f"{title}\npoints 1..{marks} every {np.degrees(cyc) / marks:g} deg of {self.angle_reference}, "
                     "point 1 at 0 deg",
                     fontsize=10)
        fig.tight_layout()
        return fig


def solve_model(model: Model, *, passes: int = 2, tol: float = 1e-9, max_passes: int = 50) -> ForceResult:
    """Reactions and the balancing moment of a model, with friction by successive passes.

    Parameters
    ----------
    model : Model
    passes : int or None
        1: no reaction-dependent friction; 2: the seeds' two-stage method
        (friction from the first pass's reactions); None: iterate until
        |M_b| changes by less than ``tol`` x its largest value.
    tol : float
    max_passes : int

    Returns
    -------
    ForceResult
    """
    if passes is not None and (isinstance(passes, bool) or not isinstance(passes, (int, np.integer)) or passes < 1):
        raise InputError("forces.passes", f"must be an integer >= 1 or None, got {show_value(passes)}")
    has_friction = any(j.friction is not None and j.friction.coefficient > 0 for j in model.joints)
    R, Mb = _solve(model, model.loads)
    fl: list = []
    n, change = 1, 0.0
    limit = 1 if not has_friction else (max_passes if passes is None else passes)
    while n < limit:
        fl = _friction_loads(model, R)
        R, Mb2 = _solve(model, (*model.loads, *fl))
        change = float(np.max(np.abs(Mb2 - Mb)))
        Mb = Mb2
        n += 1
        if passes is None and change <= tol * max(float(np.max(np.abs(Mb))), 1e-300):
            break
    return ForceResult(model, R, Mb, tuple(fl), n, change)


def analyse_forces(machine, spec: ForceSpec, *, phi=None, samples: int = 360, rpm: float | None = None, passes: int = 2,
                   origin: float = 0.0) -> ForceResult:
    """Kinetostatics of a machine over its cycle: :func:`build_model` then :func:`solve_model`.

    Examples
    --------
    A crank-slider with a 10 kg piston at 120 rpm, no friction: the balancing
    moment equals the one from Zhukovsky's lever.

    >>> from cams.machine.linkage.machines import CrankSlider
    >>> m = CrankSlider(crank=100.0, rod=400.0, rpm=120)
    >>> r = analyse_forces(m, ForceSpec(links={"slider": LinkMass(10.0)}), samples=36)
    >>> bool(np.allclose(r.balancing_moment, r.virtual_moment, atol=1e-9))
    True
    """
    return solve_model(build_model(machine, spec, phi=phi, samples=samples, rpm=rpm, origin=origin), passes=passes)


# --------------------------------------------------------------------------- machine files
FORCES_KEYS = ("gravity", "samples", "passes", "delta", "interpolation", "links", "friction", "loads")
"""Keys of a machine file's ``[forces]`` table."""
_LOAD_KEYS = {
    "resistance": {"kind", "body", "force", "window", "approach", "overrun", "working"},
    "gas": {"kind", "body", "angles", "pressure", "bore", "start", "period"},
    "constant_friction": {"kind", "body", "force"},
}


def _keys(table, allowed, field_: str) -> dict:
    if not isinstance(table, dict):
        raise InputError(field_, "must be a table")
    unknown = set(table) - set(allowed)
    if unknown:
        raise InputError(field_, f"unknown key(s) {', '.join(sorted(unknown))}; allowed: {', '.join(sorted(allowed))}")
    return table


@dataclass(frozen=True)
class ForceOptions:
    """How a machine file asks for its forces: sampling, friction passes and the flywheel.

    Attributes
    ----------
    samples : int
        Crank angles per turn.
    passes : int or None
        Friction passes (:func:`solve_model`); None iterates.
    delta : float or None
        Coefficient of speed fluctuation for the flywheel; None: no flywheel.
    interpolation : str
        For :func:`cams.machine.flywheel.flywheel`.
    """

    samples: int = 360
    passes: int | None = 2
    delta: float | None = None
    interpolation: str = "linear"


def force_spec_from_dict(table: dict, kind: str, *, units: str = "mm", cutting=None) -> tuple[ForceSpec, ForceOptions]:
    """A machine file's ``[forces]`` table.

    Schema (masses kg, moments of inertia kg m^2, forces N, pressures Pa,
    lengths in the file's unit, angles in degrees)::

        [forces]            gravity (m/s^2, default 9.80665), samples (360), passes (2 | "iterate"),
                            delta (flywheel), interpolation ("linear" | "spline")
        [forces.links.NAME] mass, inertia, cg           NAME: see cams.machine.kinetostatics.LINKS
                            (cg: links that turn only; PINNED links refuse it)
        [forces.friction]   revolute = {coefficient, radius}, prismatic = {coefficient},
                            PAIR = {coefficient, radius} (overrides; PAIR: see JOINTS;
                            radius refused for a prismatic pair)
        [[forces.loads]]    kind = "resistance": body, force, window ("cut" | "working" | "always"),
                                                 approach, overrun (window "cut" only),
                                                 working (not with "always"); default: [cutting]
                            kind = "gas": body, angles, pressure, bore, start, period
                            kind = "constant_friction": body, force
                            body: a link that slides on a guide (GUIDED)

    Every value is checked here, with the load's index in the field
    (``forces.loads[1].approach``), not only when the forces are computed.

    Parameters
    ----------
    table : dict
    kind : str
        The linkage's kind (:data:`LINKS`).
    units : str
        The file's length unit: ``"mm"`` only (:data:`cams.dynamics.forces.LENGTH_UNITS`).
    cutting : cams.machine.timing.CuttingZone or None
        Defaults of a "resistance" load's window.

    Returns
    -------
    (ForceSpec, ForceOptions)

    Examples
    --------
    >>> spec, opt = force_spec_from_dict({"links": {"tool": {"mass": 80}}, "delta": 0.05,
    ...     "loads": [{"kind": "resistance", "body": "tool", "force": 1000}]}, "slotting")
    >>> spec.links["tool"].mass, spec.loads[0].window, opt.delta
    (80.0, 'cut', 0.05)
    """
    from cams.dynamics.forces import LENGTH_UNITS

    t = _keys(table, FORCES_KEYS, "forces")
    if units not in LENGTH_UNITS:
        raise InputError("units", f"{units!r} is not supported: machine files are in mm")
    names, pairs = LINKS[kind], JOINTS[kind]
    links = {}
    for nm, lt in _keys(t.get("links", {}), names, "forces.links").items():
        lt = _keys(lt, {"mass", "inertia", "cg"}, f"forces.links.{nm}")
        if "cg" in lt and nm in PINNED:
            raise InputError(f"forces.links.{nm}.cg", _pinned_cg(nm, kind))
        vals = {k: _num(f"forces.links.{nm}.{k}", v) for k, v in lt.items()}
        for k in ("mass", "inertia"):
            if vals.get(k, 0.0) < 0:
                raise InputError(f"forces.links.{nm}.{k}", f"cannot be negative, got {show_value(vals[k])}")
        links[nm] = LinkMass(vals.get("mass", 0.0), vals.get("inertia", 0.0), vals.get("cg"))
    fr = _keys(t.get("friction", {}), {"revolute", "prismatic", *pairs}, "forces.friction")

    def is_prismatic(p):
        return p.endswith(("_slot", "_guide")) or p == "E"

    entries = {}
    for name, v in fr.items():  # every entry checked, also one that every pair's own entry overrides
        f = f"forces.friction.{name}"
        v = _keys(v, {"coefficient", "radius"}, f)
        if "coefficient" not in v:
            raise InputError(f"{f}.coefficient", "is required")
        if "radius" in v and (name == "prismatic" or (name != "revolute" and is_prismatic(name))):
            raise InputError(f"{f}.radius", "applies to a revolute pair's journal (friction moment mu r R); a prismatic "
                             "pair's friction is the force mu N along its guide and has no radius: remove it")
        c = _num(f"{f}.coefficient", v["coefficient"], lo=0.0)
        entries[name] = Friction(c, _num(f"{f}.radius", v.get("radius", 0.0), lo=0.0))

    friction = {}
    for p in pairs:
        prismatic = is_prismatic(p)
        if p in entries:
            friction[p] = entries[p]
        elif prismatic and "prismatic" in entries:
            friction[p] = entries["prismatic"]
        elif not prismatic and "revolute" in entries:
            friction[p] = entries["revolute"]
    guided = GUIDED[kind]
    loads = []
    raw = t.get("loads", [])
    if not isinstance(raw, list):
        raise InputError("forces.loads", "must be a list of tables ([[forces.loads]])")
    for i, ld in enumerate(raw):
        f = f"forces.loads[{i}]"
        if not isinstance(ld, dict):
            raise InputError(f, "must be a table")
        k = check_option(f"{f}.kind", ld.get("kind"), tuple(_LOAD_KEYS))
        _keys(ld, _LOAD_KEYS[k], f)
        if "body" not in ld:
            raise InputError(f"{f}.body", "is required")
        body = ld["body"]
        if body not in names:
            raise InputError(f"{f}.body", f"{show_value(body)} is not a link of a {kind} linkage; a load acts on a link "
                             f"that slides on a guide: {', '.join(map(repr, guided))}")
        if body not in guided:
            raise InputError(f"{f}.body", f"{body!r} does not slide on a guide; a load acts along a guide, on one of "
                             f"{', '.join(map(repr, guided))}")
        try:
            if k == "gas":
                for key in ("angles", "pressure", "bore"):
                    if key not in ld:
                        raise InputError(f"{f}.{key}", "is required")
                for key in ("angles", "pressure"):
                    if not isinstance(ld[key], list):
                        raise InputError(f"{f}.{key}", f"must be a list of numbers, got {show_value(ld[key])}")
                    for j, x in enumerate(ld[key]):  # each element: no booleans, strings or arrays
                        _num(f"{f}.{key}[{j}]", x)
                loads.append(GasPressure(body, tuple(ld["angles"]), tuple(ld["pressure"]), _num(f"{f}.bore", ld["bore"]),
                                         start=_num(f"{f}.start", ld.get("start", 0.0)), period=ld.get("period", 360.0)))
            else:
                if "force" not in ld:
                    raise InputError(f"{f}.force", "is required")
                F = _num(f"{f}.force", ld["force"])
                if k == "constant_friction":
                    loads.append(ConstantFriction(body, F))
                else:
                    cz = cutting
                    window = check_option(f"{f}.window", ld.get("window", "cut"), WINDOWS)
                    if window != "cut":
                        for key in ("approach", "overrun"):
                            if key in ld:
                                raise InputError(f"{f}.{key}", f"applies to window = 'cut' only (the part of the working "
                                                 f"stroke in the work); window = {window!r} does not use it: remove it")
                    if window == "always" and "working" in ld:
                        raise InputError(f"{f}.working", "applies to windows 'cut' and 'working'; window = 'always' acts "
                                         "over the whole cycle whichever stroke works: remove it")
                    frac = {key: ld.get(key, 0.0 if cz is None or window != "cut" else getattr(cz, key))
                            for key in ("approach", "overrun")}
                    loads.append(Resistance(body, F, window=window, **frac,
                                            working=ld.get("working", "slow" if cz is None else cz.working)))
        except InputError as e:
            # name the load in the field: forces.loads.angles -> forces.loads[i].angles
            fld = e.field.replace("forces.loads.", f"{f}.") if e.field.startswith("forces.loads.") else e.field
            raise InputError(fld, _message(e)) from None
    samples = t.get("samples", 360)
    if isinstance(samples, bool) or not isinstance(samples, int) or not 12 <= samples <= 100_000:
        # the bound keeps memory near 0.5 GB (about 4 kB a crank angle)
        raise InputError("forces.samples", f"must be an integer from 12 to 100000, got {show_value(samples)}")
    passes = t.get("passes", 2)
    if passes == "iterate":
        passes = None
    elif isinstance(passes, bool) or not isinstance(passes, int) or passes < 1:
        raise InputError("forces.passes", f"must be an integer >= 1 or 'iterate', got {show_value(passes)}")
    delta = t.get("delta")
    if delta is not None:
        delta = _num("forces.delta", delta)
        if not 0 < delta < 1:
            raise InputError("forces.delta", f"the coefficient of speed fluctuation must be in (0, 1), got {show_value(delta)}")
    from cams.machine.flywheel import INTERPOLATIONS

    interp = check_option("forces.interpolation", t.get("interpolation", "linear"), INTERPOLATIONS)
    spec = ForceSpec(links=links, loads=tuple(loads), friction=friction, gravity=_num("forces.gravity", t.get("gravity", G)),
                     length_unit=LENGTH_UNITS[units])
    return spec, ForceOptions(samples=samples, passes=passes, delta=delta, interpolation=interp)


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
    notes: tuple = ()
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
            from cams.dynamics.forces import jump_dict

            cam = {**self.cam.to_dict(), "spring": {"rate": self.spring.rate, "preload": self.spring.preload},
                   **jump_dict(self.jump), "ok": bool(self.cam.ok)}
            if "between_impacts" in cam and self.jump is not None:
                cam["between_impacts"]["jump_rpm"] = self.jump.between_impacts_rpm
            if self.cam_timing is not None:
                cam["angle_reference"] = (f"*_at_deg, cam_angle_deg: {CAM_ANGLE}; *_at_cycle_deg, cycle_deg: {CYCLE_ANGLE} "
                                          f"(every time the cam is there in {self.cam_timing.period[1]} crank turn(s))")

                def cyc(a):
                    return None if a is None else [float(np.degrees(c)) for c in self.cycle_angles(np.radians(a))]

                for key in ("max_contact_at", "max_torque_at", "jump_at"):
                    cam[key + "_cycle_deg"] = cyc(cam.get(key + "_deg"))
                for imp in cam["impacts"]:
                    imp["cycle_deg"] = cyc(imp["cam_angle_deg"])
            else:
                cam["angle_reference"] = f"*_at_deg, cam_angle_deg: {CAM_ANGLE}"
            out["cam"] = cam
        return out

    def plot(self, directory, stem: str, *, title: str = "") -> list:
        """Reactions and balancing moment, hodographs, energy curves, cam forces as PNGs in ``directory``; the paths."""
        from pathlib import Path

        d = Path(directory)
        paths = []
        if self.linkage is not None:
            paths.append(self.linkage.plot(d / f"{stem}_forces.png", title=f"{title}: reactions and balancing moment"))
            paths.append(self.linkage.plot_hodographs(d / f"{stem}_hodographs.png", title=f"{title}: hodographs of the reactions"))
        if self.flywheel is not None:
            paths.append(self.flywheel.plot(d / f"{stem}_flywheel.png", title=f"{title}: energy"))
        if self.cam is not None:
            paths.append(_plot_cam(self.cam, d / f"{stem}_cam_forces.png", title=f"{title}: cam forces",
                                   timing=self.cam_timing))
        return paths


CYCLE_ANGLE = "cycle angle from position 1"
"""How a machine's reports name their crank angles: the crank's rotation from position 1 (:mod:`cams.machine.timing`)."""
CAM_ANGLE = "cam angle from the start of its program"


def _plot_cam(cf, path, *, title: str, timing=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if timing is None:
        deg, o = np.degrees(cf.phi), slice(None)
        xlabel = f"{CAM_ANGLE}, deg"
    else:  # every cam sample at each cycle angle where it occurs over the repeating period
        p, q = timing.period
        c = np.concatenate([timing.mount + (cf.phi + TWO_PI * j) / timing.ratio for j in range(p)])
        deg = np.degrees(np.mod(c, TWO_PI * q))
        o = np.argsort(deg)
        deg = deg[o]
        o = np.tile(np.arange(cf.phi.size), p)[o]
        xlabel = f"{CYCLE_ANGLE}, deg" + (f" (over {q} crank turns)" if q > 1 else "")
    cf = _Picked(cf, o)
    N = np.where(np.isfinite(cf.contact), cf.contact, np.nan)
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(8, 5.5))
    ax1.plot(deg, N, label="contact force N")
    ax1.plot(deg, np.where(np.isfinite(cf.contact), cf.lateral, np.nan), label="lateral N sin(gamma)")
    ax1.plot(deg, cf.spring, "--", label="spring")
    ax1.set_ylabel("force, N (N m rocker)")
    ax1.legend(loc="upper right")
    ax2.plot(deg, np.where(np.isfinite(cf.torque), cf.torque, np.nan), color="C3", label="camshaft torque")
    ax2.set_ylabel("torque, N m")
    ax2.set_xlabel(xlabel)
    for n, imp in enumerate(getattr(cf, "impacts", ())):  # rigid impacts: unbounded force (or contact lost) there
        xs = [np.degrees(imp.phi)] if timing is None else np.degrees(
            np.mod(timing.mount + (imp.phi + TWO_PI * np.arange(timing.period[0])) / timing.ratio, TWO_PI * timing.period[1]))
        for x in xs:
            for ax in (ax1, ax2):
                ax.axvline(x, color="C3", lw=1.0, ls=":",
                           label=("rigid impact (unbounded / contact lost)" if ax is ax1 and n == 0 and x == xs[0] else None))
    if getattr(cf, "impacts", ()):
        ax1.legend(loc="upper right")
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
    ax1.set_title(f"{title} at {cf.rpm:.4g} rpm")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
    return path


class _Picked:
    """The arrays of a :class:`cams.dynamics.forces.CamForces` indexed by ``o`` (for plotting in another order)."""

    def __init__(self, cf, o):
        self._cf, self._o = cf, o

    def __getattr__(self, name):
        v = getattr(self._cf, name)
        return v[self._o] if isinstance(v, np.ndarray) and v.shape == self._cf.phi.shape else v


def machine_forces(spec, centre=None, *, found=None) -> MachineForces:
    """Forces of a machine file's machine (:class:`cams.machine.timing.MachineSpec`).

    Parameters
    ----------
    spec : MachineSpec
        ``spec.extra["forces"]`` (from ``[forces]``) gives the linkage's data;
        ``spec.cam.dynamics`` (from ``[dynamics]``) the follower's.
    centre : array_like or None
        The cam's centre (``SolveResult.centre``); needed for the cam's forces.
    found : cams.machine.timing.MachineResult, optional
        What :func:`cams.machine.timing.design_machine` found for ``spec``: its
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
    forces = spec.extra.get("forces")
    if forces is not None:
        fs, opt = forces
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
                fw = lk.flywheel(delta=opt.delta, interpolation=opt.interpolation, cycle_deg=360 * turns)
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
