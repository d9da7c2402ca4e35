"""The rigid-body model of a linkage for its forces: bodies, pairs and known loads at the crank angles (SI).

Each machine of :mod:`cams.machine.linkage.machines` declares its own
topology (its moving links, its pairs, :meth:`link_states`); this module turns
it into :class:`Body`, :class:`Joint` and :class:`AppliedLoad` in SI units.
Pairs: a revolute's reaction is the force ``R`` (complex ``Rx + i Ry``) on the
pair's first link from its second at the pair's centre; a prismatic pair's is
the normal force ``N`` along ``n = i u`` (``u``: the guide's direction, fixed
in the second link) at a reference point of the guide and a couple ``M``.
Ground is link 0 (index -1 here).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from cams.machine.kinetostatics.loads import (
    ConstantFriction,
    ForceSpec,
    Friction,
    GasPressure,
    LinkMass,
    Resistance,
    check_table,
    cycle_turns,
)
from cams.machine.linkage.common import LinkageBase
from cams.machine.linkage.machines import MACHINES
from cams.machine.linkage.primitives import Angle, Point
from laws.errors import InputError, check_number, show_value
from laws.units import TWO_PI, rpm_to_omega

__all__ = ["Body", "Joint", "AppliedLoad", "Model", "build_model", "LINKS", "JOINTS", "GUIDED", "PINNED", "message_of",
           "pinned_cg_message"]


LINKS = {kind: cls.links for kind, cls in MACHINES.items()}
"""Moving links of each machine kind (seed 003: 1..5; seed 002: 1..3; seed 000: 1..5; seed 004: 1..5), as the
machines declare them."""

JOINTS = {kind: tuple(p.name for p in cls.pairs) for kind, cls in MACHINES.items()}
"""Pairs of each machine kind, as the machines declare them (:attr:`Pair.kind`: revolute or prismatic)."""

GUIDED = {kind: cls.guided() for kind, cls in MACHINES.items()}
"""Links of each machine kind that slide on a guide (the first link of a prismatic pair): the bodies a load can
act on."""

PINNED = tuple(dict.fromkeys(name for g in GUIDED.values() for name in g))
"""Links whose centre of mass is their pin: they slide (and a block turns with its guide), so ``cg`` does not apply."""


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
    of its ``start`` at or after it), radians. ``omega``: the crank's speed,
    rad/s, signed (counter-clockwise positive); ``sense``: the crank's sense
    of rotation (+1 counter-clockwise, -1 clockwise); ``linkage``: the machine
    the model was built from; ``output``: its working member's link.
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
    linkage: LinkageBase | None = None
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


def _mass(spec: ForceSpec, name: str) -> LinkMass:
    return spec.links.get(name, LinkMass())


def _cg(spec: ForceSpec, name: str, default: float) -> float:
    c = _mass(spec, name).cg
    return default if c is None else c


def message_of(e: InputError) -> str:
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
    raise InputError("forces.loads.body",
                     f"{name!r} does not slide on a guide; loads along a guide need a slider or piston")


def _load_window(model: Model, ld: Resistance) -> np.ndarray:
    if ld.window == "always":
        return np.ones_like(model.phi, dtype=bool)
    from cams.machine.timing import CuttingZone, windows

    m = model.linkage
    if m is None:
        raise InputError("forces.loads.window", "a load's window needs the linkage the model was built from")
    if ld.window == "cut":
        zone = CuttingZone(approach=ld.approach, overrun=ld.overrun, working=ld.working)
    else:
        zone = CuttingZone(working=ld.working)
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
            raise InputError(f"forces.loads[{i}].body", message_of(e)) from None
        b = model.bodies[k]
        if isinstance(ld, GasPressure):
            a, p = check_table(f"forces.loads[{i}].angles", ld.angles, ld.pressure, ld.period)
            # the table's angle 0: the first time the crank passes `start` at or after the model's origin
            # (a property of the crank position, not of the angles asked for)
            first = np.mod(model.sense * (ld.start - model.origin), TWO_PI)
            rot = model.sense * (model.phi - model.origin) - first
            pp = np.interp(np.mod(rot, ld.period), a, p)
            area = np.pi * (ld.bore * u) ** 2 / 4
            toward = -np.sign(np.real(np.conj(axis) * b.cg.pos))  # along the axis toward the crank centre
            out.append(AppliedLoad(f"gas on {ld.body}", k, pp * area * toward * axis, b.cg.pos,
                                   np.zeros_like(model.phi)))
        else:
            v = np.real(np.conj(axis) * b.cg.vel)
            on = np.ones_like(model.phi, dtype=bool) if isinstance(ld, ConstantFriction) else _load_window(model, ld)
            F = np.where(on, -np.sign(v) * ld.force, 0.0) * axis
            what = "resistance" if isinstance(ld, Resistance) else "constant friction"
            out.append(AppliedLoad(f"{what} on {ld.body}", k, F, b.cg.pos, np.zeros_like(model.phi)))
    return out



def pinned_cg_message(name: str, kind: str) -> str:
    """Why a ``cg`` is refused for the sliding link ``name`` of a machine of kind ``kind`` (the message, no field)."""
    turning = ", ".join(repr(n) for n in LINKS.get(kind, ()) if n not in GUIDED.get(kind, ()))
    return (f"does not apply to the {name}: a sliding body's centre of mass is taken at its pin and moves with it; "
            f"cg applies to the links that turn about a joint ({turning})")


def build_model(linkage, spec: ForceSpec, *, phi=None, samples: int = 360, rpm: float | None = None,
                origin: float = 0.0) -> Model:
    """The rigid-body model of a linkage of :mod:`cams.machine.linkage.machines` at crank angles ``phi``.

    Parameters
    ----------
    linkage : SlottingMachine, CrankSlider, OpposedTwin or SlottedLeverPump
        Any machine that declares its topology (``links``, ``pairs``, ``link_states``).
    spec : ForceSpec
    phi : array_like, optional
        Frame crank angles, radians; default ``samples`` angles a turn over one
        cycle of the loads (two turns with a gas table of period 720).
    samples : int
        Crank angles per turn (ignored with ``phi``).
    rpm : float, optional
        Crank speed, rev/min; default the linkage's.
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
    n = linkage.rpm if rpm is None else rpm
    if n is None:
        raise InputError("linkage.rpm", "the forces need the crank's speed; give linkage.rpm")
    n = check_number("linkage.rpm", n, lo=0.0, strict=True)
    speed = linkage.crank_sense * rpm_to_omega(n)  # signed crank speed, rad/s
    turns = cycle_turns(spec)
    if phi is None:
        if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 4:
            raise InputError("forces.samples", f"must be an integer >= 4, got {show_value(samples)}")
        phi = np.linspace(0.0, TWO_PI * turns, int(samples) * turns, endpoint=False)
    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    kind = linkage.kind
    names = linkage.links
    pairs = tuple(p.name for p in linkage.pairs)
    for k, lm in spec.links.items():
        if k not in names:
            raise InputError(f"forces.links.{k}",
                             f"is not a link of a {kind} linkage, must be one of {', '.join(map(repr, names))}")
        if k in linkage.guided() and lm.cg is not None:
            raise InputError(f"forces.links.{k}.cg", pinned_cg_message(k, kind))
    for k in spec.friction:
        if k not in pairs:
            raise InputError(f"forces.friction.{k}",
                             f"is not a pair of a {kind} linkage, must be one of {', '.join(map(repr, pairs))}")
    states = linkage.link_states(phi, speed, lambda name, default: _cg(spec, name, default))
    u = spec.length_unit
    bodies = tuple(
        Body(nm, _mass(spec, nm).mass, _mass(spec, nm).inertia, _scale(states.cg[nm], u), states.angle[nm])
        for nm in names
    )
    idx = {nm: i for i, nm in enumerate(names)}
    js = []
    for p in linkage.pairs:
        fr = spec.friction.get(p.name)
        if fr is not None and p.kind == "revolute":
            fr = Friction(fr.coefficient, fr.radius * u)
        axis = states.axis.get(p.name)
        js.append(Joint(p.name, p.kind, idx[p.first], -1 if p.second is None else idx[p.second],
                        np.asarray(states.point[p.name]) * u,
                        None if axis is None else np.asarray(axis, dtype=complex), fr))
    model = Model(kind, phi, float(speed), bodies, tuple(js), (), 0, float(spec.gravity), linkage._output,
                  linkage.crank_sense, linkage, TWO_PI * turns, float(origin))
    loads = tuple(_external_loads(model, spec))
    return replace(model, loads=loads)
