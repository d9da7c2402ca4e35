"""The follower's dynamics, typed: its spring, masses, loads and friction (a design file's ``[dynamics]``).

Plain data, checked once here with the message the file's key gets; the forces they cause are
computed by :mod:`cams.dynamics.forces`, and :func:`cams.io.designfile.dynamics_from_dict` maps a
file's table onto :class:`DynamicsSpec`. Units are SI (N, kg, N/m; N m, kg m^2, N m/rad for a
rocker) except ``journal_radius``, in the design's length unit (mm).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from laws.errors import InputError
from laws.errors import check_number as _num

__all__ = ["DynamicsSpec", "FollowerDynamics", "Spring", "check_dynamics_follower", "journal_error",
           "face_friction_error"]


@dataclass(frozen=True)
class Spring:
    """A closing spring acting on the follower's coordinate.

    Parameters
    ----------
    rate : float
        k >= 0: N/m (translating) or N m/rad (rocker, torsional).
    preload : float
        F0 >= 0: spring force at the near dwell, N or N m.

    Examples
    --------
    >>> Spring(2000.0, 15.0).force(np.array([0.0, 0.01]))
    array([15., 35.])
    """

    rate: float
    preload: float

    def __post_init__(self) -> None:
        _num("dynamics.spring_rate", self.rate, lo=0.0)
        _num("dynamics.preload", self.preload, lo=0.0)

    def force(self, q: np.ndarray) -> np.ndarray:
        """Spring force F0 + k q at the follower coordinate ``q`` (m or rad)."""
        return self.preload + self.rate * np.asarray(q, dtype=float)


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
    """

    mass: float
    load: float = 0.0
    spring: Spring | None = None
    friction: float = 0.0
    journal_radius: float = 0.0
    length_unit: float = 1e-3
    max_spring_force: float | None = None
    face_friction: float = 0.0

    def __post_init__(self) -> None:
        _num("dynamics.mass", self.mass, lo=0.0, strict=True)
        _num("dynamics.load", self.load)
        _num("dynamics.friction", self.friction, lo=0.0)
        _num("dynamics.journal_radius", self.journal_radius, lo=0.0)
        _num("dynamics.length_unit", self.length_unit, lo=0.0, strict=True)
        _num("dynamics.max_spring_force", self.max_spring_force, lo=0.0, strict=True, allow_none=True)
        _num("dynamics.face_friction", self.face_friction, lo=0.0)
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

    The spring to use is :func:`cams.dynamics.forces.chosen_spring`.
    """

    dynamics: FollowerDynamics
    margin: float = 1.2
    rate: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.dynamics, FollowerDynamics):
            raise InputError("dynamics", f"must be a FollowerDynamics, got {type(self.dynamics).__name__}")
        _num("dynamics.margin", self.margin, lo=1.0)
        _num("dynamics.spring_rate", self.rate, lo=0.0, allow_none=True)


def check_dynamics_follower(spec: DynamicsSpec, rocker: bool, *, flat: bool = False) -> None:
    """Refuse what a follower's kind does not take: a translating follower has no pivot journal, a roller no
    sliding face.

    Raises
    ------
    InputError
        ``dynamics.journal_radius`` other than 0 for a translating follower (``rocker`` False), roller or flat
        face alike; ``dynamics.face_friction`` other than 0 for a roller follower (``flat`` False).
    """
    if not rocker and spec.dynamics.journal_radius != 0:
        raise journal_error()
    if not flat and spec.dynamics.face_friction != 0:
        raise face_friction_error()


def journal_error() -> InputError:
    """The error of a journal radius given for a translating follower (a design file refuses the key itself)."""
    return InputError("dynamics.journal_radius", "applies to a rocker's pivot journal (friction moment mu r N); a "
                      "translating follower's friction is in its guide (dynamics.friction alone): remove it")


def face_friction_error() -> InputError:
    """The error of a face friction given for a roller follower (a design file refuses the key itself)."""
    return InputError("dynamics.face_friction", "applies to a flat-faced follower (sliding friction at the face); a "
                      "roller turns freely on its pin: remove it")
