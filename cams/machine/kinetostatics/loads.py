"""The forces' inputs: mass properties, loads and friction of a machine's linkage (:class:`ForceSpec`).

Units: masses kg, moments of inertia kg m^2, forces N, pressures Pa, lengths
in the machine's unit (``ForceSpec.length_unit`` metres each). The machine
file's ``[forces]`` table is read by :func:`cams.machine.machinefile.force_spec_from_dict`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from laws.errors import InputError, check_number, check_option, show_value
from laws.units import TWO_PI

__all__ = ["LinkMass", "Friction", "GasPressure", "Resistance", "ConstantFriction", "Load", "ForceSpec", "ForceOptions",
           "cycle_turns", "check_table", "WINDOWS", "G"]


G = 9.80665
"""Standard gravity, m/s^2."""

WINDOWS = ("cut", "working", "always")
"""Where in the cycle a :class:`Resistance` acts."""


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
        check_number("forces.links.mass", self.mass, lo=0.0)
        check_number("forces.links.inertia", self.inertia, lo=0.0)
        check_number("forces.links.cg", self.cg, allow_none=True)


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
        check_number("forces.friction.coefficient", self.coefficient, lo=0.0)
        check_number("forces.friction.radius", self.radius, lo=0.0)


def check_table(field_: str, angles, values, period: float) -> tuple[np.ndarray, np.ndarray]:
    """A periodic table over the crank angle, checked: ``angles`` (radians) from 0 to ``period`` inclusive.

    The angles must increase strictly and the values close the cycle (equal
    at 0 and ``period``). Messages give the angles in degrees (the file's unit).
    Returns the angles and the values as float arrays.
    """
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
            f"the table covers {np.degrees(a[0]):g}..{np.degrees(a[-1]):g} deg; it must cover the whole cycle, "
            f"from 0 to {np.degrees(period):g} deg",
        )
    if abs(v[0] - v[-1]) > 1e-9 * max(1.0, float(np.max(np.abs(v)))):
        raise InputError(field_, f"the values at 0 and {np.degrees(period):g} deg differ ({v[0]:g} and {v[-1]:g}); "
                         "the cycle must close")
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
        Crank rotation (radians, in the crank's sense) from the frame angle
        ``start``, from 0 to ``period`` inclusive. The table's angle 0 is the
        first time the crank passes ``start`` at or after the first crank
        angle analysed (a machine's position 1); with ``period`` 2 pi that is
        every time it passes ``start``. (A machine file gives degrees.)
    pressure : sequence of float
        Gauge pressure at those angles, Pa (negative: below the outside).
    bore : float
        Piston diameter d, machine length unit.
    start : float
        Frame crank angle (radians) where the table's angle 0 is.
    period : float
        2 pi (one turn per cycle) or 4 pi (a four-stroke cycle: the model's
        default crank angles then cover two turns, and so does the flywheel's
        cycle), radians.
    """

    body: str
    angles: tuple
    pressure: tuple
    bore: float
    start: float = 0.0
    period: float = TWO_PI

    def __post_init__(self):
        check_number("forces.loads.bore", self.bore, lo=0.0, strict=True)
        check_number("forces.loads.start", self.start)
        p = self.period
        ok = not isinstance(p, bool) and isinstance(p, (int, float, np.integer, np.floating)) and np.isfinite(p)
        turns = [n for n in (1, 2) if ok and abs(float(p) - n * TWO_PI) <= 1e-9]
        if not turns:
            raise InputError("forces.loads.period",
                             f"must be 2 pi or 4 pi radians (one or two crank turns), got {show_value(p)}")
        object.__setattr__(self, "period", turns[0] * TWO_PI)
        check_table("forces.loads.angles", self.angles, self.pressure, self.period)

    @property
    def turns(self) -> int:
        """Crank turns in one cycle of the table: 1 or 2."""
        return 1 if self.period < 1.5 * TWO_PI else 2


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

        check_number("forces.loads.force", self.force, lo=0.0)
        check_option("forces.loads.window", self.window, WINDOWS)
        for name in ("approach", "overrun"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)) or not np.isfinite(v) \
                    or not 0 <= v < 1:
                raise InputError(f"forces.loads.{name}",
                                 f"must be a fraction of the stroke in [0, 1), got {show_value(v)}")
            if self.window != "cut" and v != 0:
                raise InputError(f"forces.loads.{name}",
                                 f"applies to window = 'cut' only (the part of the working stroke "
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
        check_number("forces.loads.force", self.force, lo=0.0)


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
        check_number("forces.gravity", self.gravity)
        check_number("forces.length_unit", self.length_unit, lo=0.0, strict=True)
        for k, v in self.links.items():
            if not isinstance(v, LinkMass):
                raise InputError(f"forces.links.{k}", f"must be a LinkMass, got {type(v).__name__}")
        for k, v in self.friction.items():
            if not isinstance(v, Friction):
                raise InputError(f"forces.friction.{k}", f"must be a Friction, got {type(v).__name__}")
        for i, ld in enumerate(self.loads):
            if not isinstance(ld, (GasPressure, Resistance, ConstantFriction)):
                raise InputError(f"forces.loads[{i}]", f"must be a load, got {type(ld).__name__}")



def cycle_turns(spec: ForceSpec) -> int:
    """Crank turns in one cycle of the loads: 2 with a gas table of two turns (period 4 pi), else 1."""
    return 2 if any(isinstance(ld, GasPressure) and ld.turns == 2 for ld in spec.loads) else 1


@dataclass(frozen=True)
class ForceOptions:
    """How a machine file asks for its forces: sampling, friction passes and the flywheel.

    Attributes
    ----------
    samples : int
        Crank angles per turn.
    passes : int or None
        Friction passes (:func:`cams.machine.kinetostatics.solve.solve_model`); None iterates.
    delta : float or None
        Coefficient of speed fluctuation for the flywheel; None: no flywheel.
    interpolation : str
        For :func:`cams.machine.flywheel.flywheel`.
    """

    samples: int = 360
    passes: int | None = 2
    delta: float | None = None
    interpolation: str = "linear"
