"""The follower's dynamics, typed: its spring, masses, loads and friction (a design file's ``[dynamics]``).

Plain data, checked once here with the message the file's key gets; the forces they cause are
computed by :mod:`cams.dynamics.forces`, and :func:`cams.io.designfile.dynamics_from_dict` maps a
file's table onto :class:`DynamicsSpec`. Units are SI (N, kg, N/m; N m, kg m^2, N m/rad for a
rocker) except ``journal_radius`` and the bounds on a spring's installed compression, in the design's length
unit (mm), and the bounds on a torsional spring's installed twist, in radians.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from laws.errors import InputError
from laws.errors import check_number as _num

__all__ = ["DynamicsSpec", "FollowerDynamics", "Spring", "check_dynamics_follower", "journal_error",
           "face_friction_error", "installed_error"]


@dataclass(frozen=True)
class Spring:
    """A closing spring acting on the follower's coordinate.

    Parameters
    ----------
    rate : float
        k >= 0: N/m (translating) or N m/rad (rocker, torsional).
    preload : float
        F0 >= 0: spring force at the near dwell, N or N m.
    travel : float or None
        The follower's working travel from the near dwell (its stroke: m, or
        rad for a rocker), over which the spring works; None when not known.
        Gives :attr:`max_force`.
    torsional : bool
        A rocker's torsional spring (``q`` an angle: N m/rad, N m, rad).
    note : str or None
        What the choice of the spring has to say (outside the usual range of
        installed compression, no spring needed).

    ``travel``, ``torsional`` and ``note`` describe the spring's use (set by
    :func:`cams.dynamics.forces.chosen_spring`); they are not part of its
    identity, which is its rate and preload (equality, repr).

    The spring's *installed compression* (a torsional spring's installed
    twist) is ``F0 / k`` (:attr:`installed`): how far it is compressed from
    its free length when the follower sits at the near dwell; at the far
    dwell it is compressed by ``F0 / k + travel`` and exerts :attr:`max_force`.

    Examples
    --------
    >>> Spring(2000.0, 15.0).force(np.array([0.0, 0.01]))
    array([15., 35.])
    >>> s = Spring(2000.0, 15.0, travel=0.03)
    >>> round(s.installed, 6), round(s.max_force, 6)
    (0.0075, 75.0)
    """

    rate: float
    preload: float
    travel: float | None = field(default=None, compare=False, repr=False)
    torsional: bool = field(default=False, compare=False, repr=False)
    note: str | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        _num("dynamics.spring_rate", self.rate, lo=0.0)
        _num("dynamics.preload", self.preload, lo=0.0)
        _num("dynamics.travel", self.travel, lo=0.0, allow_none=True)

    def force(self, q: np.ndarray) -> np.ndarray:
        """Spring force F0 + k q at the follower coordinate ``q`` (m or rad)."""
        return self.preload + self.rate * np.asarray(q, dtype=float)

    @property
    def installed(self) -> float | None:
        """Installed compression ``F0 / k`` (m; a torsional spring's installed twist, rad); None when k = 0."""
        return self.preload / self.rate if self.rate > 0 else None

    @property
    def max_force(self) -> float | None:
        """The largest force ``F0 + k travel`` (N or N m), at the far dwell; None without :attr:`travel`."""
        return None if self.travel is None else self.preload + self.rate * self.travel

    def to_dict(self, length_unit: float = 1e-3) -> dict:
        """JSON-ready: ``rate`` (N/m; N m/rad), ``preload`` (N; N m), ``installed_compression`` (mm) or, for a
        torsional spring, ``installed_twist`` (deg) -- null for a rate of 0 --, ``max_force`` (N; N m) and
        ``note``; ``length_unit``: metres per design length unit (1e-3: mm)."""
        inst = self.installed
        if self.torsional:
            shown = {"installed_twist": None if inst is None else float(np.degrees(inst))}
        else:
            shown = {"installed_compression": None if inst is None else inst / length_unit}
        return {"rate": self.rate, "preload": self.preload, **shown, "max_force": self.max_force, "note": self.note}


@dataclass(frozen=True)
class FollowerDynamics:
    """Masses, loads, spring and friction of a force-closed follower.

    Parameters
    ----------
    mass : float
        Reduced mass of a translating follower (kg) or moment of inertia of a
        rocker about its pivot (kg m^2), > 0.
    load : float, optional
        Constant external load opposing the rise, N (N m for a rocker).
    spring : Spring or None
        The closing spring; ``None`` when it is to be designed
        (:func:`cams.dynamics.forces.spring_for_contact`).
    friction : float, optional
        mu >= 0: in the translating follower's guide, or in the rocker's pivot.
    journal_radius : float, optional
        Radius of the rocker's pivot journal, design length unit (friction
        moment ``mu r_j N``); not used by a translating follower (whose
        friction is in its guide); a design refuses it there
        (:func:`check_dynamics_follower`).
    length_unit : float, optional
        Metres per design length unit (1e-3: mm).
    max_spring_force : float or None
        Largest force (N or N m) the spring may exert (solid or allowable
        stress); a spring that would need more is rejected.
    face_friction : float, optional
        mu_f >= 0 (dimensionless): sliding (Coulomb) friction between a flat
        face and the cam, ``mu_f N`` along the face opposing the sliding
        (:mod:`cams.dynamics.flat_forces`); a roller turns freely and a roller
        design refuses it (:func:`check_dynamics_follower`).
    train_stiffness : float or None
        k_t > 0: the follower train's stiffness between the cam and the mass
        ``mass`` (N/m; a rocker's torsional stiffness about its pivot, N m/rad);
        None: a rigid follower (no vibration, :mod:`cams.dynamics.vibration`).
    damping_ratio : float, optional
        zeta >= 0 (dimensionless) of the train's damper, defined against the
        total stiffness: ``zeta = c / (2 sqrt((k_t + k_s) m))``; the damper
        acts across the train, on the relative velocity of cam and mass.
    """

    mass: float
    load: float = 0.0
    spring: Spring | None = None
    friction: float = 0.0
    journal_radius: float = 0.0
    length_unit: float = 1e-3
    max_spring_force: float | None = None
    face_friction: float = 0.0
    train_stiffness: float | None = None
    damping_ratio: float = 0.0

    def __post_init__(self) -> None:
        _num("dynamics.mass", self.mass, lo=0.0, strict=True)
        _num("dynamics.load", self.load)
        _num("dynamics.friction", self.friction, lo=0.0)
        _num("dynamics.journal_radius", self.journal_radius, lo=0.0)
        _num("dynamics.length_unit", self.length_unit, lo=0.0, strict=True)
        _num("dynamics.max_spring_force", self.max_spring_force, lo=0.0, strict=True, allow_none=True)
        _num("dynamics.face_friction", self.face_friction, lo=0.0)
        _num("dynamics.train_stiffness", self.train_stiffness, lo=0.0, strict=True, allow_none=True)
        _num("dynamics.damping_ratio", self.damping_ratio, lo=0.0)
        if self.damping_ratio and self.train_stiffness is None:
            raise InputError("dynamics.damping_ratio", "is the follower train's damping: give train_stiffness too")
        if self.spring is not None and not isinstance(self.spring, Spring):
            raise InputError("dynamics.spring", f"must be a Spring, got {type(self.spring).__name__}")

    def with_spring(self, spring: Spring) -> FollowerDynamics:
        """A copy with ``spring``."""
        return replace(self, spring=spring)


@dataclass(frozen=True)
class DynamicsSpec:
    """A design's ``[dynamics]``: the follower's dynamics and how to choose its spring.

    Attributes
    ----------
    dynamics : FollowerDynamics
        With its ``spring`` when both rate and preload were given.
    margin : float
        Contact margin for :func:`cams.dynamics.forces.spring_for_contact` (>= 1).
    rate : float or None
        A given spring rate whose preload is to be chosen (with no spring in ``dynamics``).
    min_installed_compression, max_installed_compression : float or None
        Bounds on a chosen translating follower's spring's installed compression
        ``F0 / k``, design length unit (mm), >= 0; None: the default
        (:func:`cams.dynamics.forces.spring_for_contact`).
    min_installed_twist, max_installed_twist : float or None
        The same for a rocker's torsional spring's installed twist, radians.

    The spring to use is :func:`cams.dynamics.forces.chosen_spring`.
    """

    dynamics: FollowerDynamics
    margin: float = 1.2
    rate: float | None = None
    min_installed_compression: float | None = None
    max_installed_compression: float | None = None
    min_installed_twist: float | None = None
    max_installed_twist: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.dynamics, FollowerDynamics):
            raise InputError("dynamics", f"must be a FollowerDynamics, got {type(self.dynamics).__name__}")
        _num("dynamics.margin", self.margin, lo=1.0)
        _num("dynamics.spring_rate", self.rate, lo=0.0, allow_none=True)
        for what, unit, scale in (("compression", "mm", 1.0), ("twist", "deg", 180 / np.pi)):
            lo, hi = (getattr(self, f"{end}_installed_{what}") for end in ("min", "max"))
            _num(f"dynamics.min_installed_{what}", lo, lo=0.0, allow_none=True)
            _num(f"dynamics.max_installed_{what}", hi, lo=0.0, allow_none=True)
            if lo is not None and hi is not None and lo > hi:
                raise InputError(f"dynamics.max_installed_{what}", f"must be >= min_installed_{what} "
                                 f"({lo * scale:g} {unit}), got {hi * scale:g} {unit}")
            if (lo is not None or hi is not None) and self.dynamics.spring is not None:
                raise InputError(f"dynamics.{'min' if lo is not None else 'max'}_installed_{what}",
                                 "bounds a chosen spring's installed " + what + "; spring_rate and preload are both "
                                 "given (a spring to check): remove the bound or the preload")
            if (lo is not None or hi is not None) and self.rate == 0:
                raise InputError(f"dynamics.{'min' if lo is not None else 'max'}_installed_{what}",
                                 "a spring_rate of 0 (a constant-force spring) has no installed " + what +
                                 ": remove the bound or give a positive spring_rate")

    @property
    def installed_bounds(self) -> tuple[float | None, float | None]:
        """The given bounds on the installed compression (mm) or twist (rad), whichever are set; (None, None)."""
        if self.min_installed_twist is not None or self.max_installed_twist is not None:
            return self.min_installed_twist, self.max_installed_twist
        return self.min_installed_compression, self.max_installed_compression


def check_dynamics_follower(spec: DynamicsSpec, rocker: bool, *, flat: bool = False) -> None:
    """Refuse what a follower's kind does not take.

    A translating follower has no pivot journal and a linear spring (installed
    compression, mm); a rocker a torsional spring (installed twist); a roller
    no sliding face.

    Raises
    ------
    InputError
        ``dynamics.journal_radius`` other than 0, or ``min_installed_twist`` /
        ``max_installed_twist``, for a translating follower (``rocker`` False), roller or flat face alike;
        ``min_installed_compression`` / ``max_installed_compression`` for a rocker; ``dynamics.face_friction``
        other than 0 for a roller follower (``flat`` False).
    """
    if not rocker and spec.dynamics.journal_radius != 0:
        raise journal_error()
    if not flat and spec.dynamics.face_friction != 0:
        raise face_friction_error()
    for end in ("min", "max"):
        if not rocker and getattr(spec, f"{end}_installed_twist") is not None:
            raise installed_error(f"{end}_installed_twist", rocker=False)
        if rocker and getattr(spec, f"{end}_installed_compression") is not None:
            raise installed_error(f"{end}_installed_compression", rocker=True)


def installed_error(key: str, *, rocker: bool) -> InputError:
    """The error of a bound on the installed compression given for a rocker, or on the twist for a translating
    follower (a design file refuses the key itself)."""
    if rocker:
        why = ("bounds a translating follower's spring (mm); a rocker's spring is torsional: use "
               f"{key.replace('compression', 'twist')} (deg)")
    else:
        why = ("bounds a rocker's torsional spring (deg); a translating follower's spring is linear: use "
               f"{key.replace('twist', 'compression')} (mm)")
    return InputError(f"dynamics.{key}", why)


def journal_error() -> InputError:
    """The error of a journal radius given for a translating follower (a design file refuses the key itself)."""
    return InputError("dynamics.journal_radius", "applies to a rocker's pivot journal (friction moment mu r N); a "
                      "translating follower's friction is in its guide (dynamics.friction alone): remove it")


def face_friction_error() -> InputError:
    """The error of a face friction given for a roller follower (a design file refuses the key itself)."""
    return InputError("dynamics.face_friction", "applies to a flat-faced follower (sliding friction at the face); a "
                      "roller turns freely on its pin: remove it")
